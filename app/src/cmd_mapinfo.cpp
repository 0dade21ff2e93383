// `ceilplan mapinfo`: what a map holds, and how much of it has a ceiling close overhead.

#include "command_registry.hpp"
#include "output.hpp"

#include "ceilplan/environment/map_statistics.hpp"
#include "ceilplan/environment/occupancy_map.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/report_json.hpp"

#include <cstdio>
#include <memory>
#include <string>

namespace ceilplan::app {
namespace {

struct MapinfoOptions {
  std::string map;
  std::string json;
};

void runMapinfo(const MapinfoOptions& options) {
  using namespace environment;
  const OccupancyMap map = OccupancyMap::load(options.map);
  const MapStatistics stats = computeStatistics(map);
  const Eigen::Vector3d lo = stats.extent_m.min(), hi = stats.extent_m.max();
  std::printf("map: %s\n", options.map.c_str());
  std::printf("resolution_m: %g\n", stats.resolution_m);
  std::printf("extent_m: [%.3f, %.3f, %.3f] to [%.3f, %.3f, %.3f] (%.1f x %.1f x %.1f m)\n", lo.x(), lo.y(), lo.z(),
              hi.x(), hi.y(), hi.z(), hi.x() - lo.x(), hi.y() - lo.y(), hi.z() - lo.z());
  std::printf("leaves: %zu occupied, %zu free\n", stats.occupied_leaves, stats.free_leaves);
  std::printf("volume_m3: %.1f occupied, %.1f free, %.1f unknown (within the extent)\n", stats.occupied_volume_m3,
              stats.free_volume_m3, stats.unknown_volume_m3);
  std::printf("ceiling_area_share: %.3f of the floor area has a ceiling within %g m\n", stats.ceiling_area_share,
              stats.ceiling_within_m);
  if (options.json.empty()) return;
  nlohmann::json report = io::mapStatisticsJson(stats);
  report["map"] = options.map;
  io::writeJsonFile(options.json, report);
}

const CommandRegistration registration(21, [](CLI::App& parent) {
  auto options = std::make_shared<MapinfoOptions>();
  CLI::App* command = parent.add_subcommand("mapinfo", "Summarise an OctoMap (.bt or .ot)");
  command->add_option("--map", options->map, "OctoMap file (.bt or .ot)")->required();
  command->add_option("--json", options->json, "Also write the summary as JSON to this file");
  command->callback([options] { runMapinfo(*options); });
});

}  // namespace
}  // namespace ceilplan::app
