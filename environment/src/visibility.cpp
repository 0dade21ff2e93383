#include "ceilplan/environment/visibility.hpp"

#include "ceilplan/core/parallel_for.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <limits>

namespace ceilplan::environment {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

// A voxel walk (Amanatides & Woo): the voxel it is in, and for each axis the parameter t along the
// segment at which it crosses its next voxel face, computed from the face itself (not summed step
// by step), so that a walk that skips ahead finds the same values as one that steps there.
struct Walk {
  const GridFrame* frame;
  Eigen::Vector3d from_m, delta_m, inverse_delta;
  Index3 voxel, last, step;
  double t_next[3];
  int remaining = 0;
  std::size_t at = 0;  // linear index of `voxel` when both ends lie in the grid
  std::ptrdiff_t stride[3];

  // t at face `face` (the lower face of voxel `face`) of `axis`.
  double faceT(int axis, int face) const { return (frame->faceOf(axis, face) - from_m[axis]) * inverse_delta[axis]; }

  // The next crossing along `axis`, none once its end index is reached.
  void aim(int axis) {
    if (voxel[axis] == last[axis]) {
      step[axis] = 0;
      t_next[axis] = kNever;
    } else {
      t_next[axis] = faceT(axis, voxel[axis] + (step[axis] > 0 ? 1 : 0));
    }
  }

  // Moves `count` voxels along `axis`, in its direction.
  void advance(int axis, int count) {
    voxel[axis] += step[axis] * count;
    at += step[axis] * stride[axis] * count;
    remaining -= count;
    aim(axis);
  }

  // The walk takes crossings in the order of their t, ties to the lower axis. Inside an all-free
  // block it takes at once every crossing before the one that leaves the block; returns false
  // when the walk ends in the block (the steps it could take are then taken).
  bool crossFreeBlock() {
    const Index3& size = frame->size();
    double exit_t = kNever;
    int exit_axis = 0;
    Index3 bound;  // the farthest voxel of the block, or the end, along each axis
    for (int axis = 0; axis < 3; ++axis) {
      if (step[axis] == 0) continue;
      const int block_lo = (voxel[axis] >> FreeBlocks::kShift) << FreeBlocks::kShift;
      const int block_hi = std::min(block_lo + (1 << FreeBlocks::kShift) - 1, size[axis] - 1);
      bound[axis] = step[axis] > 0 ? block_hi : block_lo;
      if ((last[axis] - bound[axis]) * step[axis] <= 0) {  // this axis ends in the block
        bound[axis] = last[axis];
        continue;
      }
      const double t = faceT(axis, step[axis] > 0 ? block_hi + 1 : block_lo);
      if (t < exit_t) {
        exit_t = t;
        exit_axis = axis;
      }
    }
    for (int axis = 0; axis < 3; ++axis) {
      if (step[axis] == 0) continue;
      const int s = step[axis];
      const auto before = [&](int face) {
        const double t = faceT(axis, face);
        return t < exit_t || (t == exit_t && axis < exit_axis);
      };
      // The voxel it is in at exit_t (from the point there), then the face tests make it exact.
      int target = exit_t == kNever ? bound[axis] : frame->indexOf(axis, from_m[axis] + exit_t * delta_m[axis]);
      target = s > 0 ? std::clamp(target, voxel[axis], bound[axis]) : std::clamp(target, bound[axis], voxel[axis]);
      while (target != voxel[axis] && !before(s > 0 ? target : target + 1)) target -= s;
      while (target != bound[axis] && before(s > 0 ? target + 1 : target)) target += s;
      advance(axis, (target - voxel[axis]) * s);
    }
    return exit_t != kNever;
  }
};

bool walkSight(const VoxelGrid& grid, const FreeBlocks* blocks, const Eigen::Vector3d& from_m,
               const Eigen::Vector3d& to_m) {
  const GridFrame& frame = grid.frame();
  if (!from_m.allFinite() || !to_m.allFinite()) return false;
  Walk walk;
  walk.frame = &frame;
  walk.from_m = from_m;
  walk.delta_m = to_m - from_m;
  const Eigen::Vector3d& delta = walk.delta_m;
  for (int axis = 0; axis < 3; ++axis) {
    walk.voxel[axis] = frame.indexOf(axis, from_m[axis]);
    walk.last[axis] = frame.indexOf(axis, to_m[axis]);
    walk.remaining += std::abs(walk.last[axis] - walk.voxel[axis]);
    walk.step[axis] = walk.last[axis] > walk.voxel[axis] ? 1 : (walk.last[axis] < walk.voxel[axis] ? -1 : 0);
    walk.inverse_delta[axis] = 1.0 / delta[axis];
    if (walk.step[axis] == 0 || delta[axis] == 0.0) {
      walk.step[axis] = 0;
      walk.t_next[axis] = kNever;
      continue;
    }
    walk.aim(axis);
  }
  if (grid.at(walk.voxel[0], walk.voxel[1], walk.voxel[2]) != CellState::Free) return false;
  // Exactly one index changes per step, so the walk reaches `last` after `remaining` steps. With
  // both ends inside the grid every voxel between them is inside too (each index moves
  // monotonically from the first end's to the last's): the walk then steps the linear index by
  // each axis's stride and reads the cells without bounds checks (coverage casts millions of
  // these sights).
  const bool inside = frame.inside(walk.last[0], walk.last[1], walk.last[2]);
  const Index3& size = frame.size();
  walk.stride[0] = 1;
  walk.stride[1] = size[0];
  walk.stride[2] = static_cast<std::ptrdiff_t>(size[0]) * size[1];
  walk.at = inside ? frame.linear(walk.voxel[0], walk.voxel[1], walk.voxel[2]) : 0;
  const bool skips = blocks != nullptr && inside;
  while (walk.remaining > 0) {
    if (skips && blocks->allFree(walk.voxel[0], walk.voxel[1], walk.voxel[2]) && !walk.crossFreeBlock())
      return walk.remaining == 0;
    int axis = 0;
    for (int other = 1; other < 3; ++other)
      if (walk.t_next[other] < walk.t_next[axis]) axis = other;
    if (walk.step[axis] == 0) return false;  // rounding left no crossing to take: treat as blocked
    walk.advance(axis, 1);
    if ((inside ? grid.atLinear(walk.at) : grid.at(walk.voxel[0], walk.voxel[1], walk.voxel[2])) != CellState::Free)
      return false;
  }
  return true;
}

}  // namespace

