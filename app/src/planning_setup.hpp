#pragma once
// Everything a planning command needs, built from its flags: the map indexed for the vehicle,
// the energy model, the battery, the cost models (planning and full) and the safety rules. Shared by plan, evaluate,
// compare and bench-planners, which register the same flags through addPlanningOptions.

#include "ceilplan/battery/pack.hpp"
#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/environment/environment.hpp"
#include "ceilplan/environment/occupancy_map.hpp"
#include "ceilplan/planner/flight_cost_model.hpp"
#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/objective_factory.hpp"
#include "ceilplan/planner/safety_rules.hpp"

#include <CLI/CLI.hpp>
#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace ceilplan::app {

struct PlanningArguments {
  std::string map;
  std::string vehicle;  // empty: maps/vehicles/quad.yaml
  std::string battery;  // empty: the paper's pack at 95 %
  std::string objective = "charge";
  std::string ageing_model = "xu";
  double ageing_dod = 0.0;  // 0: the route's own (straight-line estimate, at least 1 %)
  planner::FlightSpeeds speeds;
  double min_ceiling_gap_m = 0.05;
  double standoff_m = 1.0;  // free mode: the conventional standoff, kept where it fits
  double temperature_c = 25.0;
};

// Registers --map, --vehicle, --battery, --objective and the model flags on `command`.
// `with_objective` false leaves --objective out (commands that report every objective).
void addPlanningOptions(CLI::App* command, PlanningArguments& arguments, bool with_objective = true);

// The search flags shared by plan, compare and bench-planners.
struct SearchArguments {
  std::string planner;  // empty: the default
  double time_limit_s = 5.0;
  std::uint32_t seed = 1;
  double band_fraction = 0.0;  // uniform by default: the band did not help BIT* in the study (docs/planner.md)
  bool no_refine = false;
  double lattice_spacing_m = 0.2;  // the lattice planners' node spacing

  planner::PlanRequest request(const Eigen::Vector3d& start_m, const Eigen::Vector3d& goal_m) const;
  std::string plannerName() const;
};
void addSearchOptions(CLI::App* command, SearchArguments& arguments);

// The battery file (docs/planner.md): capacity_ah, start_soc, charge_current_a, cell_count,
// soc_min, state_of_health at the top level or under `battery:` (so a mission file serves).
struct BatteryChoice {
  battery::Pack pack;
  double start_soc = 0.95;
  std::string source = "built-in: the founding paper's 4S 5.2 Ah pack at 95 %";
};
BatteryChoice readBatteryFile(const std::filesystem::path& path);

Eigen::Vector3d parsePoint(const std::string& text, const std::string& flag);

enum class PlanningMode { Ceiling, Free };
PlanningMode modeFromName(const std::string& name);
std::string modeName(PlanningMode mode);

// Builds the map index, the energy model and the battery once; modes are then cheap to add.
class PlanningSetup {
 public:
  explicit PlanningSetup(const PlanningArguments& arguments);

  const PlanningArguments& arguments() const { return arguments_; }
  const environment::Environment& environment() const { return *environment_; }
  const energy::EnergyModel& energy() const { return *energy_; }
  const BatteryChoice& battery() const { return battery_; }
  std::string vehicleName() const { return vehicle_name_; }

  // The full proximity model at the planning SOC: every reported figure comes from it.
  const planner::FlightCostModel& fullModel() const { return *full_model_; }
  // The safety rules of every mode: what the dense re-check and `evaluate` apply.
  const planner::SafetyRules& baseRules() const { return *base_rules_; }

  // What one mode plans with: the same safety rules in both; free mode's cost ignores
  // proximity effects and prefers the conventional standoff (CostModelOptions::standoff_m).
  // `start_m` and `goal_m` are no longer used (to be dropped).
  struct Mode {
    std::unique_ptr<planner::FlightCostModel> model;
    std::unique_ptr<planner::SafetyRules> rules;
  };
  Mode mode(PlanningMode mode, const Eigen::Vector3d& start_m, const Eigen::Vector3d& goal_m) const;

  // The objective, with ageing rates measured for the route's expected depth of discharge.
  planner::ObjectiveChoice objective(const Eigen::Vector3d& start_m, const Eigen::Vector3d& goal_m) const;

 private:
  PlanningArguments arguments_;
  std::string vehicle_name_;
  std::unique_ptr<environment::OccupancyMap> map_;
  std::unique_ptr<environment::Environment> environment_;
  std::unique_ptr<energy::EnergyModel> energy_;
  BatteryChoice battery_;
  std::unique_ptr<planner::FlightCostModel> full_model_;
  std::unique_ptr<planner::SafetyRules> base_rules_;
};

}  // namespace ceilplan::app
