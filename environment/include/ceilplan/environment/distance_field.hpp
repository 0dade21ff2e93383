#pragma once
/// @file
/// For every voxel of a grid, the nearest blocked voxel (Euclidean, between centres): an exact
/// feature transform computed with the separable lower-envelope method (Felzenszwalb &
/// Huttenlocher 2012), 4 bytes per voxel, plus the horizontal distance to the nearest blocked
/// voxel of the same layer (2 bytes per voxel), which the footprint masks of every vehicle
/// read. dynamicEDT3D's grid needs about 24 bytes per voxel; see docs/environment.md.

#include "ceilplan/environment/column_index.hpp"
#include "ceilplan/environment/voxel_grid.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <vector>

namespace ceilplan::environment {

/// Distances from any point to the nearest blocked voxel of a grid (the clearance queries).
class DistanceField {
 public:
  /// Horizontal squared distances are stored up to this many voxels squared (255 voxels and a bit).
  static constexpr std::uint32_t kHorizontalCap = 65535;

  /// Blocked voxels: occupied ones, and unknown ones when `unknown_is_blocked` (then everything
  /// outside the grid counts as blocked too).
  DistanceField(const VoxelGrid& grid, bool unknown_is_blocked);
  /// The same from the grid's column runs, on `workers` threads; `progress` gets fractions in [0, 1].
  DistanceField(const ColumnIndex& columns, bool unknown_is_blocked, int workers = 1,
                const std::function<void(double)>& progress = {});

  /// Distance from `point_m` to the surface of the nearest blocked voxel, 0 inside one,
  /// +infinity when nothing is blocked. Takes the best of the nearest blocked voxels of the 27
  /// voxels around the point: exact whenever one of them is the point's nearest (always, in
  /// practice); otherwise too large by a fraction of a voxel.
  double distance_m(const Eigen::Vector3d& point_m) const;

  /// A lower bound on distance_m, from the voxel holding the point alone; cheap.
  double lowerBound_m(const Eigen::Vector3d& point_m) const;

  /// Squared distance, in voxels between column centres, from voxel `voxel` (a linear index of
  /// the grid) to the nearest blocked voxel in its own horizontal layer; kHorizontalCap when
  /// there is none that close. Outside the grid is not counted here.
  std::uint32_t horizontalSquared(std::size_t voxel) const { return horizontal_[voxel]; }

  /// Where the voxels lie.
  const GridFrame& frame() const { return frame_; }
  /// Whether unknown voxels count as blocked.
  bool unknownIsBlocked() const { return unknown_is_blocked_; }
  /// Memory held, bytes.
  std::size_t memoryBytes() const {
    return nearest_.capacity() * sizeof(std::int32_t) + horizontal_.capacity() * sizeof(std::uint16_t);
  }

 private:
  /// Squared distance from `point_m` to the box of voxel `voxel` (a linear index).
  double boxSquared_m2(const Eigen::Vector3d& point_m, std::int32_t voxel) const;
  Eigen::Vector3d centreOf(std::int32_t voxel) const;
  double boundaryDistance_m(const Eigen::Vector3d& point_m) const;

  GridFrame frame_;
  bool unknown_is_blocked_;
  std::vector<std::int32_t> nearest_;      ///< linear index of the nearest blocked voxel, -1 if none
  std::vector<std::uint16_t> horizontal_;  ///< see horizontalSquared
};

}  // namespace ceilplan::environment
