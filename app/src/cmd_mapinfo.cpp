// `ceilplan mapinfo`: what a map holds, and how much of it has a ceiling close overhead.

#include "command_registry.hpp"
#include "output.hpp"

#include "ceilplan/environment/column_index.hpp"
#include "ceilplan/environment/map_statistics.hpp"
#include "ceilplan/environment/occupancy_map.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <memory>
#include <string>

namespace ceilplan::app {
namespace {

struct MapinfoOptions {
  std::string map;
  std::string json;
};

nlohmann::json point(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

void runMapinfo(const MapinfoOptions& options) {
  using namespace environment;
  const OccupancyMap map = OccupancyMap::load(options.map);
  const VoxelGrid grid = VoxelGrid::fromTree(map.tree());
  const ColumnIndex columns(grid);
  const MapStatistics stats = computeStatistics(map, grid, columns);
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
  const nlohmann::json report = {
      {"map", options.map},
      {"resolution_m", stats.resolution_m},
      {"extent_m", {{"min", point(lo)}, {"max", point(hi)}}},
      {"leaves", {{"occupied", stats.occupied_leaves}, {"free", stats.free_leaves}}},
      {"volume_m3", {{"occupied", stats.occupied_volume_m3}, {"free", stats.free_volume_m3}, {"unknown", stats.unknown_volume_m3}}},
      {"ceiling_within_m", stats.ceiling_within_m},
      {"ceiling_area_share", stats.ceiling_area_share}};
  writeTextAtomically(options.json, [&](std::ostream& out) { out << report.dump(2) << '\n'; });
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
