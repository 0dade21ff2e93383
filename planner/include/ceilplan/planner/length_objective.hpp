#pragma once
/// @file
/// Minimises the path length (m).

#include "ceilplan/planner/flight_objective.hpp"

namespace ceilplan::planner {

class LengthObjective : public FlightObjective {
 public:
  LengthObjective(const ompl::base::SpaceInformationPtr& si, const FlightCostModel& model)
      : FlightObjective(si, model, CostWeights{1.0, 0.0, 0.0}, "length", "m") {}
};

}  // namespace ceilplan::planner
