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
  bool crossFreeBlock(int shift) {
    const Index3& size = frame->size();
    double exit_t = kNever;
    int exit_axis = 0;
    Index3 bound;  // the farthest voxel of the block, or the end, along each axis
    for (int axis = 0; axis < 3; ++axis) {
      if (step[axis] == 0) continue;
      const int block_lo = (voxel[axis] >> shift) << shift;
      const int block_hi = std::min(block_lo + (1 << shift) - 1, size[axis] - 1);
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
    if (skips)
      if (const int shift = blocks->freeShift(walk.voxel[0], walk.voxel[1], walk.voxel[2]);
          shift != 0 && !walk.crossFreeBlock(shift))
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

FreeBlocks::Level::Level(int level_shift, const Index3& voxels) : shift(level_shift) {
  for (int axis = 0; axis < 3; ++axis) blocks[axis] = (voxels[axis] + (1 << shift) - 1) >> shift;
  free.assign(static_cast<std::size_t>(blocks[0]) * blocks[1] * blocks[2], 1);
}

FreeBlocks::FreeBlocks(const VoxelGrid& grid, int workers)
    : fine_(kFineShift, grid.frame().size()), coarse_(kCoarseShift, grid.frame().size()) {
  const GridFrame& frame = grid.frame();
  const Index3& size = frame.size();
  // One layer of fine blocks per task: each reads its voxels in memory order and owns its bytes.
  parallelFor(static_cast<std::size_t>(fine_.blocks[2]), workers, [&](std::size_t layer) {
    const int k_begin = static_cast<int>(layer << kFineShift);
    const int k_end = std::min(k_begin + (1 << kFineShift), size[2]);
    for (int k = k_begin; k < k_end; ++k)
      for (int j = 0; j < size[1]; ++j) {
        const std::size_t first = frame.linear(0, j, k);
        std::uint8_t* row = fine_.free.data() + fine_.index(0, j, k);
        for (int i = 0; i < size[0]; ++i)
          if (grid.atLinear(first + i) != CellState::Free) row[i >> kFineShift] = 0;
      }
  });
  // A coarse block is free where each fine block in it is.
  constexpr int kRatio = 1 << (kCoarseShift - kFineShift);
  for (int k = 0; k < fine_.blocks[2]; ++k)
    for (int j = 0; j < fine_.blocks[1]; ++j)
      for (int i = 0; i < fine_.blocks[0]; ++i)
        if (!fine_.free[(static_cast<std::size_t>(k) * fine_.blocks[1] + j) * fine_.blocks[0] + i])
          coarse_.free[(static_cast<std::size_t>(k / kRatio) * coarse_.blocks[1] + j / kRatio) * coarse_.blocks[0] +
                       i / kRatio] = 0;
}

bool lineOfSight(const VoxelGrid& grid, const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) {
  return walkSight(grid, nullptr, from_m, to_m);
}

bool lineOfSight(const VoxelGrid& grid, const FreeBlocks& blocks, const Eigen::Vector3d& from_m,
                 const Eigen::Vector3d& to_m) {
  return walkSight(grid, &blocks, from_m, to_m);
}

}  // namespace ceilplan::environment
