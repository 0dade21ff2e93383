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

/// Which blocks of a grid hold free voxels only (a block at the grid's far faces counts its
/// voxels inside the grid), at two sizes: 16 x 16 x 16 voxels for open air and 4 x 4 x 4 near
/// structure. A line of sight crosses such a block without reading its voxels. One byte per
/// block: 1/64 of the grid's and 1/4096.
class FreeBlocks {
 public:
  static constexpr int kFineShift = 2;    ///< fine blocks are 2^2 voxels a side
  static constexpr int kCoarseShift = 4;  ///< coarse blocks 2^4

  /// One pass over `grid`, on `workers` threads. Valid while the grid is not changed.
  explicit FreeBlocks(const VoxelGrid& grid, int workers = 1);

  /// The log2 of the side of the largest all-free block holding voxel (i, j, k), which must lie
  /// in the grid: kCoarseShift, kFineShift, or 0 where its fine block holds a voxel that is not free.
  int freeShift(int i, int j, int k) const {
    return coarse_.allFree(i, j, k) ? kCoarseShift : (fine_.allFree(i, j, k) ? kFineShift : 0);
  }

  /// Memory held, bytes.
  std::size_t memoryBytes() const { return fine_.free.capacity() + coarse_.free.capacity(); }

 private:
  struct Level {
    int shift = 0;
    Index3 blocks{};  // blocks along x, y and z
    std::vector<std::uint8_t> free;

    Level(int shift, const Index3& voxels);
    std::size_t index(int i, int j, int k) const {
      return (static_cast<std::size_t>(k >> shift) * blocks[1] + (j >> shift)) * blocks[0] + (i >> shift);
    }
    bool allFree(int i, int j, int k) const { return free[index(i, j, k)] != 0; }
  };
  Level fine_, coarse_;
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
