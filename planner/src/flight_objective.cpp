#include "ceilplan/planner/flight_objective.hpp"

#include "ceilplan/planner/ompl_state.hpp"
#include "ceilplan/planner/rejection_band_sampler.hpp"

#include <ompl/base/goals/GoalRegion.h>

#include <algorithm>

namespace ceilplan::planner {

FlightObjective::FlightObjective(const ompl::base::SpaceInformationPtr& si, const FlightCostModel& model,
                                 CostWeights weights, const std::string& name, const std::string& unit)
    : ompl::base::OptimizationObjective(si), model_(model), weights_(weights), unit_(unit) {
  description_ = name;
  // The standoff preference in this objective's units: its weight in metres of level cruise.
  if (model_.options().standoff_m > 0.0)
    weights_.per_shortfall_m2 = model_.options().standoff_weight * model_.cruiseCostPerMetre(weights_);
  min_cost_per_m_ = model_.minCostPerMetre(weights_);
  const double per_m = min_cost_per_m_;
  setCostToGoHeuristic([per_m](const ompl::base::State* state, const ompl::base::Goal* goal) {
    const auto* region = goal->as<ompl::base::GoalRegion>();
    return ompl::base::Cost(per_m * std::max(0.0, region->distanceGoal(state) - region->getThreshold()));
  });
}

ompl::base::Cost FlightObjective::stateCost(const ompl::base::State*) const { return identityCost(); }

ompl::base::Cost FlightObjective::motionCost(const ompl::base::State* from, const ompl::base::State* to) const {
  return ompl::base::Cost(motionCost(toPosition(from), toPosition(to)));
}

ompl::base::Cost FlightObjective::motionCostHeuristic(const ompl::base::State* from,
                                                      const ompl::base::State* to) const {
  return ompl::base::Cost(heuristic(toPosition(from), toPosition(to)));
}

ompl::base::InformedSamplerPtr FlightObjective::allocInformedStateSampler(
    const ompl::base::ProblemDefinitionPtr& definition, unsigned int max_calls) const {
  return std::make_shared<RejectionBandSampler>(definition, max_calls);
}

double FlightObjective::motionCost(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) const {
  return weights_.of(model_.integrate(from_m, to_m));
}

double FlightObjective::pathCost(const std::vector<Eigen::Vector3d>& waypoints_m) const {
  double cost = 0.0;
  for (std::size_t k = 0; k + 1 < waypoints_m.size(); ++k) cost += motionCost(waypoints_m[k], waypoints_m[k + 1]);
  return cost;
}

}  // namespace ceilplan::planner
