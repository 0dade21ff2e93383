#pragma once
/// @file
/// Minimises the flight time (s) under the speed rules.

#include "ceilplan/planner/flight_objective.hpp"

namespace ceilplan::planner {

class TimeObjective : public FlightObjective {
 public:
  TimeObjective(const ompl::base::SpaceInformationPtr& si, const FlightCostModel& model)
      : FlightObjective(si, model, CostWeights{0.0, 1.0, 0.0}, "time", "s") {}
};

}  // namespace ceilplan::planner
