#pragma once
// The lattice both lattice searches use (LatticePlanner, LatticeRoadmap): voxel centres every
// `stride` voxels of the map's grid (the spacing in metres rounded to whole voxels),
// 26-connected, and how a free point joins it.

#include "ceilplan/environment/voxel_grid.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace ceilplan::planner::detail {

// The stride in voxels closest to `spacing_m`, at least one.
inline int strideVoxels(const environment::GridFrame& frame, double spacing_m) {
  return std::max(1, static_cast<int>(std::lround(spacing_m / frame.resolution_m())));
}

class LatticeGrid {
 public:
  LatticeGrid(const environment::GridFrame& frame, double spacing_m)
      : frame_(frame), stride_(detail::strideVoxels(frame, spacing_m)), spacing_m_(stride_ * frame.resolution_m()) {
    for (int axis = 0; axis < 3; ++axis) size_[axis] = (frame.size()[axis] + stride_ - 1) / stride_;
  }

  std::size_t nodeCount() const { return static_cast<std::size_t>(size_[0]) * size_[1] * size_[2]; }
  double spacing_m() const { return spacing_m_; }
  int strideVoxels() const { return stride_; }
  int size(int axis) const { return size_[axis]; }
  const environment::GridFrame& frame() const { return frame_; }

  std::size_t id(int a, int b, int c) const { return (static_cast<std::size_t>(c) * size_[1] + b) * size_[0] + a; }
  std::array<int, 3> indices(std::size_t id) const {
    return {static_cast<int>(id % size_[0]), static_cast<int>((id / size_[0]) % size_[1]),
            static_cast<int>(id / (static_cast<std::size_t>(size_[0]) * size_[1]))};
  }
  bool inside(int a, int b, int c) const {
    return a >= 0 && b >= 0 && c >= 0 && a < size_[0] && b < size_[1] && c < size_[2];
  }
  Eigen::Vector3d position(int a, int b, int c) const {
    return {frame_.centreOf(0, a * stride_), frame_.centreOf(1, b * stride_), frame_.centreOf(2, c * stride_)};
  }
  Eigen::Vector3d position(std::size_t id) const {
    const std::array<int, 3> i = indices(id);
    return position(i[0], i[1], i[2]);
  }

  // Lattice nodes within sqrt(3) spacings of a point: the nodes a free point joins by a
  // straight motion (enough that any point inside the lattice's hull has a corner of its cell).
  double joinRadius_m() const { return std::sqrt(3.0) * spacing_m_; }
  template <typename Visit>
  void forEachNodeNear(const Eigen::Vector3d& point_m, Visit&& visit) const {
    forEachNodeWithin(point_m, joinRadius_m(), visit);
  }
  // Lattice nodes within `radius_m` of a point, in id order.
  template <typename Visit>
  void forEachNodeWithin(const Eigen::Vector3d& point_m, double radius_m, Visit&& visit) const {
    int lo[3], hi[3];
    for (int axis = 0; axis < 3; ++axis) {
      const double origin = frame_.centreOf(axis, 0);
      lo[axis] = std::max(0, static_cast<int>(std::floor((point_m[axis] - radius_m - origin) / spacing_m_)));
      hi[axis] =
          std::min(size_[axis] - 1, static_cast<int>(std::ceil((point_m[axis] + radius_m - origin) / spacing_m_)));
    }
    for (int c = lo[2]; c <= hi[2]; ++c)
      for (int b = lo[1]; b <= hi[1]; ++b)
        for (int a = lo[0]; a <= hi[0]; ++a)
          if ((position(a, b, c) - point_m).norm() <= radius_m) visit(id(a, b, c));
  }

 private:
  const environment::GridFrame& frame_;
  int stride_;
  double spacing_m_;
  int size_[3];
};

// The 26 neighbour offsets of a lattice node, and which of them is each one's opposite.
struct LatticeDirections {
  std::array<std::array<int, 3>, 26> offsets{};
  std::array<int, 26> opposite{};
  LatticeDirections() {
    int k = 0;
    for (int dc = -1; dc <= 1; ++dc)
      for (int db = -1; db <= 1; ++db)
        for (int da = -1; da <= 1; ++da)
          if ((da | db | dc) != 0) offsets[k++] = {da, db, dc};
    // Enumerated in lexicographic order, the opposite of offset k is offset 25 - k.
    for (int d = 0; d < 26; ++d) opposite[d] = 25 - d;
  }
};

}  // namespace ceilplan::planner::detail
