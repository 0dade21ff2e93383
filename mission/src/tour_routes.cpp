#include "ceilplan/mission/tour_routes.hpp"

#include <algorithm>
#include <limits>

namespace ceilplan::mission {
namespace {

// The slowest speed the evaluation flies on each segment of `waypoints` (infinity where it
// never moves). Samples run segment by segment; a waypoint closes one segment and opens the next.
std::vector<double> slowestPerSegment(const std::vector<Eigen::Vector3d>& waypoints,
                                      const planner::PathEvaluation& evaluation) {
  std::vector<double> slowest(waypoints.size() > 1 ? waypoints.size() - 1 : 0, std::numeric_limits<double>::infinity());
  std::size_t segment = 0;
  const auto skipEmpty = [&] {
    while (segment < slowest.size() && (waypoints[segment + 1] - waypoints[segment]).norm() == 0.0) ++segment;
  };
  skipEmpty();
  for (const planner::PathSample& sample : evaluation.samples) {
    if (segment >= slowest.size()) break;
    if (sample.speed_m_s > 0.0) slowest[segment] = std::min(slowest[segment], sample.speed_m_s);
    if ((sample.position_m - waypoints[segment + 1]).norm() < 1e-9) {
      ++segment;
      skipEmpty();
    }
  }
  return slowest;
}

}  // namespace

std::vector<SortieRoute> sortieRoutes(const SortiePlan& plan, const LegTable& legs, const std::vector<RouteStop>& stops,
                                      const Mission& mission) {
  std::vector<SortieRoute> routes;
  for (const Sortie& sortie : plan.sorties) {
    SortieRoute route;
    route.sortie = static_cast<int>(routes.size()) + 1;
    route.home_m = mission.home_m;
    route.cruise_speed_m_s = mission.speeds.cruise_m_s;
    for (const SortieLeg& leg : sortie.legs) {
      const TourLeg& flown = legs[leg.from][leg.to];
      const std::vector<double> slowest = slowestPerSegment(flown.waypoints, flown.evaluation);
      // The speed along a segment is set at the waypoint it leaves: the previous leg's last one
      // for this leg's first segment, none (the cruise speed) out of home.
      for (std::size_t i = 1; i < flown.waypoints.size(); ++i) {
        const double speed = slowest[i - 1];
        if (std::isfinite(speed) && !route.waypoints.empty()) route.waypoints.back().speed_m_s = speed;
        route.waypoints.emplace_back(flown.waypoints[i]);
      }
      if (leg.to == 0) continue;
      const RouteStop& stop = stops.at(leg.to - 1);
      RouteWaypoint& at = route.waypoints.back();
      at.hold_s = stop.dwell_s;
      const CameraAim aim = aimAt(at.position_m, stop.point_m);
      at.yaw_deg = aim.yaw_deg;
      at.gimbal_pitch_deg = aim.gimbal_pitch_deg;
      at.take_photo = true;
      at.name = stop.name;
    }
    routes.push_back(std::move(route));
  }
  return routes;
}

std::vector<Trajectory> routeTrajectories(const std::vector<SortieRoute>& routes, const Mission& mission,
                                          const planner::SafetyRules& rules) {
  TrajectoryLimits limits;
  limits.climb_m_s = mission.speeds.climb_m_s;
  limits.descent_m_s = mission.speeds.descent_m_s;
  limits.max_acceleration_m_s2 = mission.vehicle.limits.max_acceleration_m_s2;
  limits.max_jerk_m_s3 = mission.vehicle.limits.max_jerk_m_s3;
  limits.max_yaw_rate_deg_s = mission.vehicle.limits.max_yaw_rate_deg_s;
  TrajectoryOptions options = mission.trajectory;
  options.path_is_safe = [&rules](const std::vector<Eigen::Vector3d>& positions) {
    return !rules.checkPathDensely(positions);
  };
  std::vector<Trajectory> trajectories;
  for (const SortieRoute& route : routes) {
    trajectories.push_back(timeScale(route, limits, options));
    trajectories.back().sortie = route.sortie;
  }
  return trajectories;
}

}  // namespace ceilplan::mission
