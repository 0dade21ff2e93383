#pragma once
/// @file
/// Minimises predicted battery wear: loss_per_ah x charge + loss_per_s x time, from an ageing
/// model linearised at the route's depth of discharge (ageing_rates.hpp). Additive along motions.
/// The cost is a fraction of nominal capacity.

#include "ceilplan/planner/ageing_rates.hpp"
#include "ceilplan/planner/flight_objective.hpp"

namespace ceilplan::planner {

/// Least capacity lost under an ageing model, linearised at the route's depth of discharge (AgeingRates).
class AgeingObjective : public FlightObjective {
 public:
  /// The objective with `rates`; `model` must outlive it.
  AgeingObjective(const ompl::base::SpaceInformationPtr& si, const FlightCostModel& model, const AgeingRates& rates)
      : FlightObjective(si, model, CostWeights{0.0, rates.loss_per_s, rates.loss_per_ah}, "ageing",
                        "capacity fraction"),
        rates_(rates) {}
  /// The rates it weighs charge and time with.
  const AgeingRates& rates() const { return rates_; }

 private:
  AgeingRates rates_;
};

}  // namespace ceilplan::planner
