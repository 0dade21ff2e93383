#include "planning_setup.hpp"

#include "cli_checks.hpp"
#include "output.hpp"
#include "vehicle_energy_file.hpp"
#include "vehicle_geometry_file.hpp"

#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/energy/lipo_open_circuit_voltage.hpp"
#include "ceilplan/planner/ageing_rates.hpp"
#include "ceilplan/planner/planner_factory.hpp"
#include "ceilplan/core/error.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace ceilplan::app {

void addPlanningOptions(CLI::App* command, PlanningArguments& a, bool with_objective) {
  command->add_option("--map", a.map, "OctoMap file (.bt or .ot)")->required()->check(CLI::ExistingFile);
  command->add_option("--vehicle", a.vehicle, "vehicle file (default maps/vehicles/quad.yaml)");
  command->add_option("--battery", a.battery,
                      "battery YAML: capacity_ah, start_soc, charge_current_a, ... (default: the paper's pack at 95 %)");
  if (with_objective) {
    command->add_option("--objective", a.objective, "what to minimise")
        ->capture_default_str()
        ->check(CLI::IsMember(planner::objectiveNames()));
    command->add_option("--ageing-model", a.ageing_model, "ageing model of --objective ageing")
        ->capture_default_str()
        ->check(CLI::IsMember(battery::ageingModelNames()));
    command->add_option("--ageing-dod", a.ageing_dod,
                        "depth of discharge the ageing objective is linearised at (0: the route's own estimate)")
        ->capture_default_str()
        ->check(finiteAtLeast(0.0));
  }
  command->add_option("--cruise-speed-m-s", a.speeds.cruise_m_s, "horizontal speed in free air")
      ->capture_default_str()->check(positiveFinite());
  command->add_option("--near-ceiling-speed-m-s", a.speeds.near_ceiling_m_s,
                      "horizontal speed when a rotor is within --near-ceiling-radii R of a ceiling")
      ->capture_default_str()->check(positiveFinite());
  command->add_option("--near-ceiling-radii", a.speeds.near_ceiling_gap_radii, "gap, in rotor radii, of the slow zone")
      ->capture_default_str()->check(positiveFinite());
  command->add_option("--climb-m-s", a.speeds.climb_m_s, "climb rate limit")->capture_default_str()->check(positiveFinite());
  command->add_option("--descent-m-s", a.speeds.descent_m_s, "descent rate limit")
      ->capture_default_str()->check(positiveFinite());
  command->add_option("--min-ceiling-gap-m", a.min_ceiling_gap_m, "rotor plane to ceiling, never less")
      ->capture_default_str()->check(nonNegativeFinite());
  command->add_option("--standoff-m", a.standoff_m, "free mode: the conventional distance from every structure, kept where it fits")
      ->capture_default_str()->check(nonNegativeFinite());
  command->add_option("--temperature-c", a.temperature_c, "cell temperature for the ageing model")
      ->capture_default_str()->check(CLI::Range(-40.0, 80.0));
}

