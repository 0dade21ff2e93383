#pragma once
/// @file
/// Boustrophedon passes: the chosen views of a region in lanes, flown one lane after the other in
/// alternating directions, as survey tools fly a lawnmower pattern. Views looking up or down
/// (|pitch| >= 60 deg) run in lanes along the region's heading, stacked across it; views looking
/// sideways run in level lanes along the surface they face, stacked in height.
/// docs/coverage.md, "Passes".

#include "ceilplan/mission/camera.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace ceilplan::mission {

/// A straight run of views flown one after another.
struct ViewPass {
  std::vector<std::uint32_t> views;                      ///< indices into the caller's list, in flying order
  Eigen::Vector3d direction = Eigen::Vector3d::UnitY();  ///< unit, along which the pass flies (first to last)
  double length_m = 0.0;                                 ///< first to last camera position, along the views
};

/// A region's views arranged in passes, with the generic tour it was compared against.
struct PassPlan {
  std::vector<ViewPass> passes;  ///< in flying order; every view in exactly one
  double route_m = 0.0;          ///< closed route through the passes in order (camera positions)
  double generic_route_m = 0.0;  ///< closed route of a generic tour of the same views
  std::string generic_method;    ///< how generic_route_m was found
  bool passes_win = false;       ///< route_m <= generic_route_m: fly the passes
};

/// Orders `poses` (their cameras at `camera_m`) into passes. The views marked in `in_lanes`
/// (all when empty) form the lanes: `lane_width_m` apart from the lowest lane coordinate, each
/// view in the nearest, ordered along the lane, lanes flown in alternating directions. Every
/// other view (a patch of an edge, a strip behind an occluder) is inserted where it lengthens
/// the route least, into the pass of the view before it. `heading_deg` is the region's long axis
/// (regionHeading). The generic tour is mission::heuristicTour (seed 1; 20 restarts up to 200
/// views, local search alone up to 250) and a nearest-neighbour tour beyond.
PassPlan orderIntoPasses(const std::vector<CameraPose>& poses, const std::vector<Eigen::Vector3d>& camera_m,
                         double heading_deg, double lane_width_m, const std::vector<std::uint8_t>& in_lanes = {});

}  // namespace ceilplan::mission
