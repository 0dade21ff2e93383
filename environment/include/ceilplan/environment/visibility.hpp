#pragma once
/// @file
/// Lines of sight through a voxel grid: a camera sees a point when every voxel between them is
/// known free. Occupied and unknown voxels both block the view (girders and piers occlude, and
/// the map cannot vouch for what it has not seen).

#include "ceilplan/environment/voxel_grid.hpp"

#include <Eigen/Core>

namespace ceilplan::environment {

/// Whether every voxel the segment from `from_m` to `to_m` passes through, both end voxels
/// included, is free. Walks the grid voxel by voxel (Amanatides & Woo, "A fast voxel traversal
/// algorithm for ray tracing", Eurographics 1987): about as many steps as voxels crossed.
/// Outside the grid every voxel is unknown, so a segment leaving the grid is blocked.
bool lineOfSight(const VoxelGrid& grid, const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m);

}  // namespace ceilplan::environment
