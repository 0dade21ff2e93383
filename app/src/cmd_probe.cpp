// `ceilplan probe`: what the planner and the energy model see at one body position.

#include "command_registry.hpp"
#include "output.hpp"
#include "planning_flags.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/environment/position_probe.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/report_json.hpp"
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
  bool unknown_free = false;
  bool unknown_ceiling = false;
};

std::string text(double value) {
  if (!std::isfinite(value)) return "none";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4f", value);
  return buffer;
}

void runProbe(const ProbeOptions& options) {
  using namespace environment;
  const Eigen::Vector3d body = parsePoint(options.at, "--at");
  const VehicleGeometry vehicle =
      (options.vehicle.empty() ? mission::Vehicle::defaultQuad() : io::readVehicle(options.vehicle)).geometry;
  EnvironmentOptions environment_options;
  environment_options.unknown_is_occupied = !options.unknown_free;
  environment_options.unknown_is_surface = options.unknown_ceiling;
  const OccupancyMap map = OccupancyMap::load(options.map);
  Progress progress("indexing " + options.map);
  const Environment environment(map, vehicle, environment_options, [&](double f) { progress.update(f); });
  progress.finish();

  const PositionProbe probe = probePosition(environment, body);
  const SurfaceGaps &ceiling = probe.ceiling, &ground = probe.ground;

  std::printf("at: %.3f, %.3f, %.3f (vehicle %s)\n", body.x(), body.y(), body.z(), vehicle.name.c_str());
  std::printf("ceiling_gap_m: %s\nceiling_coverage: %.4f\nceiling_mean_gap_m: %s\n", text(ceiling.nearest_gap_m).c_str(),
              ceiling.coverage, text(ceiling.mean_gap_m).c_str());
  std::printf("ground_gap_m: %s\nground_coverage: %.4f\nground_mean_gap_m: %s\n", text(ground.nearest_gap_m).c_str(),
              ground.coverage, text(ground.mean_gap_m).c_str());
  std::printf("clearance_m: %s\nvalid: %s\n", text(probe.clearance_m).c_str(), probe.violation ? "false" : "true");
  if (probe.violation) std::printf("violation: %s\n", probe.violation->describe().c_str());
  for (std::size_t r = 0; r < vehicle.rotor_positions_m.size(); ++r)
    std::printf("rotor %zu: ceiling gap %s coverage %.4f | ground gap %s coverage %.4f\n", r,
                text(ceiling.rotors[r].nearest_gap_m).c_str(), ceiling.rotors[r].coverage,
                text(ground.rotors[r].nearest_gap_m).c_str(), ground.rotors[r].coverage);
  if (options.json.empty()) return;

  nlohmann::json report = io::positionProbeJson(probe, vehicle);
  report["map"] = options.map;
  report["vehicle"] = options.vehicle.empty() ? std::string("built-in: ") + vehicle.name : options.vehicle;
  report["unknown_is_occupied"] = environment_options.unknown_is_occupied;
  report["unknown_is_surface"] = environment_options.unknown_is_surface;
  io::writeJsonFile(options.json, report);
}

const CommandRegistration registration(22, [](CLI::App& parent) {
  auto options = std::make_shared<ProbeOptions>();
  CLI::App* command = parent.add_subcommand("probe", "Ceiling and ground gaps, clearance and validity at one body position");
  command->add_option("--map", options->map, "OctoMap file (.bt or .ot)")->required();
  command->add_option("--at", options->at, "Body centre x,y,z in metres (map frame)")->required();
  command->add_option("--vehicle", options->vehicle, "Vehicle file (default: maps/vehicles/quad.yaml)");
  command->add_option("--json", options->json, "Also write the answer as JSON to this file");
  command->add_flag("--unknown-free", options->unknown_free, "Treat unknown space as free for validity and clearance");
  command->add_flag("--unknown-ceiling", options->unknown_ceiling, "Treat unknown space as a surface for the gaps");
  command->callback([options] { runProbe(*options); });
});

}  // namespace
}  // namespace ceilplan::app
