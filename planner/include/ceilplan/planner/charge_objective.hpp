#pragma once
/// @file
/// Minimises the charge drawn from the pack (Ah).

#include "ceilplan/planner/flight_objective.hpp"

namespace ceilplan::planner {

/// Least charge drawn, Ah.
class ChargeObjective : public FlightObjective {
 public:
  /// The objective; `model` must outlive it.
  ChargeObjective(const ompl::base::SpaceInformationPtr& si, const FlightCostModel& model)
      : FlightObjective(si, model, CostWeights{0.0, 0.0, 1.0}, "charge", "Ah") {}
};

}  // namespace ceilplan::planner
