#pragma once
/// @file
/// Minimises full equivalent cycles: the flight's discharge Q and the recharge that puts it back,
/// FEC = (Q + Q) / (2 C_nom) = Q / C_nom (Kocer et al. 2019, arXiv 1812.11707, eq. 6),
/// with C_nom the pack's nominal capacity.

#include "ceilplan/core/error.hpp"
#include "ceilplan/planner/flight_objective.hpp"

#include <stdexcept>

namespace ceilplan::planner {

/// Least full equivalent cycles: the charge drawn over the nominal capacity.
class FecObjective : public FlightObjective {
 public:
  /// The objective for a pack of `nominal_capacity_ah` (> 0, else ceilplan::InputError); `model` must outlive it.
  FecObjective(const ompl::base::SpaceInformationPtr& si, const FlightCostModel& model, double nominal_capacity_ah)
      : FlightObjective(si, model, CostWeights{0.0, 0.0, inverseCapacity(nominal_capacity_ah)}, "fec", "FEC") {}

 private:
  static double inverseCapacity(double capacity_ah) {
    if (!(capacity_ah > 0.0)) throw ceilplan::InputError("fec objective: the pack's capacity must be > 0 Ah");
    return 1.0 / capacity_ah;
  }
};

}  // namespace ceilplan::planner
