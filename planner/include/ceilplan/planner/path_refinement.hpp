#pragma once
/// @file
/// Post-processing that respects the objective (OMPL 1.5.2's simplifier optimises length only
/// and would pull a path away from the ceiling): shortcuts accepted only when valid and cheaper,
/// and NLopt local refinement of the waypoints, kept only if the result is valid and cheaper.

#include "ceilplan/planner/flight_objective.hpp"
#include "ceilplan/planner/safety_rules.hpp"

#include <Eigen/Core>

#include <vector>

namespace ceilplan::planner {

/// A polyline path, map coordinates.
using Waypoints = std::vector<Eigen::Vector3d>;

/// Deterministic greedy shortcutting: from each kept waypoint, jump to the farthest later one
/// whose straight motion is valid and cheaper than the path between them.
Waypoints shortcutPath(const Waypoints& path, const SafetyRules& rules, const FlightObjective& objective);

/// No clock: the refinement stops after max_evaluations, so a route does not depend on the
/// machine's speed or load.
struct RefinementOptions {
  int max_evaluations = 600;  ///< cost evaluations the refinement may spend
  int max_waypoints = 12;     ///< the path is resampled to at most this many waypoints first
  double max_move_m = 0.6;    ///< each inner waypoint moves at most this far per axis
  /// A path longer than three times this is refined within this far of each end, each end on its
  /// own, and keeps its middle; 0 refines every path whole.
  double end_window_m = 30.0;
};

/// Moves the inner waypoints with NLopt's LN_BOBYQA on cost x (1 + number of invalid motions),
/// the endpoints fixed, then keeps the result only if every motion is valid and the cost dropped.
/// A path longer than 3 x RefinementOptions::end_window_m is refined so near each of its ends.
/// Returns the input when nothing better was found.
Waypoints refinePath(const Waypoints& path, const SafetyRules& rules, const FlightObjective& objective,
                     const RefinementOptions& options);

/// Splits segments so that no segment is longer than `max_segment_m`.
Waypoints subdivide(const Waypoints& path, double max_segment_m);

}  // namespace ceilplan::planner
