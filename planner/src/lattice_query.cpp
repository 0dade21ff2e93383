#include "lattice_query.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/planner/ompl_state.hpp"
#include "ceilplan/planner/state_validity_checker.hpp"

#include <ompl/base/goals/GoalState.h>
#include <ompl/geometric/PathGeometric.h>

namespace ceilplan::planner::detail {

const SafetyRules& rulesOf(const ompl::base::SpaceInformation& si, const std::string& planner_name) {
  const auto* checker = dynamic_cast<const FlightStateValidityChecker*>(si.getStateValidityChecker().get());
  if (!checker)
    throw ceilplan::Error(planner_name +
                          " plans under ceilplan's safety rules: give the space a FlightStateValidityChecker");
  return checker->rules();
}

const FlightObjective& objectiveOf(const ompl::base::ProblemDefinition& definition, const std::string& planner_name) {
  const auto* objective = dynamic_cast<const FlightObjective*>(definition.getOptimizationObjective().get());
  if (!objective)
    throw ceilplan::Error(planner_name + " minimises ceilplan's objectives: give the problem a FlightObjective");
  return *objective;
}

std::optional<LatticeQuery> readQuery(const ompl::base::ProblemDefinition& definition,
                                      ompl::base::PlannerStatus& failure) {
  const auto* goal = dynamic_cast<const ompl::base::GoalState*>(definition.getGoal().get());
  if (!goal) {
    failure = ompl::base::PlannerStatus::UNRECOGNIZED_GOAL_TYPE;
    return std::nullopt;
  }
  if (definition.getStartStateCount() == 0) {
    failure = ompl::base::PlannerStatus::INVALID_START;
    return std::nullopt;
  }
  return LatticeQuery{toPosition(definition.getStartState(0)), toPosition(goal->getState())};
}

void addSolution(const ompl::base::Planner& planner, const std::vector<Eigen::Vector3d>& waypoints, double cost) {
  const ompl::base::SpaceInformationPtr& si = planner.getSpaceInformation();
  auto path = std::make_shared<ompl::geometric::PathGeometric>(si);
  ompl::base::State* state = si->allocState();
  for (const Eigen::Vector3d& p : waypoints) {
    setPosition(state, p);
    path->append(state);
  }
  si->freeState(state);
  ompl::base::PlannerSolution solution(path);
  solution.setPlannerName(planner.getName());
  solution.setOptimized(planner.getProblemDefinition()->getOptimizationObjective(), ompl::base::Cost(cost), true);
  planner.getProblemDefinition()->addSolutionPath(solution);
}

}  // namespace ceilplan::planner::detail
