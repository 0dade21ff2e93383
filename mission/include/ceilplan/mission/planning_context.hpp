#pragma once
/// @file
/// Everything planning needs, built once per map, vehicle and battery: the map indexed for the
/// vehicle (one index: free mode shares it and only prefers a standoff in its cost), the energy
/// model, the cost models (planning and full) and the safety rules; flight modes are then cheap
/// to add. Shared read-only by every query, leg and command.

#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/core/progress.hpp"
#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/environment/environment.hpp"
#include "ceilplan/environment/occupancy_map.hpp"
#include "ceilplan/mission/battery_spec.hpp"
#include "ceilplan/mission/flight_mode.hpp"
#include "ceilplan/mission/mission.hpp"
#include "ceilplan/mission/planning_options.hpp"
#include "ceilplan/mission/vehicle.hpp"
#include "ceilplan/planner/flight_cost_model.hpp"
#include "ceilplan/planner/lattice_roadmap.hpp"
#include "ceilplan/planner/objective_factory.hpp"
#include "ceilplan/planner/reachable_space.hpp"
#include "ceilplan/planner/safety_rules.hpp"

#include <Eigen/Core>

#include <memory>
#include <string>

namespace ceilplan::mission {

/// The ageing models' options at a cell temperature, with the energy module's LiPo open-circuit
/// voltage curve for Schmalstieg's voltage-dependent terms.
battery::AgeingModelOptions ageingModelOptions(double temperature_c);

/// A map indexed for one vehicle and battery, with its energy, cost and safety models and the
/// planning settings: built once, shared read-only by every route, tour and thread (docs/cpp.md).
class PlanningContext {
 public:
  /// Indexes `map` for the vehicle. Throws ceilplan::InputError for bad options or vehicle.
  PlanningContext(environment::OccupancyMap map, Vehicle vehicle, BatterySpec battery, PlanningOptions options,
                  const ProgressCallback& progress = {});
  /// The mission's map (loaded here), vehicle, battery and settings (Mission::planning).
  explicit PlanningContext(const Mission& mission, const ProgressCallback& progress = {});

  /// The options the context was built with, validated.
  const PlanningOptions& options() const { return options_; }
  /// The vehicle it was built for.
  const Vehicle& vehicle() const { return vehicle_; }
  /// The battery it was built for.
  const BatterySpec& battery() const { return battery_; }
  /// The map as loaded.
  const environment::OccupancyMap& map() const { return map_; }
  /// The map indexed for the vehicle: gaps, clearance and validity queries.
  const environment::Environment& environment() const { return *environment_; }
  /// The vehicle's current model.
  const energy::EnergyModel& energy() const { return *energy_; }

  /// The full proximity model at the start SOC: every reported figure comes from it.
  const planner::FlightCostModel& fullModel() const { return *full_model_; }
  /// The safety rules of every mode: what the dense re-check and `evaluate` apply.
  const planner::SafetyRules& baseRules() const { return *base_rules_; }

  /// What one mode plans with: the same safety rules in both; free mode's cost ignores proximity
  /// effects and prefers the conventional standoff where it fits (CostModelOptions::standoff_m).
  struct Mode {
    std::unique_ptr<planner::FlightCostModel> model;  ///< the mode's cost model
    std::unique_ptr<planner::SafetyRules> rules;      ///< the safety rules (the same in both modes)
  };
  /// The cost model and safety rules `mode` plans with, built anew for the caller.
  Mode mode(FlightMode mode) const;

  /// The objective (the options', or `name`), with ageing rates measured for the route's
  /// expected depth of discharge. Throws ceilplan::InputError for an unknown name.
  planner::ObjectiveChoice objective(const Eigen::Vector3d& start_m, const Eigen::Vector3d& goal_m,
                                     const std::string& name = {}) const;

  /// Where a route from `origin_m` reaches under the safety rules (planner::ReachableSpace at
  /// `spacing_m`): flooded on first use and kept, so the two modes of a tour share one flood.
  /// Safe to call from several threads.
  const planner::ReachableSpace& reachableFrom(const Eigen::Vector3d& origin_m, double spacing_m,
                                               int workers = 1) const;
  /// What the safety rules allow on a roadmap lattice at `spacing_m`, checked as roadmaps need
  /// it and kept, so the two modes of a tour check each lattice node and edge once between them
  /// (planner::LatticeRoadmap::build). Safe to call from several threads.
  std::shared_ptr<const planner::LatticeValidity> latticeValidity(double spacing_m) const;

 private:
  struct SharedWork;
  PlanningOptions options_;
  Vehicle vehicle_;
  BatterySpec battery_;
  environment::OccupancyMap map_;
  ProgressCallback progress_;
  std::unique_ptr<environment::Environment> environment_;
  std::unique_ptr<energy::EnergyModel> energy_;
  std::unique_ptr<planner::FlightCostModel> full_model_;
  std::unique_ptr<planner::SafetyRules> base_rules_;
  std::shared_ptr<SharedWork> shared_;  ///< what the modes of a tour share
};

}  // namespace ceilplan::mission
