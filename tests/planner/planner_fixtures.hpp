#pragma once
// Analytic scenes and the default vehicle's models for planner tests.

#include "analytic_maps.hpp"

#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/energy/paper_quad.hpp"
#include "ceilplan/environment/environment.hpp"
#include "ceilplan/planner/flight_cost_model.hpp"
#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/ompl_state.hpp"
#include "ceilplan/planner/safety_rules.hpp"

#include <ompl/base/Planner.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/geometric/PathGeometric.h>

#include <functional>
#include <memory>
#include <utility>

namespace ceilplan::testing {

// A corridor along x, `length_m` long (7 m by default), 5 m wide, floor top at 0.2 m, ceiling
// underside at `ceiling(x, y)` (0.4 m slab), walls beyond |y| = 2.5 m and x outside
// [-0.5, length_m - 0.5]: high and wide enough that free mode's 1 m standoff leaves room. No
// ceiling: `ceiling` returns +inf (free up to 4 m).
inline environment::OccupancyMap corridor(const std::function<double(double x, double y)>& ceiling,
                                          double length_m = 7.0) {
  const double end_m = length_m - 0.5;
  return analyticMap({-0.7, -2.7, 0}, {end_m + 0.2, 2.7, 4.2}, 0.1, [&](const Eigen::Vector3d& c) {
    if (c.z() < 0.2 || std::abs(c.y()) > 2.5 || c.x() < -0.5 || c.x() > end_m) return CellState::Occupied;
    const double underside = ceiling(c.x(), c.y());
    if (c.z() < std::min(underside, 4.0)) return CellState::Free;
    if (c.z() < underside + 0.4) return CellState::Occupied;
    return std::isfinite(underside) ? CellState::Unknown : CellState::Free;
  });
}

inline double flatCeiling(double, double) { return 3.5; }

// A 3.3 x 2.4 m room, ceiling at 2.0 m with one 0.4 m deep beam across it at x in [0, 0.3).
inline environment::OccupancyMap beamRoom() {
  return analyticMap({-1.5, -1.2, 0}, {1.8, 1.2, 2.4}, 0.1, [](const Eigen::Vector3d& c) {
    if (c.z() < 0.2 || c.z() > 2.0) return CellState::Occupied;
    if (c.x() >= 0.0 && c.x() < 0.3 && c.z() > 1.6) return CellState::Occupied;
    return CellState::Free;
  });
}

inline energy::EnergyModel paperEnergy() { return energy::EnergyModel(energy::paperQuadParameters()); }

// Start and goal under a ceiling at height h: the rotor plane 7 cm below it.
inline double bodyHeightUnder(double ceiling_m) { return ceiling_m - 0.1; }

// A map with the default vehicle, the paper's energy model, the rules of both modes (5 cm
// minimum rotor gap) and a planner under the charge objective, with a mode's cost model
// options (by default ceiling mode's).
struct PlannerScene {
  explicit PlannerScene(environment::OccupancyMap scene_map, planner::CostModelOptions cost = {})
      : map(std::move(scene_map)), cost_options(cost) {}
  environment::OccupancyMap map;
  planner::CostModelOptions cost_options;
  environment::Environment environment{map, quad()};
  energy::EnergyModel energy = paperEnergy();
  planner::SafetyRules rules{environment, 0.05};
  planner::FlightCostModel model{environment, energy, cost_options};
  planner::FlightPlanner planner{rules, model, planner::ObjectiveChoice{}};
};
using CeilingScene = PlannerScene;

// What an OMPL planner returned for one query.
struct Solved {
  ompl::base::PlannerStatus status;
  std::vector<Eigen::Vector3d> waypoints;  // empty without an exact solution
  double cost = 0.0;                       // as the planner reported it
};

// Runs `planner` (made on `flight_planner`'s space) on one query under its objective.
inline Solved solveOnce(ompl::base::Planner& planner, const planner::FlightPlanner& flight_planner,
                        const Eigen::Vector3d& start_m, const Eigen::Vector3d& goal_m, double time_limit_s = 120.0) {
  const ompl::base::SpaceInformationPtr& si = flight_planner.spaceInformation();
  auto definition = std::make_shared<ompl::base::ProblemDefinition>(si);
  ompl::base::ScopedState<> start(si), goal(si);
  planner::setPosition(start.get(), start_m);
  planner::setPosition(goal.get(), goal_m);
  definition->setStartAndGoalStates(start, goal, 1e-6);
  definition->setOptimizationObjective(flight_planner.objectivePtr());
  planner.setProblemDefinition(definition);
  Solved solved{planner.solve(time_limit_s), {}, 0.0};
  if (solved.status == ompl::base::PlannerStatus::EXACT_SOLUTION) {
    for (const ompl::base::State* s : definition->getSolutionPath()->as<ompl::geometric::PathGeometric>()->getStates())
      solved.waypoints.push_back(planner::toPosition(s));
    ompl::base::PlannerSolution solution(nullptr);
    definition->getSolution(solution);
    solved.cost = solution.cost_.value();
  }
  return solved;
}

}  // namespace ceilplan::testing
