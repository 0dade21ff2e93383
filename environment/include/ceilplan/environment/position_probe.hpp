#pragma once
/// @file
/// Everything the planner and the energy model see at one body position (`ceilplan probe`,
/// `ceilplan.Environment.probe`): the gaps above and below each rotor, the clearance, whether
/// the state is valid and whether that relies on the unknown-space policy.

#include "ceilplan/environment/environment.hpp"

#include <Eigen/Core>

#include <optional>

namespace ceilplan::environment {

/// What `ceilplan probe` reports at one body position: gaps, clearance and validity.
struct PositionProbe {
  Eigen::Vector3d body_m;              ///< the body centre probed
  SurfaceGaps ceiling;                 ///< the rotors against the surface above
  SurfaceGaps ground;                  ///< the rotors against the surface below
  double clearance_m;                  ///< body centre to the nearest blocking voxel
  std::optional<Violation> violation;  ///< empty: a valid state
  bool assumes_free;                   ///< the vehicle overlaps unknown space the policy assumed free
  bool point_assumed_free;             ///< the body centre itself lies in such space
};

/// Throws ceilplan::InputError for a body position outside the map.
PositionProbe probePosition(const Environment& environment, const Eigen::Vector3d& body_m);

}  // namespace ceilplan::environment
