#include "ceilplan/mission/tour_routes.hpp"

#include "ceilplan/core/error.hpp"

#include <algorithm>
#include <functional>
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
    route.cruise_speed_m_s = mission.planning.speeds.cruise_m_s;
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
      // At a contact point the probe reads: the camera is not aimed, no heading or pitch is commanded.
      if (stop.gimbal_pitch_deg && !stop.contact_reading) {
        at.yaw_deg = stop.yaw_deg;
        at.gimbal_pitch_deg = stop.gimbal_pitch_deg;
      } else if (!stop.contact_reading) {
        const CameraAim aim = aimAt(at.position_m, stop.point_m);
        at.yaw_deg = aim.yaw_deg;
        at.gimbal_pitch_deg = aim.gimbal_pitch_deg;
      }
      at.take_photo = !stop.contact_reading;
      at.contact_reading = stop.contact_reading;
      at.name = stop.name;
    }
    routes.push_back(std::move(route));
  }
  return routes;
}

namespace {

// The highest of `preferred`, half of it, a quarter, ... (down to 5 cm) for which `path(height)`
// passes the dense re-check; none if even the lowest fails.
std::optional<double> highestSafeHeight(double preferred_m,
                                        const std::function<std::vector<Eigen::Vector3d>(double)>& path,
                                        const planner::SafetyRules& rules) {
  constexpr double kLowest_m = 0.05;
  if (!rules.checkPathDensely(path(preferred_m))) return preferred_m;
  for (double height = preferred_m / 2.0; height >= kLowest_m; height /= 2.0)
    if (!rules.checkPathDensely(path(height))) return height;
  return std::nullopt;
}

}  // namespace

void assignTakeoffAndLanding(std::vector<SortieRoute>& routes, const planner::SafetyRules& rules) {
  for (SortieRoute& route : routes) {
    const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d first = route.waypoints.at(0).position_m;
    const auto climb = [&](double h) {
      return std::vector<Eigen::Vector3d>{route.home_m, route.home_m + h * up, first};
    };
    route.takeoff_height_m.reset();
    route.landing_height_m.reset();
    route.takeoff_height_m = highestSafeHeight(route.takeoffHeight_m(), climb, rules);
    if (!route.takeoff_height_m)
      throw Error("sortie " + std::to_string(route.sortie) +
                  ": no vertical take-off from home of 5 cm or more reaches " +
                  "the first waypoint without failing the dense re-check");
    if (!route.endsAtHome() || route.waypoints.size() < 2) continue;
    const Eigen::Vector3d last = route.waypoints[route.waypoints.size() - 2].position_m;
    const auto descent = [&](double h) {
      return std::vector<Eigen::Vector3d>{last, route.home_m + h * up, route.home_m};
    };
    route.landing_height_m = highestSafeHeight(route.landingHeight_m(), descent, rules);
    if (!route.landing_height_m)
      throw Error("sortie " + std::to_string(route.sortie) +
                  ": no vertical landing at home of 5 cm or more is reached " +
                  "from the last waypoint but one without failing the dense re-check");
  }
}

std::vector<Trajectory> routeTrajectories(const std::vector<SortieRoute>& routes, const Mission& mission,
                                          const planner::SafetyRules& rules) {
  TrajectoryLimits limits;
  limits.climb_m_s = mission.planning.speeds.climb_m_s;
  limits.descent_m_s = mission.planning.speeds.descent_m_s;
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
