// `ceilplan mapinfo`: what a map holds, and how much of it has a ceiling close overhead.

#include "command_registry.hpp"
#include "map_options.hpp"
#include "output.hpp"

#include "ceilplan/environment/environment.hpp"
#include "ceilplan/environment/map_index.hpp"
#include "ceilplan/environment/map_statistics.hpp"
#include "ceilplan/environment/occupancy_map.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/map_slice_file.hpp"
#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/report_json.hpp"
#include "ceilplan/io/report_text.hpp"
#include "ceilplan/io/vehicle_file.hpp"

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

void runMapinfo(const MapinfoOptions& options) {
  using namespace environment;
  MapIndexOptions index_options;
  index_options.unknown = options.unknown.value();
  // Checked and staged before the map is read and indexed; both outputs appear together.
  io::OutputSet out({{"--json", options.json}, {"--slice-csv", options.slice_csv}},
                    commandInputs({{"--map", options.map}, {"--vehicle", options.vehicle}}));
  const OccupancyMap map = OccupancyMap::load(options.map);
  if (!options.vehicle.empty() && options.slice_csv.empty())
    throw ceilplan::InputError("--vehicle applies only to --slice-csv; add --slice-csv FILE or drop it");
  const ProgressCallback progress = terminalProgress();
  const std::string stage = "indexing " + options.map;
  const auto index = MapIndex::build(map, index_options, [&](double f) { progress(stage, f); });
  progress(stage, 1.0);
  const MapStatistics stats = computeStatistics(map, *index);
  // Once the map (and below, the vehicle) was read: their readers name what is wrong with them.
  io::Provenance provenance = commandProvenance().input("map", options.map);
  if (!options.slice_csv.empty()) {
    std::unique_ptr<Environment> environment;
    if (!options.vehicle.empty())
      environment = std::make_unique<Environment>(index, io::readVehicle(options.vehicle).geometry);
    provenance.input("vehicle", options.vehicle);
    io::writeMapSliceCsv(out.path("--slice-csv"), *index, options.slice_z_m, environment.get(), "--slice-z",
                         provenance);
  }
  print(io::mapStatisticsText(options.map, stats));
  if (!options.json.empty())
    io::writeJsonFile(out.path("--json"), io::withProvenance(io::mapStatisticsJson(options.map, stats), provenance));
  out.commit();
}

const CommandRegistration registration(21, [](CLI::App& parent) {
  auto options = std::make_shared<MapinfoOptions>();
  CLI::App* command = parent.add_subcommand("mapinfo", "Summarise an OctoMap (.bt or .ot)");
  command->add_option("--map", options->map, "OctoMap file (.bt or .ot)")->required();
  command->add_option("--json", options->json, "Also write the summary as JSON to this file");
  options->unknown.addTo(*command);
  CLI::Option* slice_z =
      command->add_option("--slice-z", options->slice_z_m, "Height of the slice --slice-csv writes, in metres");
  command
      ->add_option("--slice-csv", options->slice_csv,
                   "Write one row per map column at --slice-z: x_m, y_m, state (occupied, free, unknown, "
                   "assumed_free), under_ceiling, and with --vehicle valid and assumes_free")
      ->needs(slice_z);
  command->add_option("--vehicle", options->vehicle, "Vehicle file for --slice-csv's valid and assumes_free columns");
  command->callback([options] { runMapinfo(*options); });
});

}  // namespace
}  // namespace ceilplan::app