void addSearchOptions(CLI::App* command, SearchArguments& a) {
  command->add_option("--planner", a.planner, "planner (default " + planner::defaultPlannerName() + ")")
      ->check(CLI::IsMember(planner::plannerNames()));
  command->add_option("--time-limit-s", a.time_limit_s, "search time per plan")->capture_default_str()->check(positiveFinite());
  command->add_option("--seed", a.seed, "random seed (> 0)")->capture_default_str()->check(CLI::Range(1u, 4294967295u));
  command->add_option("--band-fraction", a.band_fraction, "share of samples aimed under ceilings")
      ->capture_default_str()->check(CLI::Range(0.0, 1.0));
  command->add_flag("--no-refine", a.no_refine, "skip shortcutting and NLopt refinement");
  command->add_option("--lattice-spacing-m", a.lattice_spacing_m, "lattice and roadmap planners: node spacing")
      ->capture_default_str()->check(CLI::Range(0.01, 2.0));
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

namespace {

double numberAt(const YAML::Node& node, const std::string& key, double fallback, const std::string& file) {
  if (!node[key]) return fallback;
  try {
    const double value = node[key].as<double>();
    if (!std::isfinite(value)) throw ceilplan::InputError("not finite");
    return value;
  } catch (const std::exception&) {
    throw ceilplan::InputError(file + ": '" + key + "' must be a finite number");
  }
}

}  // namespace

BatteryChoice readBatteryFile(const std::filesystem::path& path) {
  BatteryChoice choice;
  YAML::Node root;
  try {
    if (!std::filesystem::exists(path)) throw std::runtime_error("no such file");
    root = YAML::LoadFile(path.string());
  } catch (const std::exception& e) {
    throw ceilplan::InputError("battery file " + path.string() + ": " + e.what());
  }
  const YAML::Node node = root["battery"] ? root["battery"] : root;
  if (!node.IsMap()) throw ceilplan::InputError("battery file " + path.string() + ": expected a map of keys");
  const std::string file = "battery file " + path.string();
  battery::Pack& pack = choice.pack;
  pack.capacity_ah = numberAt(node, "capacity_ah", pack.capacity_ah, file);
  pack.charge_current_a = numberAt(node, "charge_current_a", pack.charge_current_a, file);
  pack.cell_count = static_cast<int>(numberAt(node, "cell_count", pack.cell_count, file));
  pack.soc_min = numberAt(node, "soc_min", pack.soc_min, file);
  pack.state_of_health = numberAt(node, "state_of_health", pack.state_of_health, file);
  choice.start_soc = numberAt(node, "start_soc", choice.start_soc, file);
  try {
    pack.validate();
  } catch (const std::exception& e) {
    throw ceilplan::InputError(file + ": " + e.what());
  }
  if (!(choice.start_soc > pack.soc_min && choice.start_soc <= pack.soc_max))
    throw ceilplan::InputError(file + ": start_soc must lie in (soc_min, soc_max]");
  choice.source = path.string();
  return choice;
}

Eigen::Vector3d parsePoint(const std::string& text, const std::string& flag) {
  std::istringstream in(text);
  Eigen::Vector3d point;
  char comma1 = 0, comma2 = 0;
  if (!(in >> point.x() >> comma1 >> point.y() >> comma2 >> point.z()) || comma1 != ',' || comma2 != ',' ||
      !(in >> std::ws).eof() || !point.allFinite())
    throw ceilplan::InputError(flag + " '" + text + "': expected three finite numbers x,y,z in metres");
  return point;
}

PlanningMode modeFromName(const std::string& name) {
  if (name == "ceiling") return PlanningMode::Ceiling;
  if (name == "free") return PlanningMode::Free;
  throw ceilplan::InputError("unknown mode '" + name + "': choose ceiling or free");
}

std::string modeName(PlanningMode mode) { return mode == PlanningMode::Ceiling ? "ceiling" : "free"; }

PlanningSetup::PlanningSetup(const PlanningArguments& arguments) : arguments_(arguments) {
  const std::filesystem::path vehicle_file =
      arguments_.vehicle.empty() ? defaultVehicleFile() : std::filesystem::path(arguments_.vehicle);
  if (arguments_.vehicle.empty() && !std::filesystem::exists(vehicle_file))
    throw ceilplan::InputError("no --vehicle given and " + vehicle_file.string() + " is not here; pass --vehicle FILE");
  const environment::VehicleGeometry geometry = readVehicleGeometry(vehicle_file);
  const VehicleEnergyFile energy_file = readVehicleEnergyFile(vehicle_file);
  vehicle_name_ = geometry.name;
  energy_ = std::make_unique<energy::EnergyModel>(energy_file.parameters);
  if (!arguments_.battery.empty()) battery_ = readBatteryFile(arguments_.battery);

  map_ = std::make_unique<environment::OccupancyMap>(environment::OccupancyMap::load(arguments_.map));
  Progress progress("indexing " + arguments_.map);
  environment_ = std::make_unique<environment::Environment>(*map_, geometry, environment::EnvironmentOptions{},
                                                            [&](double f) { progress.update(f); });
  progress.finish();

  planner::CostModelOptions full;
  full.speeds = arguments_.speeds;
  full.planning_soc = battery_.start_soc;
  full_model_ = std::make_unique<planner::FlightCostModel>(*environment_, *energy_, full);
  base_rules_ = std::make_unique<planner::SafetyRules>(*environment_, arguments_.min_ceiling_gap_m);
}

PlanningSetup::Mode PlanningSetup::mode(PlanningMode mode, const Eigen::Vector3d&, const Eigen::Vector3d&) const {
  Mode result;
  planner::CostModelOptions options = full_model_->options();
  if (mode == PlanningMode::Free) {
    options.proximity_effects = false;
    options.standoff_m = arguments_.standoff_m;
  }
  result.model = std::make_unique<planner::FlightCostModel>(*environment_, *energy_, options);
  result.rules = std::make_unique<planner::SafetyRules>(*environment_, arguments_.min_ceiling_gap_m);
  return result;
}

planner::ObjectiveChoice PlanningSetup::objective(const Eigen::Vector3d& start_m, const Eigen::Vector3d& goal_m) const {
  planner::ObjectiveChoice choice;
  choice.name = arguments_.objective;
  choice.nominal_capacity_ah = battery_.pack.capacity_ah;
  if (choice.name != "ageing") return choice;
  // The route's expected depth of discharge: the straight line's charge under the full model
  // (a fair estimate for a route a little longer), never below 1 %.
  double dod = arguments_.ageing_dod;
  if (dod == 0.0) {
    const double straight_ah = full_model_->integrate(start_m, goal_m).charge_ah;
    dod = std::max(0.01, straight_ah / battery_.pack.usableCapacityAh());
  }
  dod = std::min(dod, battery_.start_soc - battery_.pack.soc_min);
  battery::AgeingModelOptions options;
  options.conditions = battery::OperatingConditions::fromCelsius(arguments_.temperature_c);
  const energy::LipoOpenCircuitVoltage ocv;  // the energy module's cell curve, for Schmalstieg
  options.cell_voltage_of_soc = [ocv](double soc) { return ocv.cellVoltageV(soc); };
  energy::FlightCondition cruise;
  cruise.speed_m_s = arguments_.speeds.cruise_m_s;
  cruise.soc = battery_.start_soc;
  const double cruise_current_a = energy_->currentA(energy::kNoSurface, 0.0, cruise);
  choice.ageing = planner::measureAgeingRates(arguments_.ageing_model, options, battery_.pack, battery_.start_soc, dod,
                                              cruise_current_a);
  return choice;
}

}  // namespace ceilplan::app
