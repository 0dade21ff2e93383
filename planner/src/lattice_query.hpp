#pragma once
// How the lattice planners read an OMPL problem (ceilplan's rules behind the space's validity
// checker, the FlightObjective, one start, one goal state) and hand a path back to it.

#include "ceilplan/planner/flight_objective.hpp"
#include "ceilplan/planner/safety_rules.hpp"

#include <ompl/base/Planner.h>
#include <Eigen/Core>

#include <optional>
#include <vector>

namespace ceilplan::planner::detail {

// The rules behind the space's validity checker; throws ceilplan::Error when it is not a
// FlightStateValidityChecker.
const SafetyRules& rulesOf(const ompl::base::SpaceInformation& si, const std::string& planner_name);

// The problem's objective; throws ceilplan::Error when it is not a FlightObjective.
const FlightObjective& objectiveOf(const ompl::base::ProblemDefinition& definition, const std::string& planner_name);

struct LatticeQuery {
  Eigen::Vector3d start_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d goal_m = Eigen::Vector3d::Zero();
};

// The first start state and the goal state, or nothing when the goal is not a GoalState
// (UNRECOGNIZED_GOAL_TYPE) or there is no start (INVALID_START): `failure` says which.
std::optional<LatticeQuery> readQuery(const ompl::base::ProblemDefinition& definition,
                                      ompl::base::PlannerStatus& failure);

// Hands `waypoints` to the problem as an exact solution found by `planner`.
void addSolution(const ompl::base::Planner& planner, const std::vector<Eigen::Vector3d>& waypoints, double cost);

}  // namespace ceilplan::planner::detail
