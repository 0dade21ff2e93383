#pragma once
/// @file
/// A flown path's current profile as the battery module's load segments, for the founding
/// paper's month-long duty projection (compare, tour).

#include "ceilplan/battery/duty_cycle.hpp"
#include "ceilplan/planner/path_evaluation.hpp"

#include <vector>

namespace ceilplan::mission {

/// Discharge segments of at most a second each over `samples` (in time order; coulomb counting
/// is linear, so merging keeps charge and FEC exact).
battery::LoadProfile dischargeProfile(const std::vector<planner::PathSample>& samples);

/// The evaluation's profile, repeated `repeats` times.
battery::LoadProfile flightProfile(const planner::PathEvaluation& evaluation, int repeats);

}  // namespace ceilplan::mission
