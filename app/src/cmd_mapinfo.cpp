// `ceilplan mapinfo`: what a map holds, and how much of it has a ceiling close overhead.

#include "command_registry.hpp"
#include "map_options.hpp"

#include "ceilplan/io/unknown_space_report.hpp"
#include "output.hpp"

#include "ceilplan/environment/environment.hpp"
#include "ceilplan/environment/map_index.hpp"
#include "ceilplan/environment/map_statistics.hpp"
#include "ceilplan/environment/occupancy_map.hpp"
#include "ceilplan/io/vehicle_file.hpp"

#include "ceilplan/core/format.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <memory>
#include <string>

namespace ceilplan::app {
namespace {

struct MapinfoOptions {
  std::string map;
  std::string json;
  UnknownSpaceFlags unknown;
  double slice_z_m = 0.0;
  std::string slice_csv;
  std::string vehicle;
};

const char* stateName(environment::CellState state, bool assumed_free) {
  if (assumed_free) return "assumed_free";
  switch (state) {
    case environment::CellState::Occupied: return "occupied";
    case environment::CellState::Free: return "free";
    case environment::CellState::Unknown: return "unknown";
  }
  return "unknown";
}

// One row per column of the map at height z: what the map holds there, what the policy
// assumed, whether the column lies under a ceiling, and with a vehicle whether its body
// centre may be there and whether that relies on the policy.
void writeSlice(const MapinfoOptions& options, const std::shared_ptr<const environment::MapIndex>& index) {
  using namespace environment;
  const GridFrame& frame = index->grid().frame();
  const int k = frame.indexOf(2, options.slice_z_m);
  if (k < 0 || k >= frame.size()[2])
    throw ceilplan::InputError("--slice-z " + formatNumber(options.slice_z_m) + " lies outside the map, whose heights span " +
                               formatNumber(frame.faceOf(2, 0)) + " to " + formatNumber(frame.faceOf(2, frame.size()[2])) + " m");
  std::unique_ptr<Environment> environment;
  if (!options.vehicle.empty()) environment = std::make_unique<Environment>(index, io::readVehicle(options.vehicle).geometry);
  const std::vector<std::uint8_t> ceiling = ceilingColumns(*index);
  writeTextAtomically(options.slice_csv, [&](std::ostream& out) {
    out << "x_m,y_m,state,under_ceiling" << (environment ? ",valid,assumes_free" : "") << '\n';
    for (int j = 0; j < frame.size()[1]; ++j)
      for (int i = 0; i < frame.size()[0]; ++i) {
        const Eigen::Vector3d centre(frame.centreOf(0, i), frame.centreOf(1, j), options.slice_z_m);
        out << formatNumber(centre.x()) << ',' << formatNumber(centre.y()) << ','
            << stateName(index->grid().at(i, j, k), index->isAssumedFree(centre)) << ','
            << int(ceiling[static_cast<std::size_t>(j) * frame.size()[0] + i] == 2);
        if (environment) out << ',' << int(environment->isStateValid(centre)) << ',' << int(environment->assumesFree(centre));
        out << '\n';
      }
  });
}

nlohmann::json point(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

void runMapinfo(const MapinfoOptions& options) {
  using namespace environment;
  MapIndexOptions index_options;
  index_options.unknown = options.unknown.value();
  if (!options.json.empty()) checkWritableFile(options.json);  // before the map is read and indexed
  if (!options.slice_csv.empty()) checkWritableFile(options.slice_csv);
  const OccupancyMap map = OccupancyMap::load(options.map);
  if (!options.vehicle.empty() && options.slice_csv.empty())
    throw ceilplan::InputError("--vehicle applies only to --slice-csv; add --slice-csv FILE or drop it");
  Progress progress("indexing " + options.map);
  const auto index = MapIndex::build(map, index_options, [&](double f) { progress.update(f); });
  progress.finish();
  const MapStatistics stats = computeStatistics(map, *index);
  if (!options.slice_csv.empty()) writeSlice(options, index);
  const Eigen::Vector3d lo = stats.extent_m.min(), hi = stats.extent_m.max();
  std::printf("map: %s\n", options.map.c_str());
  std::printf("resolution_m: %g\n", stats.resolution_m);
  std::printf("extent_m: [%.3f, %.3f, %.3f] to [%.3f, %.3f, %.3f] (%.1f x %.1f x %.1f m)\n", lo.x(), lo.y(), lo.z(),
              hi.x(), hi.y(), hi.z(), hi.x() - lo.x(), hi.y() - lo.y(), hi.z() - lo.z());
  std::printf("leaves: %zu occupied, %zu free\n", stats.occupied_leaves, stats.free_leaves);
  std::printf("volume_m3: %.1f occupied, %.1f free, %.1f unknown (within the extent)\n", stats.occupied_volume_m3,
              stats.free_volume_m3, stats.unknown_volume_m3);
  std::printf("unknown: %s\n", io::unknownSpaceLine(stats.unknown, stats.unknown_summary).c_str());
  std::printf("ceiling_area_share: %.3f of the floor area lies under a ceiling (an occupied surface with %s m or more "
              "of free space below, in patches of %s m2 or more)\n",
              stats.ceiling_area_share, formatNumber(stats.ceiling.min_headroom_m).c_str(),
              formatNumber(stats.ceiling.min_area_m2).c_str());
  if (options.json.empty()) return;
  const nlohmann::json report = {
      {"map", options.map},
      {"resolution_m", stats.resolution_m},
      {"extent_m", {{"min", point(lo)}, {"max", point(hi)}}},
      {"leaves", {{"occupied", stats.occupied_leaves}, {"free", stats.free_leaves}}},
      {"volume_m3", {{"occupied", stats.occupied_volume_m3}, {"free", stats.free_volume_m3}, {"unknown", stats.unknown_volume_m3}}},
      {"unknown", io::unknownSpaceJson(stats.unknown, stats.unknown_summary)},
      {"ceiling", {{"min_headroom_m", stats.ceiling.min_headroom_m}, {"min_area_m2", stats.ceiling.min_area_m2}}},
      {"ceiling_area_share", stats.ceiling_area_share}};
  writeTextAtomically(options.json, [&](std::ostream& out) { out << report.dump(2) << '\n'; });
}

const CommandRegistration registration(21, [](CLI::App& parent) {
  auto options = std::make_shared<MapinfoOptions>();
  CLI::App* command = parent.add_subcommand("mapinfo", "Summarise an OctoMap (.bt or .ot)");
  command->add_option("--map", options->map, "OctoMap file (.bt or .ot)")->required();
  command->add_option("--json", options->json, "Also write the summary as JSON to this file");
  options->unknown.addTo(*command);
  CLI::Option* slice_z =
      command->add_option("--slice-z", options->slice_z_m, "Height of the slice --slice-csv writes, in metres");
  command->add_option("--slice-csv", options->slice_csv,
                      "Write one row per map column at --slice-z: x_m, y_m, state (occupied, free, unknown, "
                      "assumed_free), under_ceiling, and with --vehicle valid and assumes_free")
      ->needs(slice_z);
  command->add_option("--vehicle", options->vehicle, "Vehicle file for --slice-csv's valid and assumes_free columns");
  command->callback([options] { runMapinfo(*options); });
});

}  // namespace
}  // namespace ceilplan::app
