#pragma once
/// @file
/// Minimises the flight time (s) under the speed rules.

#include "ceilplan/planner/flight_objective.hpp"

namespace ceilplan::planner {

/// Shortest flight time, s.
class TimeObjective : public FlightObjective {
 public:
  /// The objective; `model` must outlive it.
  TimeObjective(const ompl::base::SpaceInformationPtr& si, const FlightCostModel& model)
      : FlightObjective(si, model, CostWeights{0.0, 1.0, 0.0}, "time", "s") {}
};

}  // namespace ceilplan::planner
