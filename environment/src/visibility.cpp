#include "ceilplan/environment/visibility.hpp"

#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <limits>

namespace ceilplan::environment {

bool lineOfSight(const VoxelGrid& grid, const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) {
  const GridFrame& frame = grid.frame();
  if (!from_m.allFinite() || !to_m.allFinite()) return false;
  const Eigen::Vector3d delta = to_m - from_m;
  Index3 voxel, last, step;
  double t_next[3], t_delta[3];
  constexpr double kNever = std::numeric_limits<double>::infinity();
  int remaining = 0;
  for (int axis = 0; axis < 3; ++axis) {
    voxel[axis] = frame.indexOf(axis, from_m[axis]);
    last[axis] = frame.indexOf(axis, to_m[axis]);
    remaining += std::abs(last[axis] - voxel[axis]);
    step[axis] = last[axis] > voxel[axis] ? 1 : (last[axis] < voxel[axis] ? -1 : 0);
    if (step[axis] == 0 || delta[axis] == 0.0) {
      step[axis] = 0;
      t_next[axis] = kNever;
      t_delta[axis] = kNever;
      continue;
    }
    const double boundary_m = frame.faceOf(axis, step[axis] > 0 ? voxel[axis] + 1 : voxel[axis]);
    t_next[axis] = (boundary_m - from_m[axis]) / delta[axis];
    t_delta[axis] = frame.resolution_m() / std::abs(delta[axis]);
  }
  if (grid.at(voxel[0], voxel[1], voxel[2]) != CellState::Free) return false;
  // Exactly one index changes per step, so the walk reaches `last` after `remaining` steps. With
  // both ends inside the grid every voxel between them is inside too (each index moves
  // monotonically from the first end's to the last's): the walk then steps the linear index by
  // each axis's stride and reads the cells without bounds checks (coverage casts millions of
  // these sights).
  const bool inside = frame.inside(last[0], last[1], last[2]);
  const Index3& size = frame.size();
  const std::ptrdiff_t stride[3] = {1, size[0], static_cast<std::ptrdiff_t>(size[0]) * size[1]};
  std::size_t at = inside ? frame.linear(voxel[0], voxel[1], voxel[2]) : 0;
  for (; remaining > 0; --remaining) {
    int axis = 0;
    for (int other = 1; other < 3; ++other)
      if (t_next[other] < t_next[axis]) axis = other;
    if (step[axis] == 0) return false;  // rounding left no crossing to take: treat as blocked
    voxel[axis] += step[axis];
    at += step[axis] * stride[axis];
    t_next[axis] += t_delta[axis];
    // An axis whose end index is reached takes no further step.
    if (voxel[axis] == last[axis]) {
      step[axis] = 0;
      t_next[axis] = kNever;
    }
    if ((inside ? grid.atLinear(at) : grid.at(voxel[0], voxel[1], voxel[2])) != CellState::Free) return false;
  }
  return true;
}

}  // namespace ceilplan::environment
