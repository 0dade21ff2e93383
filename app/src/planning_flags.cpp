#include "planning_flags.hpp"

#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/io/point_text.hpp"
#include "ceilplan/io/vehicle_file.hpp"
#include "cli_checks.hpp"

#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/planner/planner_factory.hpp"

namespace ceilplan::app {

void addPlanningOptions(CLI::App* command, PlanningFlags& flags, bool with_objective) {
  mission::PlanningOptions& a = flags.options;
  command->add_option("--map", flags.map, "OctoMap file (.bt or .ot)")->required()->check(CLI::ExistingFile);
  command->add_option("--vehicle", flags.vehicle,
                      "vehicle file (default: the built-in quadrotor, as maps/vehicles/quad.yaml)");
  command->add_option(
      "--battery", flags.battery,
      "battery YAML: capacity_ah, start_soc, charge_current_a, ... (default: the paper's pack at 95 %)");
  flags.unknown.addTo(*command);
  if (with_objective) {
    command->add_option("--objective", a.objective, "what to minimise")
        ->capture_default_str()
        ->check(CLI::IsMember(planner::objectiveNames()));
    command->add_option("--ageing-model", a.ageing_model, "ageing model of --objective ageing")
        ->capture_default_str()
        ->check(CLI::IsMember(battery::ageingModelNames()));
    command
        ->add_option("--ageing-dod", a.ageing_dod,
                     "depth of discharge the ageing objective is linearised at (0: the route's own estimate)")
        ->capture_default_str()
        ->check(finiteAtLeast(0.0));
  }
  const double min_speed_m_s = planner::FlightSpeeds::kMinSpeed_m_s;
  command->add_option("--cruise-speed-m-s", a.speeds.cruise_m_s, "horizontal speed in free air")
      ->capture_default_str()
      ->check(finiteAtLeast(min_speed_m_s));
  command
      ->add_option("--near-ceiling-speed-m-s", a.speeds.near_ceiling_m_s,
                   "horizontal speed when a rotor is within --near-ceiling-radii R of a ceiling")
      ->capture_default_str()
      ->check(finiteAtLeast(min_speed_m_s));
  command->add_option("--near-ceiling-radii", a.speeds.near_ceiling_gap_radii, "gap, in rotor radii, of the slow zone")
      ->capture_default_str()
      ->check(positiveFinite());
  command->add_option("--climb-m-s", a.speeds.climb_m_s, "climb rate limit")
      ->capture_default_str()
      ->check(finiteAtLeast(min_speed_m_s));
  command->add_option("--descent-m-s", a.speeds.descent_m_s, "descent rate limit")
      ->capture_default_str()
      ->check(finiteAtLeast(min_speed_m_s));
  command->add_option("--min-ceiling-gap-m", a.min_ceiling_gap_m, "rotor plane to ceiling, never less")
      ->capture_default_str()
      ->check(nonNegativeFinite());
  command
      ->add_option("--standoff-m", a.standoff_m,
                   "free mode: the conventional distance from every structure, kept where it fits")
      ->capture_default_str()
      ->check(nonNegativeFinite());
  command->add_option("--temperature-c", a.temperature_c, "cell temperature for the ageing model")
      ->capture_default_str()
      ->check(finiteRange(-40.0, 80.0));
}

void addSearchOptions(CLI::App* command, SearchArguments& a, PlanningFlags& planning) {
  command->add_option("--planner", a.planner, "planner (default " + planner::defaultPlannerName() + ")")
      ->check(CLI::IsMember(planner::plannerNames()));
  command->add_option("--time-limit-s", a.time_limit_s, "search time per plan, up to a day")
      ->capture_default_str()
      ->check(positiveFinite() & atMost(planner::PlanRequest::kMaxTimeLimit_s));
  command->add_option("--seed", planning.options.seed, "random seed (> 0)")
      ->capture_default_str()
      ->check(CLI::Range(1u, 4294967295u));
  command->add_option("--band-fraction", a.band_fraction, "share of samples aimed under ceilings")
      ->capture_default_str()
      ->check(finiteRange(0.0, 1.0));
  command->add_flag("--no-refine", a.no_refine, "skip shortcutting and NLopt refinement");
  command->add_option("--lattice-spacing-m", a.lattice_spacing_m, "lattice and roadmap planners: node spacing")
      ->capture_default_str()
      ->check(finiteRange(planner::kMinLatticeSpacing_m, planner::kMaxLatticeSpacing_m));
}

planner::PlanRequest SearchArguments::request(const Eigen::Vector3d& start_m, const Eigen::Vector3d& goal_m) const {
  planner::PlanRequest request;
  request.start_m = start_m;
  request.goal_m = goal_m;
  request.planner = planner;
  request.time_limit_s = time_limit_s;
  request.band_fraction = band_fraction;
  request.refine = !no_refine;
  request.lattice.spacing_m = lattice_spacing_m;
  return request;
}

std::string SearchArguments::plannerName() const { return planner.empty() ? planner::defaultPlannerName() : planner; }

std::string SearchArguments::describe(std::uint32_t seed) const {
  const std::string name = plannerName();
  // The lattice planners are deterministic and run to completion: no seed, no clock.
  if (planner::plannerInfo(name).deterministic())
    return "planner " + name + " (lattice spacing " + formatNumber(lattice_spacing_m) + " m)";
  return "planner " + name + ", seed " + std::to_string(seed) + ", " + formatNumber(time_limit_s) + " s";
}

Eigen::Vector3d parsePoint(const std::string& text, const std::string& flag) {
  try {
    return io::parsePoint(text);
  } catch (const InputError&) {
    rethrowWithContext(flag + " ");
  }
}

io::Provenance planningProvenance(const PlanningFlags& flags, std::optional<std::uint64_t> seed) {
  io::Provenance provenance = commandProvenance();
  provenance.input("map", flags.map).input("vehicle", flags.vehicle).input("battery", flags.battery);
  provenance.seed = seed;
  return provenance;
}

std::vector<io::Input> planningInputs(const PlanningFlags& flags) {
  return commandInputs({{"--map", flags.map}, {"--vehicle", flags.vehicle}, {"--battery", flags.battery}});
}

std::unique_ptr<mission::PlanningContext> makePlanningContext(const PlanningFlags& flags) {
  const mission::Vehicle vehicle = io::readVehicleOrDefault(flags.vehicle);
  const mission::BatterySpec battery = io::readBatteryOrDefault(flags.battery, vehicle, flags.vehicle);
  mission::PlanningOptions options = flags.options;
  options.unknown = flags.unknown.value();
  return std::make_unique<mission::PlanningContext>(environment::OccupancyMap::load(flags.map), vehicle, battery,
                                                    options, terminalProgress());
}

}  // namespace ceilplan::app
