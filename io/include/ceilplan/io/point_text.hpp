#pragma once
// A point written as text, as command lines give one: "x,y,z" in metres.

#include <Eigen/Core>

#include <string>

namespace ceilplan::io {

// The farthest coordinate any input may give (a point on the command line, a mission's home and
// targets, a coverage region's corners): farther than any map, so a slip of the exponent is refused.
inline constexpr double kMaxPointCoordinate_m = 1e6;

// "1.5,-2,3e-1" -> (1.5, -2, 0.3). Throws ceilplan::InputError quoting the text (printable) for
// anything but three finite numbers joined by commas, each within +-kMaxPointCoordinate_m.
Eigen::Vector3d parsePoint(const std::string& text);

}  // namespace ceilplan::io
