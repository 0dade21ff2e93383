#include "ceilplan/environment/distance_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ceilplan::environment {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// One pass of the separable transform along a line of n voxels: `cost[q]` is the squared
// distance already known from voxel q to its nearest blocked voxel (infinity if none);
// returns in `best[p]` the q minimising (p - q)^2 + cost[q], or -1.
class LowerEnvelope {
 public:
  void run(int n, const std::vector<double>& cost, std::vector<int>& best) {
    sites_.resize(n);
    bounds_.resize(n + 1);
    int k = -1;
    for (int q = 0; q < n; ++q) {
      if (cost[q] == kInfinity) continue;
      double s = -kInfinity;
      while (k >= 0) {
        const int v = sites_[k];
        s = ((cost[q] + double(q) * q) - (cost[v] + double(v) * v)) / (2.0 * (q - v));
        if (s > bounds_[k]) break;
        --k;
      }
      ++k;
      sites_[k] = q;
      bounds_[k] = k == 0 ? -kInfinity : s;
      bounds_[k + 1] = kInfinity;
    }
    if (k < 0) {
      std::fill(best.begin(), best.begin() + n, -1);
      return;
    }
    int j = 0;
    for (int p = 0; p < n; ++p) {
      while (bounds_[j + 1] < p) ++j;
      best[p] = sites_[j];
    }
  }

 private:
  std::vector<int> sites_;
  std::vector<double> bounds_;
};

}  // namespace

DistanceField::DistanceField(const VoxelGrid& grid, bool unknown_is_blocked)
    : frame_(grid.frame()), unknown_is_blocked_(unknown_is_blocked), nearest_(frame_.voxelCount(), -1) {
  const Index3 size = frame_.size();
  for (std::size_t voxel = 0; voxel < nearest_.size(); ++voxel) {
    const CellState state = grid.atLinear(voxel);
    if (state == CellState::Occupied || (unknown_is_blocked && state == CellState::Unknown))
      nearest_[voxel] = static_cast<std::int32_t>(voxel);
  }

  const auto squaredDistance = [&](const Index3& from, std::int32_t to) {
    const Index3 target = frame_.unlinear(to);
    const double di = from[0] - target[0], dj = from[1] - target[1], dk = from[2] - target[2];
    return di * di + dj * dj + dk * dk;
  };
  const int longest = std::max({size[0], size[1], size[2]});
  std::vector<double> cost(longest);
  std::vector<int> best(longest);
  std::vector<std::int32_t> line(longest);
  LowerEnvelope envelope;
  // Along each axis in turn: the nearest blocked voxel seen so far, refined by the voxels of the line.
  for (int axis = 0; axis < 3; ++axis) {
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    const int n = size[axis];
    Index3 voxel{};
    for (voxel[a2] = 0; voxel[a2] < size[a2]; ++voxel[a2])
      for (voxel[a1] = 0; voxel[a1] < size[a1]; ++voxel[a1]) {
        for (voxel[axis] = 0; voxel[axis] < n; ++voxel[axis]) {
          const std::int32_t feature = nearest_[frame_.linear(voxel[0], voxel[1], voxel[2])];
          line[voxel[axis]] = feature;
          cost[voxel[axis]] = feature < 0 ? kInfinity : squaredDistance(voxel, feature) ;
        }
        envelope.run(n, cost, best);
        for (voxel[axis] = 0; voxel[axis] < n; ++voxel[axis])
          nearest_[frame_.linear(voxel[0], voxel[1], voxel[2])] = best[voxel[axis]] < 0 ? -1 : line[best[voxel[axis]]];
      }
  }
}

double DistanceField::boxDistance_m(const Eigen::Vector3d& point_m, std::int32_t voxel) const {
  const Index3 index = frame_.unlinear(voxel);
  double squared = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = frame_.faceOf(axis, index[axis]);
    const double hi = frame_.faceOf(axis, index[axis] + 1);
    const double outside = std::max({lo - point_m[axis], 0.0, point_m[axis] - hi});
    squared += outside * outside;
  }
  return std::sqrt(squared);
}

double DistanceField::boundaryDistance_m(const Eigen::Vector3d& point_m) const {
  if (!unknown_is_blocked_) return kInfinity;
  const Eigen::AlignedBox3d box = frame_.bounds();
  const double inside = std::min((point_m - box.min()).minCoeff(), (box.max() - point_m).minCoeff());
  return std::max(inside, 0.0);
}

double DistanceField::distance_m(const Eigen::Vector3d& point_m) const {
  const double boundary = boundaryDistance_m(point_m);
  if (boundary == 0.0) return 0.0;
  Index3 centre;
  for (int axis = 0; axis < 3; ++axis)
    centre[axis] = std::clamp(frame_.indexOf(axis, point_m[axis]), 0, frame_.size()[axis] - 1);
  double best = boundary;
  for (int dk = -1; dk <= 1; ++dk)
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int i = centre[0] + di, j = centre[1] + dj, k = centre[2] + dk;
        if (!frame_.inside(i, j, k)) continue;
        const std::int32_t feature = nearest_[frame_.linear(i, j, k)];
        if (feature >= 0) best = std::min(best, boxDistance_m(point_m, feature));
      }
  return best;
}

double DistanceField::lowerBound_m(const Eigen::Vector3d& point_m) const {
  const double boundary = boundaryDistance_m(point_m);
  const int i = frame_.indexOf(0, point_m.x()), j = frame_.indexOf(1, point_m.y()), k = frame_.indexOf(2, point_m.z());
  if (!frame_.inside(i, j, k)) return 0.0;
  const std::int32_t feature = nearest_[frame_.linear(i, j, k)];
  if (feature < 0) return boundary;
  // The nearest blocked box to any point of this voxel is at least the centre-to-centre
  // distance minus both half diagonals.
  const double centre_distance = (centreOf(feature) - centreOf(static_cast<std::int32_t>(frame_.linear(i, j, k)))).norm();
  const double half_diagonal = 0.5 * std::sqrt(3.0) * frame_.resolution_m();
  return std::min(boundary, std::max(0.0, centre_distance - 2.0 * half_diagonal));
}

Eigen::Vector3d DistanceField::centreOf(std::int32_t voxel) const {
  const Index3 index = frame_.unlinear(voxel);
  return Eigen::Vector3d(frame_.centreOf(0, index[0]), frame_.centreOf(1, index[1]), frame_.centreOf(2, index[2]));
}

}  // namespace ceilplan::environment
