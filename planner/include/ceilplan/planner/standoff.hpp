#pragma once
/// @file
/// Free mode's standoff: how far the airframe stays from every structure, measured from its
/// bounding sphere with the environment's clearance (which, under the occupied policy, counts
/// unknown space as structure too). A conventional planner keeps a standoff where it can; a path
/// that had to narrow says where (docs/planner.md, "Free mode").

#include "ceilplan/environment/environment.hpp"

#include <Eigen/Core>

#include <vector>

namespace ceilplan::planner {

/// Within a millimetre of a standoff counts as keeping it (paths, viewpoints, tours).
inline constexpr double kStandoffTolerance_m = 1e-3;

/// The radius of the sphere around the body centre that holds the airframe's collision
/// cylinder (without margins): 0.38 m for the default quad.
double airframeRadius_m(const environment::VehicleGeometry& vehicle);

/// The gap between the airframe's bounding sphere and the nearest structure (negative when the
/// sphere reaches into it, as close under a ceiling). Throws ceilplan::InputError outside the map.
double standoffAt(const environment::Environment& environment, const Eigen::Vector3d& body_m);

/// A stretch of a path where the standoff was not kept.
struct NarrowedSpan {
  double from_m = 0.0, to_m = 0.0;  ///< along the path, from its start
  /** @var from_m
   *  Where the span starts, along the path from its start. */
  double min_standoff_m = 0.0;                            ///< the closest the airframe came
  Eigen::Vector3d narrowest_m = Eigen::Vector3d::Zero();  ///< where
};

/// How far a free-mode path kept the conventional standoff from every structure.
struct StandoffReport {
  double standoff_m = 0.0;          ///< the standoff asked for
  double length_m = 0.0;            ///< of the path
  double narrowed_m = 0.0;          ///< total length of the spans
  double min_standoff_m = 0.0;      ///< over the whole path
  std::vector<NarrowedSpan> spans;  ///< where the standoff was not kept, in order
};

/// Where along a path (samples every half voxel) the airframe came closer than `standoff_m` to a
/// structure. Throws ceilplan::InputError for fewer than 2 waypoints or one outside the map.
StandoffReport standoffReport(const environment::Environment& environment,
                              const std::vector<Eigen::Vector3d>& waypoints_m, double standoff_m);

}  // namespace ceilplan::planner
