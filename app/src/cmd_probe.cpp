// `ceilplan probe`: what the planner and the energy model see at one body position.

#include "command_registry.hpp"
#include "map_options.hpp"

#include "ceilplan/io/unknown_space_report.hpp"
#include "output.hpp"

#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/vehicle_file.hpp"

#include "ceilplan/environment/environment.hpp"
#include "ceilplan/environment/map_index.hpp"
#include "ceilplan/core/error.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <stdexcept>
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

Eigen::Vector3d parsePoint(const std::string& text) {
  std::istringstream in(text);
  Eigen::Vector3d point;
  char comma1 = 0, comma2 = 0;
  if (!(in >> point.x() >> comma1 >> point.y() >> comma2 >> point.z()) || comma1 != ',' || comma2 != ',' ||
      !(in >> std::ws).eof() || !point.allFinite())
    throw ceilplan::InputError("--at '" + text + "': expected three finite numbers x,y,z in metres");
  return point;
}


std::string text(double value) {
  if (!std::isfinite(value)) return "none";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4f", value);
  return buffer;
}

nlohmann::json gapJson(const environment::RotorGap& gap) {
  return {{"nearest_gap_m", io::finiteOrNull(gap.nearest_gap_m)}, {"coverage", gap.coverage}, {"mean_gap_m", io::finiteOrNull(gap.mean_gap_m)}};
}

void runProbe(const ProbeOptions& options) {
  using namespace environment;
  if (!options.json.empty()) checkWritableFile(options.json);
  const Eigen::Vector3d body = parsePoint(options.at);
  const VehicleGeometry vehicle =
      (options.vehicle.empty() ? mission::Vehicle::defaultQuad() : io::readVehicle(options.vehicle)).geometry;
  MapIndexOptions index_options;
  index_options.unknown = options.unknown.value();
  const OccupancyMap map = OccupancyMap::load(options.map);
  Progress progress("indexing " + options.map);
  const Environment environment(MapIndex::build(map, index_options, [&](double f) { progress.update(f); }), vehicle);
  progress.finish();
  const UnknownSpaceSummary& unknown = environment.index()->unknownSummary();

  const SurfaceGaps ceiling = environment.ceiling(body);
  const SurfaceGaps ground = environment.ground(body);
  const double clearance = environment.clearance_m(body);
  const std::optional<Violation> violation = environment.stateViolation(body);
  const bool assumes_free = environment.assumesFree(body);

  std::printf("at: %.3f, %.3f, %.3f (vehicle %s)\n", body.x(), body.y(), body.z(), vehicle.name.c_str());
  std::printf("ceiling_gap_m: %s\nceiling_coverage: %.4f\nceiling_mean_gap_m: %s\n", text(ceiling.nearest_gap_m).c_str(),
              ceiling.coverage, text(ceiling.mean_gap_m).c_str());
  std::printf("ground_gap_m: %s\nground_coverage: %.4f\nground_mean_gap_m: %s\n", text(ground.nearest_gap_m).c_str(),
              ground.coverage, text(ground.mean_gap_m).c_str());
  std::printf("clearance_m: %s\nvalid: %s\n", text(clearance).c_str(), violation ? "false" : "true");
  if (violation) std::printf("violation: %s\n", violation->describe().c_str());
  std::printf("unknown: %s\n", io::unknownSpaceLine(index_options.unknown, unknown).c_str());
  std::printf("assumed_free: %s\n", assumes_free ? "true (the vehicle overlaps unknown space the policy assumed free)" : "false");
  for (std::size_t r = 0; r < vehicle.rotor_positions_m.size(); ++r)
    std::printf("rotor %zu: ceiling gap %s coverage %.4f | ground gap %s coverage %.4f\n", r,
                text(ceiling.rotors[r].nearest_gap_m).c_str(), ceiling.rotors[r].coverage,
                text(ground.rotors[r].nearest_gap_m).c_str(), ground.rotors[r].coverage);
  if (options.json.empty()) return;

  nlohmann::json rotors = nlohmann::json::array();
  for (std::size_t r = 0; r < vehicle.rotor_positions_m.size(); ++r) {
    const Eigen::Vector2d& offset = vehicle.rotor_positions_m[r];
    rotors.push_back({{"offset_m", {offset.x(), offset.y()}},
                      {"ceiling", gapJson(ceiling.rotors[r])},
                      {"ground", gapJson(ground.rotors[r])}});
  }
  const nlohmann::json report = {
      {"map", options.map},
      {"vehicle", options.vehicle.empty() ? std::string("built-in: ") + vehicle.name : options.vehicle},
      {"at", {body.x(), body.y(), body.z()}},
      {"unknown", io::unknownSpaceJson(index_options.unknown, unknown)},
      {"assumed_free", assumes_free},
      {"point_assumed_free", environment.index()->isAssumedFree(body)},
      {"ceiling_gap_m", io::finiteOrNull(ceiling.nearest_gap_m)},
      {"ceiling_coverage", ceiling.coverage},
      {"ceiling_mean_gap_m", io::finiteOrNull(ceiling.mean_gap_m)},
      {"ground_gap_m", io::finiteOrNull(ground.nearest_gap_m)},
      {"ground_coverage", ground.coverage},
      {"ground_mean_gap_m", io::finiteOrNull(ground.mean_gap_m)},
      {"clearance_m", io::finiteOrNull(clearance)},
      {"valid", !violation},
      {"violation", violation ? nlohmann::json(violation->describe()) : nlohmann::json(nullptr)},
      {"rotors", rotors}};
  writeTextAtomically(options.json, [&](std::ostream& out) { out << report.dump(2) << '\n'; });
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
