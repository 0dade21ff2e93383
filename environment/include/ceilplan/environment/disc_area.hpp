#pragma once
/// @file
/// Exact area of a disc's overlap with an axis-aligned rectangle: how much of a rotor disc lies
/// under one map column. Exact (closed form), so a beam edge through a rotor's centre gives
/// coverage 0.5 to rounding error.

#include <Eigen/Core>

namespace ceilplan::environment {

/// Area of a disc (centre, radius) that lies inside the axis-aligned rectangle [min_m, max_m], m^2.
double discRectangleOverlap_m2(const Eigen::Vector2d& centre_m, double radius_m, const Eigen::Vector2d& min_m,
                               const Eigen::Vector2d& max_m);

}  // namespace ceilplan::environment
