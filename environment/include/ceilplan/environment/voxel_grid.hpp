#pragma once
/// @file
/// A dense grid of voxel states over the box of a map's known voxels, at the map's finest
/// resolution. Voxel (i, j, k) spans [(o + i) r, (o + i + 1) r) on each axis, with o the
/// grid's origin index and r the resolution, so its faces are OctoMap's voxel faces exactly.

#include "ceilplan/core/error.hpp"

#include <octomap/OcTree.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace ceilplan::environment {

/// A voxel's state: Unknown (no data), Free (known free air) or Occupied.
enum class CellState : std::uint8_t {
  Unknown = 0,  ///< no data
  Free = 1,     ///< known free air
  Occupied = 2  ///< occupied
};

/// A voxel's (i, j, k) index in a grid.
using Index3 = std::array<int, 3>;

/// Where the voxels of a grid lie: copied by everything indexed over a grid.
class GridFrame {
 public:
  /// `origin` is the global index (floor(coordinate / resolution)) of voxel 0.
  GridFrame(double resolution_m, const Index3& origin, const Index3& size);

  /// Voxel size, m.
  double resolution_m() const { return resolution_m_; }
  /// Global index of voxel (0, 0, 0).
  const Index3& origin() const { return origin_; }
  /// Voxels along x, y and z.
  const Index3& size() const { return size_; }
  /// Voxels in the grid.
  std::size_t voxelCount() const { return static_cast<std::size_t>(size_[0]) * size_[1] * size_[2]; }

  /// Voxel index along `axis` holding `coordinate_m` (may lie outside [0, size)). Inline: every
  /// gap and validity query asks it for each column it reads.
  int indexOf(int axis, double coordinate_m) const {
    // OctoMap's own rule (coordToKey): floor(coordinate * (1 / resolution)).
    const double global = std::floor(coordinate_m * inverse_resolution_);
    const double clamped = std::clamp(global - origin_[axis], -1e9, 1e9);  // far outside stays outside, no overflow
    return static_cast<int>(clamped);
  }
  /// Coordinate of the lower face of voxel `index` along `axis` (the upper face is index + 1).
  double faceOf(int axis, int index) const { return (origin_[axis] + index) * resolution_m_; }
  /// Coordinate of the centre of voxel `index` along `axis`.
  double centreOf(int axis, int index) const { return (origin_[axis] + index + 0.5) * resolution_m_; }

  /// Whether (i, j, k) lies in the grid.
  bool inside(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < size_[0] && j < size_[1] && k < size_[2];
  }
  /// The linear index of voxel (i, j, k): x fastest, then y, then z.
  std::size_t linear(int i, int j, int k) const { return (static_cast<std::size_t>(k) * size_[1] + j) * size_[0] + i; }
  /// The (i, j, k) index of linear index `voxel`.
  Index3 unlinear(std::size_t voxel) const {
    return {static_cast<int>(voxel % size_[0]), static_cast<int>((voxel / size_[0]) % size_[1]),
            static_cast<int>(voxel / (static_cast<std::size_t>(size_[0]) * size_[1]))};
  }

  /// The grid's extent in metres (voxel faces).
  Eigen::AlignedBox3d bounds() const;
  /// Whether `point_m` lies in the grid's extent.
  bool contains(const Eigen::Vector3d& point_m) const {
    return inside(indexOf(0, point_m.x()), indexOf(1, point_m.y()), indexOf(2, point_m.z()));
  }

 private:
  double resolution_m_;
  double inverse_resolution_;
  Index3 origin_;
  Index3 size_;
};

/// A dense grid of voxel states over a box: what a map is indexed from.
class VoxelGrid {
 public:
  /// Refuses (ceilplan::InputError) grids larger than this: about 5 bytes per voxel once indexed.
  static constexpr std::size_t kMaxVoxels = 400'000'000;

  /// All voxels unknown.
  explicit VoxelGrid(const GridFrame& frame);

  /// Rasterises every known leaf of `tree` over the bounding box of its known leaves, on
  /// `workers` threads.
  static VoxelGrid fromTree(const octomap::OcTree& tree, const std::function<void(double)>& progress = {},
                            int workers = 1);

  /// Where the voxels lie.
  const GridFrame& frame() const { return frame_; }

  /// Outside the grid every voxel is unknown.
  CellState at(int i, int j, int k) const {
    return frame_.inside(i, j, k) ? cells_[frame_.linear(i, j, k)] : CellState::Unknown;
  }
  /// The state of linear voxel `voxel` (no bounds check).
  CellState atLinear(std::size_t voxel) const { return cells_[voxel]; }
  /// Sets voxel (i, j, k), which must lie in the grid.
  void set(int i, int j, int k, CellState state) { cells_[frame_.linear(i, j, k)] = state; }
  /// Sets every voxel whose centre lies in [min, max) on all axes.
  void fillBox(const Eigen::Vector3d& min_m, const Eigen::Vector3d& max_m, CellState state);

  /// Memory held, bytes.
  std::size_t memoryBytes() const { return cells_.capacity() * sizeof(CellState); }

 private:
  GridFrame frame_;
  std::vector<CellState> cells_;
};

/// Builds the smallest OctoMap OcTree holding exactly the grid's known voxels (uniform blocks
/// become single coarse leaves, as OctoMap's pruning would leave them).
std::unique_ptr<octomap::OcTree> toOcTree(const VoxelGrid& grid);

}  // namespace ceilplan::environment
