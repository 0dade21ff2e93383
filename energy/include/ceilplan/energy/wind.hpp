#pragma once
/// @file
/// The wind a mission flies in (mission key `wind:`) and what it does to a motion: the energy
/// model's forward-flight power sees the airspeed, the ground velocity less the wind's
/// (docs/models.md, "Wind").

#include <Eigen/Core>

namespace ceilplan::energy {

/// A steady horizontal wind, the same over the whole map. Calm by default, which leaves every
/// figure as it is in still air.
struct Wind {
  static constexpr double kMaxSpeed_m_s = 40.0;  ///< the strongest wind accepted (a storm; no multirotor flies in it)

  double speed_m_s = 0.0;  ///< mean horizontal speed, >= 0
  /// Meteorological: where the wind blows FROM, clockwise from north in [0, 360). North is the map's
  /// +y (docs/missions.md, "wind").
  double from_deg = 0.0;
  /// Gusts above the mean, >= 0: not flown by the mean-wind plan; for the reserve's confidence.
  double gust_m_s = 0.0;
  /// [open] Share of the wind's speed taken away under overhead structure (where a planner's speed
  /// rule sees a ceiling close above), in [0, 1]; 0 by default (docs/models.md, "Calibration
  /// parameters at a glance").
  double sheltered_fraction = 0.0;

  /// Throws ceilplan::InputError naming the first bad field.
  void validate() const;
  /// No wind at all: every figure is the still-air one.
  bool calm() const { return speed_m_s == 0.0; }
  /// The air's horizontal velocity in the map frame (x east, y north), m/s: it blows towards
  /// from_deg + 180.
  Eigen::Vector2d airVelocityM_s() const;
};

/// The wind as a moving vehicle feels it, along and across its horizontal track.
struct RelativeWind {
  double headwind_m_s = 0.0;   ///< along the track, positive against the motion
  double crosswind_m_s = 0.0;  ///< across the track, >= 0
};

/// The wind `air_velocity_m_s` relative to a horizontal track along the unit vector
/// `track_direction`; a zero direction (hovering, or a vertical motion) takes the whole wind as
/// headwind, so hovering in wind is forward flight at the wind's speed.
RelativeWind relativeWind(const Eigen::Vector2d& air_velocity_m_s, const Eigen::Vector2d& track_direction);

}  // namespace ceilplan::energy
