// `ceilplan probe`: what the planner and the energy model see at one body position.

#include "command_registry.hpp"
#include "map_options.hpp"
#include "output.hpp"
#include "planning_flags.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/environment/map_index.hpp"
#include "ceilplan/environment/position_probe.hpp"
#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/report_json.hpp"
#include "ceilplan/io/unknown_space_report.hpp"
#include "ceilplan/io/vehicle_file.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
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

std::string text(double value) {
  if (!std::isfinite(value)) return "none";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4f", value);
  return buffer;
}

void runProbe(const ProbeOptions& options) {
  using namespace environment;
  if (!options.json.empty()) io::checkWritableFile(options.json);
  const Eigen::Vector3d body = parsePoint(options.at, "--at");
  const VehicleGeometry vehicle =
      (options.vehicle.empty() ? mission::Vehicle::defaultQuad() : io::readVehicle(options.vehicle)).geometry;
  MapIndexOptions index_options;
  index_options.unknown = options.unknown.value();
  const OccupancyMap map = OccupancyMap::load(options.map);
  Progress progress("indexing " + options.map);
  const Environment environment(MapIndex::build(map, index_options, [&](double f) { progress.update(f); }), vehicle);
  progress.finish();
  const UnknownSpaceSummary& unknown = environment.index()->unknownSummary();

  const PositionProbe probe = probePosition(environment, body);
  const SurfaceGaps &ceiling = probe.ceiling, &ground = probe.ground;

  std::printf("at: %.3f, %.3f, %.3f (vehicle %s)\n", body.x(), body.y(), body.z(), vehicle.name.c_str());
  std::printf("ceiling_gap_m: %s\nceiling_coverage: %.4f\nceiling_mean_gap_m: %s\n", text(ceiling.nearest_gap_m).c_str(),
              ceiling.coverage, text(ceiling.mean_gap_m).c_str());
  std::printf("ground_gap_m: %s\nground_coverage: %.4f\nground_mean_gap_m: %s\n", text(ground.nearest_gap_m).c_str(),
              ground.coverage, text(ground.mean_gap_m).c_str());
  std::printf("clearance_m: %s\nvalid: %s\n", text(probe.clearance_m).c_str(), probe.violation ? "false" : "true");
  if (probe.violation) std::printf("violation: %s\n", probe.violation->describe().c_str());
  std::printf("unknown: %s\n", io::unknownSpaceLine(index_options.unknown, unknown).c_str());
  std::printf("assumed_free: %s\n",
              probe.assumes_free ? "true (the vehicle overlaps unknown space the policy assumed free)" : "false");
  for (std::size_t r = 0; r < vehicle.rotor_positions_m.size(); ++r)
    std::printf("rotor %zu: ceiling gap %s coverage %.4f | ground gap %s coverage %.4f\n", r,
                text(ceiling.rotors[r].nearest_gap_m).c_str(), ceiling.rotors[r].coverage,
                text(ground.rotors[r].nearest_gap_m).c_str(), ground.rotors[r].coverage);
  if (options.json.empty()) return;

  nlohmann::json report = io::positionProbeJson(probe, vehicle);
  report["map"] = options.map;
  report["vehicle"] = options.vehicle.empty() ? std::string("built-in: ") + vehicle.name : options.vehicle;
  report["unknown"] = io::unknownSpaceJson(index_options.unknown, unknown);
  io::writeJsonFile(options.json, report);
}

const CommandRegistration registration(22, [](CLI::App& parent) {
  auto options = std::make_shared<ProbeOptions>();
  CLI::App* command = parent.add_subcommand("probe", "Ceiling and ground gaps, clearance and validity at one body position");
  command->add_option("--map", options->map, "OctoMap file (.bt or .ot)")->required();
  command->add_option("--at", options->at, "Body centre x,y,z in metres (map frame)")->required();
  command->add_option("--vehicle", options->vehicle, "Vehicle file (default: maps/vehicles/quad.yaml)");
  command->add_option("--json", options->json, "Also write the answer as JSON to this file");
  options->unknown.addTo(*command);
  command->callback([options] { runProbe(*options); });
});

}  // namespace
}  // namespace ceilplan::app
