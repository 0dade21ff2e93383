#pragma once
// The flown tour as a vehicle flies it (docs/flying.md, "How a tour maps onto it"): one
// SortieRoute per sortie, and each route time-scaled into setpoints that pass the dense re-check.

#include "ceilplan/mission/mission.hpp"
#include "ceilplan/mission/sortie_plan.hpp"
#include "ceilplan/mission/sortie_route.hpp"
#include "ceilplan/mission/tour_legs.hpp"
#include "ceilplan/mission/trajectory.hpp"
#include "ceilplan/planner/safety_rules.hpp"

#include <Eigen/Core>

#include <vector>

namespace ceilplan::mission {

// A place a sortie stops at: its name, the point inspected and the dwell.
struct RouteStop {
  std::string name;
  Eigen::Vector3d point_m = Eigen::Vector3d::Zero();
  double dwell_s = 0.0;
};

// Each sortie's waypoints: every flown leg's waypoints after its first; at a stop's viewpoint a
// hold of its dwell, the camera aimed at its point and a photo; each waypoint's speed the
// slowest the leg's evaluation flies on the segment leaving it. `stops[k - 1]` is place k.
std::vector<SortieRoute> sortieRoutes(const SortiePlan& plan, const LegTable& legs, const std::vector<RouteStop>& stops,
                                      const Mission& mission);

// The mission's trajectory settings and the vehicle's motion limits, blends re-checked by `rules`.
std::vector<Trajectory> routeTrajectories(const std::vector<SortieRoute>& routes, const Mission& mission,
                                          const planner::SafetyRules& rules);

}  // namespace ceilplan::mission
