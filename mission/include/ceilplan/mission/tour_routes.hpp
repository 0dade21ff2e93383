#pragma once
/// @file
/// The flown tour as a vehicle flies it (docs/flying.md, "How a tour maps onto it"): one
/// SortieRoute per sortie, and each route time-scaled into setpoints that pass the dense re-check.

#include "ceilplan/mission/mission.hpp"
#include "ceilplan/mission/sortie_plan.hpp"
#include "ceilplan/mission/sortie_route.hpp"
#include "ceilplan/mission/tour_legs.hpp"
#include "ceilplan/mission/trajectory.hpp"
#include "ceilplan/planner/safety_rules.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace ceilplan::mission {

/// A place a sortie stops at: its name, the point inspected and the dwell; for a coverage photo,
/// the heading and gimbal pitch it was planned with (docs/coverage.md).
struct RouteStop {
  std::string name;  ///< the stop's name
  /// the point inspected
  Eigen::Vector3d point_m = Eigen::Vector3d::Zero();
  double dwell_s = 0.0;                    ///< hover time at the stop
  std::optional<double> yaw_deg;           ///< heading at the stop, degrees clockwise from north (photos)
  std::optional<double> gimbal_pitch_deg;  ///< gimbal pitch at the stop, degrees (photos)
  bool contact_reading = false;            ///< a contact grid point: the dwell is a reading, no photo
};

/// Each sortie's waypoints: every flown leg's waypoints after its first; at a stop's viewpoint a
/// hold of its dwell, the camera aimed at its point (or set to a photo's planned heading and
/// pitch) and a photo; each waypoint's speed the slowest the leg's evaluation flies on the
/// segment leaving it (a photo's speed cap on the move shows there). `stops[k - 1]` is place k.
std::vector<SortieRoute> sortieRoutes(const SortiePlan& plan, const LegTable& legs, const std::vector<RouteStop>& stops,
                                      const Mission& mission);

/// Each route's take-off climb and landing descent (SortieRoute::takeoff_height_m,
/// landing_height_m): the vertical climb to the first waypoint's height (at least
/// kMinTakeoffHeight_m) and the straight flight on to it, or where `rules` refuse that, the
/// highest climb of half, a quarter, ... of it that they accept; the landing likewise from the
/// last waypoint but one. Autopilots fly these instead of the tour's first and last segments.
/// Throws ceilplan::Error naming the sortie when no climb or descent down to 5 cm passes.
void assignTakeoffAndLanding(std::vector<SortieRoute>& routes, const planner::SafetyRules& rules);

/// The mission's trajectory settings and the vehicle's motion limits, blends re-checked by `rules`.
std::vector<Trajectory> routeTrajectories(const std::vector<SortieRoute>& routes, const Mission& mission,
                                          const planner::SafetyRules& rules);

}  // namespace ceilplan::mission
