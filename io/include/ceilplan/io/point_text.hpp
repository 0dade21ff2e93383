#pragma once
/// @file
/// A point written as text, as command lines give one: "x,y,z" in metres.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>

namespace ceilplan::io {

/// The farthest coordinate any input may give (a point on the command line, a mission's home and
/// targets, a coverage region's corners): farther than any map, so a slip of the exponent is refused.
inline constexpr double kMaxPointCoordinate_m = 1e6;

/// "1.5,-2,3e-1" -> (1.5, -2, 0.3). Throws ceilplan::InputError quoting the text (printable) for
/// anything but three finite numbers joined by commas, each within +-kMaxPointCoordinate_m.
Eigen::Vector3d parsePoint(const std::string& text);

/// "xmin,ymin,zmin,xmax,ymax,zmax" -> the box between the two corners (an import's crop).
/// Throws ceilplan::InputError quoting the text for anything but six finite numbers joined by
/// commas, each within +-kMaxPointCoordinate_m, with each minimum below its maximum.
Eigen::AlignedBox3d parseBox(const std::string& text);

}  // namespace ceilplan::io
