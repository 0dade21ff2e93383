#pragma once
/// @file
/// Lines of sight through a voxel grid: a camera sees a point when every voxel between them is
/// known free. Occupied and unknown voxels both block the view (girders and piers occlude, and
/// the map cannot vouch for what it has not seen).

#include "ceilplan/environment/voxel_grid.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ceilplan::environment {

/// Which blocks of 8 x 8 x 8 voxels of a grid hold free voxels only (a block at the grid's far
/// faces counts its voxels inside the grid): a line of sight crosses such a block without reading
/// its voxels. One byte per block, 1/512 of the grid's.
class FreeBlocks {
 public:
  /// Blocks are 2^kShift voxels a side.
  static constexpr int kShift = 3;

  /// One pass over `grid`, on `workers` threads. Valid while the grid is not changed.
  explicit FreeBlocks(const VoxelGrid& grid, int workers = 1);

  /// Whether the block holding voxel (i, j, k), which must lie in the grid, is all free.
  bool allFree(int i, int j, int k) const {
    return free_[(static_cast<std::size_t>(k >> kShift) * blocks_[1] + (j >> kShift)) * blocks_[0] + (i >> kShift)] !=
           0;
  }

  /// Memory held, bytes.
  std::size_t memoryBytes() const { return free_.capacity(); }

 private:
  Index3 blocks_;  // blocks along x, y and z
  std::vector<std::uint8_t> free_;
};

/// Whether every voxel the segment from `from_m` to `to_m` passes through, both end voxels
/// included, is free. Walks the grid voxel by voxel (Amanatides & Woo, "A fast voxel traversal
/// algorithm for ray tracing", Eurographics 1987): about as many steps as voxels crossed.
/// Outside the grid every voxel is unknown, so a segment leaving the grid is blocked.
bool lineOfSight(const VoxelGrid& grid, const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m);

/// The same answer, faster through open air: `blocks` (built from `grid`) lets the walk cross an
/// all-free block in one step, taking every crossing the voxel walk would take inside it in the
/// same order, so the walk leaves the block exactly where the voxel walk does.
bool lineOfSight(const VoxelGrid& grid, const FreeBlocks& blocks, const Eigen::Vector3d& from_m,
                 const Eigen::Vector3d& to_m);

}  // namespace ceilplan::environment
