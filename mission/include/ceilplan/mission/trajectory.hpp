#pragma once
/// @file
/// A sortie's route turned into time-stamped setpoints at a fixed rate, for a companion computer
/// to stream to an autopilot in offboard mode (docs/flying.md). Each setpoint has position,
/// velocity, acceleration, yaw and yaw rate (the fields of PX4's TrajectorySetpoint and MAVLink's
/// SET_POSITION_TARGET_LOCAL_NED), the gimbal pitch and a camera trigger flag, in the map frame
/// (ENU); io/trajectory_file.hpp writes them in ENU or NED.
///
/// How the time scaling works (docs/flying.md, "Time scaling"):
/// - Each straight segment of the route is a one-dimensional jerk-limited motion (piecewise
///   constant jerk: S-curves between speeds, cruising in between) that starts and ends at rest
///   in its own coordinate. The position is the sum of the segments' displacements.
/// - At a corner the vehicle either stops (positions stay exactly on the route's polyline) or
///   passes it without stopping: the next segment's speed-up overlaps the previous one's
///   slow-down, mirror images of each other, so the velocity turns from one direction to the
///   other at a constant sum of speeds. That blend cuts inside the corner by at most
///   `corner_tolerance_m`, and is only used where `path_is_safe` accepts its positions.
/// - A run between two stops is stretched to a whole number of samples, so every stop, hold and
///   photo falls on a sample. Stretching time by k >= 1 divides speed by k, acceleration by k^2
///   and jerk by k^3: limits stay met.
/// - Yaw and gimbal pitch move smoothly (smoothstep in time) from one waypoint's value to the
///   next while the vehicle flies; where the yaw rate limit needs longer, the vehicle turns in
///   place on arrival.

#include "ceilplan/mission/sortie_route.hpp"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace ceilplan::mission {

/// The vehicle's motion limits. Speed along each segment is the route's speed, capped so the
/// vertical rate stays within climb and descent. Defaults: PX4 v1.14's auto-mode parameters
/// MPC_ACC_HOR (3 m/s^2), MPC_JERK_AUTO (4 m/s^3) and MPC_YAWRAUTO_MAX (45 deg/s); climb and
/// descent as the mission file's speeds.
struct TrajectoryLimits {
  double climb_m_s = 1.0;              ///< vertical speed limit, climbing
  double descent_m_s = 0.8;            ///< vertical speed limit, descending
  double max_acceleration_m_s2 = 3.0;  ///< norm of the acceleration vector
  double max_jerk_m_s3 = 4.0;          ///< norm of the jerk vector
  double max_yaw_rate_deg_s = 45.0;    ///< fastest yaw rate

  /// Throws ceilplan::InputError naming the field that is not positive and finite.
  void validate() const;
};

/// How routes are time-scaled into setpoints (mission key `trajectory:`, docs/flying.md).
struct TrajectoryOptions {
  double rate_hz = 20.0;  ///< setpoints per second
  /// How far a corner flown without stopping may stray from the route's polyline (m). 0 stops
  /// at every corner.
  double corner_tolerance_m = 0.05;
  /// Corners turning more than this stop (degrees, at most 90).
  double stop_turn_deg = 60.0;
  /// The dense re-check of the positions a blended corner flies (a polyline, in time order):
  /// true if safe. Without it every corner stops, so positions never leave the polyline.
  std::function<bool(const std::vector<Eigen::Vector3d>&)> path_is_safe;

  /// Throws ceilplan::InputError naming the bad field.
  void validate() const;
};

/// One setpoint of a trajectory, as PX4's TrajectorySetpoint takes it (docs/flying.md).
struct TrajectorySetpoint {
  double t_s = 0.0;                                      ///< time from the sortie's take-off
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  ///< map frame, x east, y north, z up
  /// velocity, map frame
  Eigen::Vector3d velocity_m_s = Eigen::Vector3d::Zero();
  /// acceleration, map frame
  Eigen::Vector3d acceleration_m_s2 = Eigen::Vector3d::Zero();
  double yaw_rad = 0.0;           ///< ENU: counter-clockwise from east, in (-pi, pi]
  double yaw_rate_rad_s = 0.0;    ///< ENU: positive counter-clockwise
  double gimbal_pitch_deg = 0.0;  ///< +90 straight up, -90 straight down
  bool trigger = false;           ///< take a photo at this setpoint
};

/// One sortie's route time-scaled into setpoints (timeScaleRoute).
struct Trajectory {
  int sortie = 1;                             ///< 1-based
  double rate_hz = 20.0;                      ///< setpoints per second
  TrajectoryLimits limits;                    ///< the limits it was scaled under
  std::vector<TrajectorySetpoint> setpoints;  ///< at t = k / rate_hz from 0, at rest at both ends
  int stops = 0;                              ///< corners and waypoints where the vehicle comes to rest (end included)
  int blended_corners = 0;                    ///< corners passed without stopping
  int photos = 0;                             ///< setpoints with the trigger set
  double length_m = 0.0;                      ///< of the route's polyline
  double max_corner_deviation_m = 0.0;        ///< furthest a blend strays from the polyline

  /// Time of the last setpoint, s.
  double duration_s() const { return setpoints.empty() ? 0.0 : setpoints.back().t_s; }
};

/// Time-scales `route` (validated) under `limits`. Throws ceilplan::InputError for a bad route,
/// limits or options.
Trajectory timeScale(const SortieRoute& route, const TrajectoryLimits& limits, const TrajectoryOptions& options = {});

}  // namespace ceilplan::mission
