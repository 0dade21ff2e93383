// `ceilplan probe`: what the planner and the energy model see at one body position.

#include "command_registry.hpp"
#include "map_options.hpp"
#include "output.hpp"
#include "planning_flags.hpp"

#include "ceilplan/environment/map_index.hpp"
#include "ceilplan/environment/position_probe.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/report_json.hpp"
#include "ceilplan/io/report_text.hpp"
#include "ceilplan/io/unknown_space_report.hpp"
#include "ceilplan/io/vehicle_file.hpp"

#include <memory>
#include <string>

namespace ceilplan::app {
namespace {

struct ProbeOptions {
  std::string map;
  std::string at;
  std::string vehicle;
  std::string json;
  UnknownSpaceFlags unknown;
};

void runProbe(const ProbeOptions& options) {
  using namespace environment;
  io::OutputSet out({{"--json", options.json}},
                    commandInputs({{"--map", options.map}, {"--vehicle", options.vehicle}}));
  const Eigen::Vector3d body = parsePoint(options.at, "--at");
  const VehicleGeometry vehicle = io::readVehicleOrDefault(options.vehicle).geometry;
  MapIndexOptions index_options;
  index_options.unknown = options.unknown.value();
  const OccupancyMap map = OccupancyMap::load(options.map);
  const io::Provenance provenance = commandProvenance().input("map", options.map).input("vehicle", options.vehicle);
  const ProgressCallback progress = terminalProgress();
  const std::string stage = "indexing " + options.map;
  const Environment environment(MapIndex::build(map, index_options, [&](double f) { progress(stage, f); }), vehicle);
  progress(stage, 1.0);

  const PositionProbe probe = probePosition(environment, body);
  print(io::positionProbeText(body, probe, vehicle, io::unknownSpaceLine(environment)));
  if (!options.json.empty())
    io::writeJsonFile(
        out.path("--json"),
        io::withProvenance(io::probeReportJson(probe, environment, options.map, options.vehicle), provenance));
  out.commit();
}

const CommandRegistration registration(22, [](CLI::App& parent) {
  auto options = std::make_shared<ProbeOptions>();
  CLI::App* command =
      parent.add_subcommand("probe", "Ceiling and ground gaps, clearance and validity at one body position");
  command->add_option("--map", options->map, "OctoMap file (.bt or .ot)")->required();
  command->add_option("--at", options->at, "Body centre x,y,z in metres (map frame)")->required();
  command->add_option("--vehicle", options->vehicle, "Vehicle file (default: maps/vehicles/quad.yaml)");
  command->add_option("--json", options->json, "Also write the answer as JSON to this file");
  options->unknown.addTo(*command);
  command->callback([options] { runProbe(*options); });
});

}  // namespace
}  // namespace ceilplan::app
