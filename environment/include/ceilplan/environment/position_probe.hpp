#pragma once
/// @file
/// Everything the planner and the energy model see at one body position (`ceilplan probe`,
/// `ceilplan.Environment.probe`): the gaps above and below each rotor, the clearance, whether
/// the state is valid and whether that relies on the unknown-space policy.

#include "ceilplan/environment/environment.hpp"

#include <Eigen/Core>

#include <optional>

namespace ceilplan::environment {

struct PositionProbe {
  Eigen::Vector3d body_m;
  SurfaceGaps ceiling;
  SurfaceGaps ground;
  double clearance_m;
  std::optional<Violation> violation;  ///< empty: a valid state
  bool assumes_free;                   ///< the vehicle overlaps unknown space the policy assumed free
  bool point_assumed_free;             ///< the body centre itself lies in such space
};

/// Throws ceilplan::InputError for a body position outside the map.
PositionProbe probePosition(const Environment& environment, const Eigen::Vector3d& body_m);

}  // namespace ceilplan::environment