FreeBlocks::FreeBlocks(const VoxelGrid& grid, int workers) {
  const GridFrame& frame = grid.frame();
  const Index3& size = frame.size();
  constexpr int kSide = 1 << kShift;
  for (int axis = 0; axis < 3; ++axis) blocks_[axis] = (size[axis] + kSide - 1) >> kShift;
  free_.assign(static_cast<std::size_t>(blocks_[0]) * blocks_[1] * blocks_[2], 1);
  // One layer of blocks per task: each reads its voxels in memory order and owns its bytes.
  parallelFor(static_cast<std::size_t>(blocks_[2]), workers, [&](std::size_t layer) {
    const int k_end = std::min(static_cast<int>((layer + 1) << kShift), size[2]);
    std::uint8_t* row = free_.data() + layer * blocks_[0] * blocks_[1];
    for (int k = static_cast<int>(layer << kShift); k < k_end; ++k)
      for (int j = 0; j < size[1]; ++j) {
        const std::size_t first = frame.linear(0, j, k);
        std::uint8_t* blocks = row + static_cast<std::size_t>(j >> kShift) * blocks_[0];
        for (int i = 0; i < size[0]; ++i)
          if (grid.atLinear(first + i) != CellState::Free) blocks[i >> kShift] = 0;
      }
  });
}

bool lineOfSight(const VoxelGrid& grid, const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) {
  return walkSight(grid, nullptr, from_m, to_m);
}

bool lineOfSight(const VoxelGrid& grid, const FreeBlocks& blocks, const Eigen::Vector3d& from_m,
                 const Eigen::Vector3d& to_m) {
  return walkSight(grid, &blocks, from_m, to_m);
}

}  // namespace ceilplan::environment
