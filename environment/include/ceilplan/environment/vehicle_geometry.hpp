#pragma once
/// @file
/// The vehicle's shape as the environment queries need it: where the rotor discs are (for
/// ceiling and ground gaps) and the collision cylinder (for validity).

#include "ceilplan/core/error.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace ceilplan::environment {

/// Rotor arrangement: X (rotors on the diagonals, the founding paper's frame) or Plus (on the axes).
enum class RotorLayout {
  X,    ///< rotors on the diagonals (the founding paper's frame)
  Plus  ///< rotors on the body axes
};

/// All lengths in metres, relative to the body centre (x forward, y left, z up).
struct VehicleGeometry {
  std::string name;                                ///< for messages and reports
  std::vector<Eigen::Vector2d> rotor_positions_m;  ///< rotor axes in the body's horizontal plane
  double rotor_radius_m = 0.0;                     ///< radius of each rotor disc
  double rotor_plane_height_m = 0.0;               ///< rotor plane above the body centre
  double top_height_m = 0.0;                       ///< highest airframe point above the body centre
  double bottom_height_m = 0.0;                    ///< lowest airframe point (negative: below the centre)
  double collision_radius_m = 0.0;                 ///< horizontal radius of the collision cylinder
  double margin_m = 0.0;                           ///< kept free sideways and below
  double top_margin_m = 0.0;                       ///< kept free above

  /// Throws ceilplan::InputError naming the first bad field.
  void validate() const;

  /// The collision cylinder inflated by the margins, relative to the body centre.
  double inflatedRadius_m() const { return collision_radius_m + margin_m; }
  /// Bottom of the inflated collision cylinder, relative to the body centre.
  double inflatedBottom_m() const { return bottom_height_m - margin_m; }
  /// Top of the inflated collision cylinder, relative to the body centre.
  double inflatedTop_m() const { return top_height_m + top_margin_m; }
};

/// Rotor axes of a symmetric multirotor: `count` arms of `arm_length_m`; X puts the first
/// rotor at 180/count degrees from the nose, Plus on the nose.
std::vector<Eigen::Vector2d> rotorPositions(RotorLayout layout, int count, double arm_length_m);

}  // namespace ceilplan::environment
