#pragma once
/// @file
/// The common base of ceilplan's OMPL objectives: a motion costs a weighted sum of its length,
/// duration and charge (FlightCostModel::integrate), states cost nothing. Costs depend on the
/// direction (climbing costs more than descending), so the objective is not symmetric. The
/// heuristics are c_min x distance with c_min the cheapest cost per metre the model can give
/// anywhere: admissible, so informed planners (InformedRRTstar, BITstar, AITstar) prune safely.

#include "ceilplan/planner/flight_cost_model.hpp"

#include <ompl/base/OptimizationObjective.h>
#include <Eigen/Core>

#include <string>
#include <vector>

namespace ceilplan::planner {

/// An OMPL optimisation objective over a FlightCostModel: a weighted sum of a motion's length, time, charge and
/// standoff shortfall (CostWeights).
class FlightObjective : public ompl::base::OptimizationObjective {
 public:
  /// `model` must outlive the objective.
  FlightObjective(const ompl::base::SpaceInformationPtr& si, const FlightCostModel& model, CostWeights weights,
                  const std::string& name, const std::string& unit);

  /// OMPL: states cost nothing, motions do.
  ompl::base::Cost stateCost(const ompl::base::State* state) const override;
  /// OMPL: the cost of the straight motion between two states.
  ompl::base::Cost motionCost(const ompl::base::State* from, const ompl::base::State* to) const override;
  /// OMPL: an admissible lower bound of the cost between two states.
  ompl::base::Cost motionCostHeuristic(const ompl::base::State* from, const ompl::base::State* to) const override;
  /// OMPL: costs are not symmetric (climbing and descending differ).
  bool isSymmetric() const override { return false; }
  /// Rejection sampling from the space's sampler (so the ceiling band survives informed search).
  ompl::base::InformedSamplerPtr allocInformedStateSampler(const ompl::base::ProblemDefinitionPtr& definition,
                                                           unsigned int max_calls) const override;

  /// The cost model it weighs.
  const FlightCostModel& model() const { return model_; }
  /// Its weights.
  const CostWeights& weights() const { return weights_; }
  /// The least cost any metre of flight can have (for heuristics).
  double minCostPerMetre() const { return min_cost_per_m_; }
  /// The cost's unit, for reports ("Ah", "m", "s", "FEC", ...).
  const std::string& unit() const { return unit_; }

  /// Cost of a polyline path under the planning model.
  double pathCost(const std::vector<Eigen::Vector3d>& waypoints_m) const;
  /// Cost of the straight motion between two positions under the planning model.
  double motionCost(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) const;
  /// Admissible lower bound of the cost between two positions.
  double heuristic(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) const {
    return min_cost_per_m_ * (to_m - from_m).norm();
  }

 private:
  const FlightCostModel& model_;
  CostWeights weights_;
  double min_cost_per_m_;
  std::string unit_;
};

}  // namespace ceilplan::planner
