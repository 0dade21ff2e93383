#pragma once
// For every voxel of a grid, the nearest blocked voxel (Euclidean, between centres): an exact
// feature transform computed with the separable lower-envelope method (Felzenszwalb &
// Huttenlocher 2012), 4 bytes per voxel. dynamicEDT3D's grid needs about 24 bytes per voxel;
// see docs/environment.md.

#include "ceilplan/environment/voxel_grid.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace ceilplan::environment {

class DistanceField {
 public:
  // Blocked voxels: occupied ones, and unknown ones when `unknown_is_blocked` (then everything
  // outside the grid counts as blocked too).
  DistanceField(const VoxelGrid& grid, bool unknown_is_blocked);

  // Distance from `point_m` to the surface of the nearest blocked voxel, 0 inside one,
  // +infinity when nothing is blocked. Takes the best of the nearest blocked voxels of the 27
  // voxels around the point: exact whenever one of them is the point's nearest (always, in
  // practice); otherwise too large by a fraction of a voxel.
  double distance_m(const Eigen::Vector3d& point_m) const;

  // A lower bound on distance_m, from the voxel holding the point alone; cheap.
  double lowerBound_m(const Eigen::Vector3d& point_m) const;

 private:
  double boxDistance_m(const Eigen::Vector3d& point_m, std::int32_t voxel) const;
  Eigen::Vector3d centreOf(std::int32_t voxel) const;
  double boundaryDistance_m(const Eigen::Vector3d& point_m) const;

  GridFrame frame_;
  bool unknown_is_blocked_;
  std::vector<std::int32_t> nearest_;  // linear index of the nearest blocked voxel, -1 if none
};

}  // namespace ceilplan::environment
