#pragma once
/// @file
/// One sortie as a vehicle flies it: the waypoints after take-off in the map frame (x east,
/// y north, z up, metres), each with what to do there (hover, face a heading, pitch the camera,
/// take a photo). Autopilot files (io/autopilot_export.hpp, io/dji_wpml.hpp), the time-scaled
/// trajectory (mission/trajectory.hpp) and the maps (io/geo_export.hpp) are all written from it.
/// docs/flying.md says how a tour's results map onto it.

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace ceilplan::mission {

/// One waypoint of a route as a vehicle flies it: position, hold, heading, speed, gimbal and camera actions.
struct RouteWaypoint {
  /// The common case in one brace: {position, hold, heading}; set the rest by name.
  RouteWaypoint(const Eigen::Vector3d& position = Eigen::Vector3d::Zero(), double hold = 0.0,
                std::optional<double> yaw = std::nullopt)
      : position_m(position), hold_s(hold), yaw_deg(yaw) {}

  Eigen::Vector3d position_m;  ///< body centre, map frame
  double hold_s;               ///< hover here this long (inspection dwell, photo)
  /// Heading to face here, degrees clockwise from north (compass, as MAVLink's NED yaw and DJI's
  /// heading). None: keep the heading in effect.
  std::optional<double> yaw_deg;
  /// Speed along the path from this waypoint to the next (m/s). None: the route's cruise speed.
  std::optional<double> speed_m_s;
  /// Camera pitch to set on the way here, degrees: +90 straight up (soffits), 0 level, -90
  /// straight down. None: keep the pitch in effect.
  std::optional<double> gimbal_pitch_deg;
  bool take_photo = false;  ///< one photo here, once the hold is over (hover to shoot) or in passing
  /// A contact reading here (a contact grid point): the hold is the reading, no photo is taken.
  bool contact_reading = false;
  /// From here on, a photo every this many metres flown (coverage passes); 0 stops the trigger.
  std::optional<double> trigger_distance_m;
  std::string name;  ///< what is inspected here, if anything (labels in KML, GeoJSON, reports)
};

/// One sortie as an autopilot flies it: home, waypoints, speeds, take-off and landing heights (the autopilot files'
/// source).
struct SortieRoute {
  int sortie = 1;                                    ///< 1-based
  Eigen::Vector3d home_m = Eigen::Vector3d::Zero();  ///< take-off point; the flight starts here
  std::vector<RouteWaypoint> waypoints;              ///< flying order, home not repeated first (usually last)
  double cruise_speed_m_s = 2.0;                     ///< where a waypoint gives no speed
  /// Take-off: a vertical climb from home to this height above it, then straight to the first
  /// waypoint. None: the first waypoint's height above home (at least kMinTakeoffHeight_m).
  /// A tour sets it where that climb passes the dense re-check (mission::assignTakeoffAndLanding).
  std::optional<double> takeoff_height_m;
  /// Landing, where the route ends at home: straight from the last waypoint but one to this
  /// height above home, then a vertical descent. None: that waypoint's height above home.
  std::optional<double> landing_height_m;

  /// Throws ceilplan::InputError naming the waypoint (1-based) and the field: no waypoints,
  /// non-finite positions, negative holds, non-positive speeds, a pitch outside [-90, 90], a
  /// negative trigger distance.
  void validate() const;

  /// The speed flown from waypoint k - 1 (home for k = 0) to waypoint k.
  double speedInto_m_s(std::size_t k) const;

  /// Whether the last waypoint is home (within 1 cm): the sortie lands where it took off.
  bool endsAtHome() const;
  /// The take-off climb's and the landing descent's heights above home, as above.
  double takeoffHeight_m() const;
  /// The landing descent's height above home, as above.
  double landingHeight_m() const;
};

/// The lowest take-off climb an export asks for [open]: PX4 does not always leave the ground for
/// a take-off below about 0.5 m (PX4-Autopilot issue 12471), so a first waypoint lower than this
/// is reached from this height.
constexpr double kMinTakeoffHeight_m = 1.0;

/// The heading in effect at each waypoint (degrees in [0, 360)): its own, else the last one
/// given before it, else the route's initial heading (below).
std::vector<double> headingsInEffect_deg(const SortieRoute& route);
/// The heading at take-off: the first one a waypoint gives if no horizontal motion comes before
/// it, else the bearing of the first horizontal motion out of home (0, north, if there is none).
double initialHeading_deg(const SortieRoute& route);
/// The gimbal pitch in effect at each waypoint: its own, else the last one given, else 0 (level).
std::vector<double> gimbalPitchesInEffect_deg(const SortieRoute& route);

/// Heading (none when the target is straight above or below, within 1 cm horizontally) and
/// gimbal pitch that point a camera at `target_m` from `from_m`.
struct CameraAim {
  std::optional<double> yaw_deg;  ///< heading, degrees clockwise from north; none: straight above or below
  double gimbal_pitch_deg = 0.0;  ///< +90 straight up, -90 straight down
};
/// The heading and gimbal pitch that point a camera at `target_m` from `from_m`.
CameraAim aimAt(const Eigen::Vector3d& from_m, const Eigen::Vector3d& target_m);

/// Compass heading (degrees clockwise from north) <-> ENU yaw (radians counter-clockwise from
/// east, REP 103), both wrapped: heading to [0, 360), yaw to (-pi, pi].
double enuYawFromHeading_rad(double heading_deg);
/// ENU yaw `yaw_rad` as a compass heading, degrees in [0, 360).
double headingFromEnuYaw_deg(double yaw_rad);

}  // namespace ceilplan::mission
