#pragma once
/// @file
/// The objectives by name: length, time, charge, fec, ageing.

#include "ceilplan/core/error.hpp"
#include "ceilplan/planner/ageing_rates.hpp"
#include "ceilplan/planner/flight_objective.hpp"

#include <memory>
#include <string>
#include <vector>

namespace ceilplan::planner {

/// A planning objective by name, with what it needs: the pack's capacity (fec) or the ageing rates (ageing).
struct ObjectiveChoice {
  std::string name = "charge";       ///< one of objectiveNames()
  double nominal_capacity_ah = 5.2;  ///< fec
  AgeingRates ageing;                ///< ageing (measureAgeingRates)
};

/// "length", "time", "charge", "fec", "ageing".
const std::vector<std::string>& objectiveNames();

/// Throws ceilplan::InputError for an unknown name, listing the known ones.
std::shared_ptr<FlightObjective> makeObjective(const ObjectiveChoice& choice, const ompl::base::SpaceInformationPtr& si,
                                               const FlightCostModel& model);

}  // namespace ceilplan::planner
