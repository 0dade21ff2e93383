// `ceilplan current`: predicted battery current for one flight condition, or against ceiling gap.

#include "cli_checks.hpp"
#include "command_registry.hpp"
#include "output.hpp"

#include "ceilplan/energy/ceiling_gap_sweep.hpp"
#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/energy/wind.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/report_json.hpp"
#include "ceilplan/io/report_text.hpp"
#include "ceilplan/io/vehicle_file.hpp"
#include "ceilplan/planner/flight_cost_model.hpp"

#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::app {
namespace {

struct CurrentOptions {
  std::optional<double> gap_m;
  std::optional<double> ground_gap_m;
  double coverage = 1.0;
  double speed_m_s = 0.0;
  double headwind_m_s = 0.0;
  double climb_m_s = 0.0;
  std::optional<double> soc;
  std::string vehicle_path;
  std::string json_path;
  bool sweep = false;
};

void runCurrent(const CurrentOptions& options) {
  io::OutputSet out({{"--json", options.json_path}}, commandInputs({{"--vehicle", options.vehicle_path}}));
  const mission::Vehicle vehicle = io::readVehicleOrDefault(options.vehicle_path);
  const io::Provenance provenance = commandProvenance().input("vehicle", options.vehicle_path);
  const energy::EnergyModel model(vehicle.energy);
  energy::FlightCondition flight;
  flight.ground_gap_m = options.ground_gap_m.value_or(energy::kNoSurface);
  flight.speed_m_s = options.speed_m_s;
  flight.headwind_m_s = options.headwind_m_s;
  flight.climb_m_s = options.climb_m_s;
  flight.soc = options.soc.value_or(vehicle.energy.reference_soc);
  const double gap_m = options.gap_m.value_or(energy::kNoSurface);
  const energy::CurrentBreakdown at_point = model.breakdown(gap_m, options.coverage, flight);  // validates input

  print(io::flightConditionText(vehicle.name, options.coverage, options.ground_gap_m, flight));
  nlohmann::json report;
  if (options.sweep) {
    const double radius_m = model.rotorRadiusM();
    const double free_air_a = model.currentA(energy::kNoSurface, options.coverage, flight);
    const std::vector<energy::GapPoint> sweep = energy::ceilingGapSweep(model, options.coverage, flight);
    print(io::currentSweepText(radius_m, free_air_a, sweep));
    report = io::currentSweepReportJson(vehicle.name, options.coverage, flight, radius_m, free_air_a, sweep);
  } else {
    print(io::currentBreakdownText(options.gap_m, at_point));
    report = io::currentReportJson(vehicle.name, gap_m, options.coverage, flight, at_point);
  }
  if (!options.json_path.empty()) {
    io::writeJsonFile(out.path("--json"), io::withProvenance(report, provenance));
    out.commit();
    print("wrote " + options.json_path + "\n");
  }
}

const CommandRegistration registration(30, [](CLI::App& parent) {
  auto options = std::make_shared<CurrentOptions>();
  CLI::App* command = parent.add_subcommand(
      "current", "Predict battery current and power from ceiling gap, ground gap, speed, climb and SOC");
  CLI::Option* gap = command->add_option("--gap-m", options->gap_m, "rotor plane to ceiling (m); absent: no ceiling");
  command->add_option("--ground-gap-m", options->ground_gap_m, "rotor plane to ground (m); absent: no ground");
  command->add_option("--coverage", options->coverage, "fraction of each rotor disc under the ceiling, 0..1")
      ->capture_default_str();
  command->add_option("--speed-m-s", options->speed_m_s, "horizontal ground speed (m/s)")->capture_default_str();
  command
      ->add_option("--headwind-m-s", options->headwind_m_s,
                   "wind along the track (m/s), positive against the motion, negative a tailwind; the power sees "
                   "the airspeed |speed + headwind|")
      ->capture_default_str()
      ->check(finiteRange(-energy::Wind::kMaxSpeed_m_s, energy::Wind::kMaxSpeed_m_s));
  constexpr double kMaxRate_m_s = planner::FlightSpeeds::kMaxVerticalSpeed_m_s;  // as a mission file allows
  command->add_option("--climb-m-s", options->climb_m_s, "climb rate (m/s), negative in descent")
      ->capture_default_str()
      ->check(finiteRange(-kMaxRate_m_s, kMaxRate_m_s));
  command->add_option("--soc", options->soc, "state of charge 0..1; default: the vehicle's reference_soc");
  command->add_option("--vehicle", options->vehicle_path, "vehicle YAML file; default: the built-in quadrotor");
  command->add_option("--json", options->json_path, "also write the result as JSON to this file");
  command->add_flag("--sweep", options->sweep, "print current against ceiling gap from 0 to 3 rotor radii")
      ->excludes(gap);
  command->callback([options] { runCurrent(*options); });
});

}  // namespace
}  // namespace ceilplan::app
