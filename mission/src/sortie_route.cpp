#include "ceilplan/mission/sortie_route.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <algorithm>
#include <cmath>

namespace ceilplan::mission {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;
constexpr double kHorizontalEpsilon_m = 0.01;

double wrapDegrees(double degrees) {
  double wrapped = std::fmod(degrees, 360.0);
  if (wrapped < 0.0) wrapped += 360.0;
  return wrapped >= 360.0 ? 0.0 : wrapped;
}

// Bearing of a horizontal displacement, degrees clockwise from north.
double bearing_deg(const Eigen::Vector3d& displacement) {
  return wrapDegrees(std::atan2(displacement.x(), displacement.y()) / kDegree);
}

}  // namespace

void SortieRoute::validate() const {
  if (!home_m.allFinite()) throw InputError("route: home must be finite, got " + formatPoint(home_m));
  if (waypoints.empty()) throw InputError("route of sortie " + std::to_string(sortie) + " has no waypoints");
  if (!(cruise_speed_m_s > 0.0) || !std::isfinite(cruise_speed_m_s))
    throw InputError("route: cruise speed must be positive, got " + formatNumber(cruise_speed_m_s) + " m/s");
  for (std::size_t k = 0; k < waypoints.size(); ++k) {
    const RouteWaypoint& w = waypoints[k];
    const std::string what = "route waypoint " + std::to_string(k + 1);
    if (!w.position_m.allFinite())
      throw InputError(what + ": position must be finite, got " + formatPoint(w.position_m));
    if (!(w.hold_s >= 0.0) || !std::isfinite(w.hold_s))
      throw InputError(what + ": hold must be finite and non-negative, got " + formatNumber(w.hold_s) + " s");
    if (w.yaw_deg && !std::isfinite(*w.yaw_deg))
      throw InputError(what + ": yaw must be finite, got " + formatNumber(*w.yaw_deg));
    if (w.speed_m_s && (!(*w.speed_m_s > 0.0) || !std::isfinite(*w.speed_m_s)))
      throw InputError(what + ": speed must be positive, got " + formatNumber(*w.speed_m_s) + " m/s");
    if (w.gimbal_pitch_deg && !(std::abs(*w.gimbal_pitch_deg) <= 90.0))
      throw InputError(what + ": gimbal pitch must lie in [-90, 90] degrees, got " + formatNumber(*w.gimbal_pitch_deg));
    if (w.trigger_distance_m && (!(*w.trigger_distance_m >= 0.0) || !std::isfinite(*w.trigger_distance_m)))
      throw InputError(what + ": trigger distance must be finite and non-negative, got " +
                       formatNumber(*w.trigger_distance_m) + " m");
    if (w.take_photo && w.contact_reading)
      throw InputError(what + ": a contact reading takes no photo: set take_photo or contact_reading, not both");
  }
  if (takeoff_height_m && (!(*takeoff_height_m > 0.0) || !std::isfinite(*takeoff_height_m)))
    throw InputError("route: take-off height must be positive, got " + formatNumber(*takeoff_height_m) + " m");
  if (landing_height_m && (!(*landing_height_m >= 0.0) || !std::isfinite(*landing_height_m)))
    throw InputError("route: landing height must be finite and non-negative, got " + formatNumber(*landing_height_m) +
                     " m");
}

double SortieRoute::speedInto_m_s(std::size_t k) const {
  if (k == 0) return cruise_speed_m_s;
  return waypoints.at(k - 1).speed_m_s.value_or(cruise_speed_m_s);
}

bool SortieRoute::endsAtHome() const {
  return !waypoints.empty() && (waypoints.back().position_m - home_m).norm() < 0.01;
}

double SortieRoute::takeoffHeight_m() const {
  if (takeoff_height_m) return *takeoff_height_m;
  return std::max(kMinTakeoffHeight_m, waypoints.at(0).position_m.z() - home_m.z());
}

double SortieRoute::landingHeight_m() const {
  if (landing_height_m) return *landing_height_m;
  return waypoints.size() < 2 ? 0.0 : std::max(0.0, waypoints[waypoints.size() - 2].position_m.z() - home_m.z());
}

double initialHeading_deg(const SortieRoute& route) {
  Eigen::Vector3d previous = route.home_m;
  for (const RouteWaypoint& w : route.waypoints) {
    const Eigen::Vector3d step = w.position_m - previous;
    if (step.head<2>().norm() > kHorizontalEpsilon_m) return bearing_deg(step);
    if (w.yaw_deg) return wrapDegrees(*w.yaw_deg);
    previous = w.position_m;
  }
  return 0.0;
}

std::vector<double> headingsInEffect_deg(const SortieRoute& route) {
  std::vector<double> headings;
  double heading = initialHeading_deg(route);
  for (const RouteWaypoint& w : route.waypoints) {
    if (w.yaw_deg) heading = wrapDegrees(*w.yaw_deg);
    headings.push_back(heading);
  }
  return headings;
}

std::vector<double> gimbalPitchesInEffect_deg(const SortieRoute& route) {
  std::vector<double> pitches;
  double pitch = 0.0;
  for (const RouteWaypoint& w : route.waypoints) {
    if (w.gimbal_pitch_deg) pitch = *w.gimbal_pitch_deg;
    pitches.push_back(pitch);
  }
  return pitches;
}

CameraAim aimAt(const Eigen::Vector3d& from_m, const Eigen::Vector3d& target_m) {
  const Eigen::Vector3d d = target_m - from_m;
  const double horizontal = d.head<2>().norm();
  CameraAim aim;
  if (horizontal > kHorizontalEpsilon_m) aim.yaw_deg = bearing_deg(d);
  aim.gimbal_pitch_deg = std::atan2(d.z(), horizontal) / kDegree;
  return aim;
}

double enuYawFromHeading_rad(double heading_deg) {
  double yaw = (90.0 - heading_deg) * kDegree;
  yaw = std::remainder(yaw, 2.0 * kPi);  // [-pi, pi]
  return yaw <= -kPi ? yaw + 2.0 * kPi : yaw;
}

double headingFromEnuYaw_deg(double yaw_rad) { return wrapDegrees(90.0 - yaw_rad / kDegree); }

}  // namespace ceilplan::mission
