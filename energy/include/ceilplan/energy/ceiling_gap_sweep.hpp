#pragma once
/// @file
/// The current against the gap to the ceiling, from touching it to a few rotor radii below
/// (`ceilplan current --sweep`, docs/energy.md): where the ceiling effect starts to pay.

#include "ceilplan/energy/energy_model.hpp"

#include <vector>

namespace ceilplan::energy {

/// One point of a sweep of the current against the ceiling gap.
struct GapPoint {
  double gap_m;                ///< rotor plane to ceiling
  CurrentBreakdown breakdown;  ///< the current and its parts at that gap
};

/// Gaps 0, R / steps_per_radius, ..., max_radii R (R the rotor radius), both ends included, each
/// at `coverage` and `flight`. Throws ceilplan::InputError for bad input, as the model does, or
/// for max_radii or steps_per_radius not positive.
std::vector<GapPoint> ceilingGapSweep(const EnergyModel& model, double coverage, const FlightCondition& flight,
                                      double max_radii = 3.0, int steps_per_radius = 20);

}  // namespace ceilplan::energy
