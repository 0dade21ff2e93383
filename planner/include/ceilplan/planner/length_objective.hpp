#pragma once
/// @file
/// Minimises the path length (m).

#include "ceilplan/planner/flight_objective.hpp"

namespace ceilplan::planner {

/// Shortest path, m.
class LengthObjective : public FlightObjective {
 public:
  /// The objective; `model` must outlive it.
  LengthObjective(const ompl::base::SpaceInformationPtr& si, const FlightCostModel& model)
      : FlightObjective(si, model, CostWeights{1.0, 0.0, 0.0}, "length", "m") {}
};

}  // namespace ceilplan::planner
