#include "ceilplan/environment/distance_field.hpp"

#include "ceilplan/core/parallel_for.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ceilplan::environment {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Lines across the grid's rows are transformed this many at a time, gathered into a tile, so
// every cache line read serves all of them instead of one voxel (16 x 4 bytes = one line).
constexpr int kTileWidth = 16;

constexpr std::int64_t kNoFeature = -1;

// One pass of the separable transform along a line of n voxels: `cost[q]` is the squared
// distance already known from voxel q to its nearest blocked voxel (kNoFeature if none);
// returns in `best[p]` the q minimising (p - q)^2 + cost[q], or -1. The parabolas' crossings
// are compared by cross-multiplying, in integers: no division, and exact.
class LowerEnvelope {
 public:
  void run(int n, const std::vector<std::int64_t>& cost, std::vector<int>& best) {
    sites_.resize(n);
    height_.resize(n);
    int k = -1;
    for (int q = 0; q < n; ++q) {
      if (cost[q] == kNoFeature) continue;
      const std::int64_t g = cost[q] + std::int64_t{q} * q;  // the parabola's height at 0, shifted
      // Drop the last site while the new parabola overtakes it no later than it overtook the one before.
      while (k >= 1) {
        const std::int64_t u = sites_[k - 1], v = sites_[k];
        if ((g - height_[k]) * (v - u) > (height_[k] - height_[k - 1]) * (q - v)) break;
        --k;
      }
      ++k;
      sites_[k] = q;
      height_[k] = g;
    }
    if (k < 0) {
      std::fill(best.begin(), best.begin() + n, -1);
      return;
    }
    int j = 0;
    for (int p = 0; p < n; ++p) {
      // Move on while the next site's parabola is lower at p: they cross before p.
      while (j < k && height_[j + 1] - height_[j] < 2 * std::int64_t{p} * (sites_[j + 1] - sites_[j])) ++j;
      best[p] = sites_[j];
    }
  }

 private:
  std::vector<int> sites_;
  std::vector<std::int64_t> height_;
};

// Per thread: a line's features and costs, the envelope and a tile of kTileWidth lines.
struct LineScratch {
  explicit LineScratch(int longest)
      : cost(longest),
        best(longest),
        line(longest),
        tile(std::size_t(longest) * kTileWidth),
        horizontal_tile(std::size_t(longest) * kTileWidth) {}
  std::vector<std::int64_t> cost;
  std::vector<int> best;
  std::vector<std::int32_t> line;
  std::vector<std::int32_t> tile;
  std::vector<std::uint16_t> horizontal_tile;
  LowerEnvelope envelope;
};

}  // namespace

DistanceField::DistanceField(const VoxelGrid& grid, bool unknown_is_blocked)
    : DistanceField(ColumnIndex(grid), unknown_is_blocked) {}

DistanceField::DistanceField(const ColumnIndex& columns, bool unknown_is_blocked, int workers,
                             const std::function<void(double)>& progress)
    : frame_(columns.frame()), unknown_is_blocked_(unknown_is_blocked) {
  const int nx = frame_.size()[0], ny = frame_.size()[1], nz = frame_.size()[2];
  const std::size_t layer = static_cast<std::size_t>(nx) * ny;
  nearest_.resize(frame_.voxelCount());
  horizontal_.resize(frame_.voxelCount());
  const int longest = std::max({nx, ny, nz});
  const auto stage = [&](double from, double to) {
    return [&progress, from, to](double f) {
      if (progress) progress(from + (to - from) * f);
    };
  };

  // Along x, from the column runs: per band of rows, a cursor per column walks its runs as the
  // layers go up, so each row's blocked voxels come in memory order.
  const std::size_t row_bands = std::min<std::size_t>(ny, std::size_t(std::max(1, workers)) * 16);
  parallelFor(
      row_bands, workers,
      [&](std::size_t band) {
        const int j0 = static_cast<int>(band * ny / row_bands), j1 = static_cast<int>((band + 1) * ny / row_bands);
        const std::size_t c0 = static_cast<std::size_t>(j0) * nx, c1 = static_cast<std::size_t>(j1) * nx;
        std::vector<const ColumnIndex::Run*> cursor(c1 - c0);
        for (std::size_t c = c0; c < c1; ++c) cursor[c - c0] = columns.runs().data() + columns.offsets()[c];
        std::vector<char> blocked(nx);
        for (int k = 0; k < nz; ++k)
          for (int j = j0; j < j1; ++j) {
            bool any = false;
            for (int i = 0; i < nx; ++i) {
              const ColumnIndex::Run*& run = cursor[static_cast<std::size_t>(j) * nx + i - c0];
              while (run->hi <= k) ++run;  // the last run is unbounded: never runs off the end
              const bool blocks = run->lo <= k && (run->state == CellState::Occupied || unknown_is_blocked);
              blocked[i] = blocks;
              any = any || blocks;
            }
            std::int32_t* row = nearest_.data() + (static_cast<std::size_t>(k) * ny + j) * nx;
            const std::int32_t base = static_cast<std::int32_t>((static_cast<std::size_t>(k) * ny + j) * nx);
            if (!any) {
              std::fill(row, row + nx, -1);
              continue;
            }
            int last = -1;
            for (int i = 0; i < nx; ++i) {
              if (blocked[i]) last = i;
              row[i] = last;  // nearest blocked at or before i, -1 if none
            }
            int next = -1;
            for (int i = nx - 1; i >= 0; --i) {
              if (blocked[i]) next = i;
              if (next >= 0 && (row[i] < 0 || next - i < i - row[i])) row[i] = next;
              row[i] = row[i] < 0 ? -1 : base + row[i];
            }
          }
      },
      stage(0.0, 0.2));

  // Along y, layer by layer: the features lie in the same row, so their x is the index minus
  // the row's start.
  parallelFor(
      static_cast<std::size_t>(nz), workers,
      [&](std::size_t k) {
        LineScratch s(longest);
        const std::size_t layer_base = k * layer;
        for (int x0 = 0; x0 < nx; x0 += kTileWidth) {
          const int width = std::min(kTileWidth, nx - x0);
          for (int y = 0; y < ny; ++y)
            std::copy_n(nearest_.data() + layer_base + static_cast<std::size_t>(y) * nx + x0, width,
                        s.tile.data() + static_cast<std::size_t>(y) * kTileWidth);
          for (int w = 0; w < width; ++w) {
            const int x = x0 + w;
            bool any = false;
            for (int y = 0; y < ny; ++y) {
              const std::int32_t feature = s.tile[static_cast<std::size_t>(y) * kTileWidth + w];
              s.line[y] = feature;
              if (feature < 0) {
                s.cost[y] = kNoFeature;
                continue;
              }
              any = true;
              const std::int64_t dx =
                  x - (feature - static_cast<std::int64_t>(layer_base + static_cast<std::size_t>(y) * nx));
              s.cost[y] = dx * dx;
            }
            if (!any) continue;
            s.envelope.run(ny, s.cost, s.best);
            for (int y = 0; y < ny; ++y) s.tile[static_cast<std::size_t>(y) * kTileWidth + w] = s.line[s.best[y]];
          }
          for (int y = 0; y < ny; ++y)
            std::copy_n(s.tile.data() + static_cast<std::size_t>(y) * kTileWidth, width,
                        nearest_.data() + layer_base + static_cast<std::size_t>(y) * nx + x0);
        }
      },
      stage(0.2, 0.55));

  // Along z, row by row: the features lie in the same layer; their (x, y) give both the cost
  // and the horizontal distance the footprint masks need.
  parallelFor(
      static_cast<std::size_t>(ny), workers,
      [&](std::size_t j) {
        LineScratch s(longest);
        const double inverse_nx = 1.0 / nx;
        for (int x0 = 0; x0 < nx; x0 += kTileWidth) {
          const int width = std::min(kTileWidth, nx - x0);
          for (int z = 0; z < nz; ++z)
            std::copy_n(nearest_.data() + z * layer + j * nx + x0, width,
                        s.tile.data() + static_cast<std::size_t>(z) * kTileWidth);
          for (int w = 0; w < width; ++w) {
            const int x = x0 + w;
            bool any = false;
            for (int z = 0; z < nz; ++z) {
              const std::int32_t feature = s.tile[static_cast<std::size_t>(z) * kTileWidth + w];
              s.line[z] = feature;
              std::uint16_t& horizontal = s.horizontal_tile[static_cast<std::size_t>(z) * kTileWidth + w];
              if (feature < 0) {
                s.cost[z] = kNoFeature;
                horizontal = kHorizontalCap;
                continue;
              }
              any = true;
              // The feature's row within its layer, by a floating-point quotient corrected to exact.
              const long within = feature - static_cast<long>(z * layer);
              long fy = static_cast<long>(within * inverse_nx);
              if (fy * nx > within) --fy;
              if ((fy + 1) * nx <= within) ++fy;
              const long dx = x - (within - fy * nx), dy = static_cast<long>(j) - fy;
              const long squared = dx * dx + dy * dy;
              s.cost[z] = squared;
              horizontal = static_cast<std::uint16_t>(std::min<long>(squared, kHorizontalCap));
            }
            if (!any) continue;
            s.envelope.run(nz, s.cost, s.best);
            for (int z = 0; z < nz; ++z) s.tile[static_cast<std::size_t>(z) * kTileWidth + w] = s.line[s.best[z]];
          }
          for (int z = 0; z < nz; ++z) {
            std::copy_n(s.tile.data() + static_cast<std::size_t>(z) * kTileWidth, width,
                        nearest_.data() + z * layer + j * nx + x0);
            std::copy_n(s.horizontal_tile.data() + static_cast<std::size_t>(z) * kTileWidth, width,
                        horizontal_.data() + z * layer + j * nx + x0);
          }
        }
      },
      stage(0.55, 1.0));
}

double DistanceField::boxSquared_m2(const Eigen::Vector3d& point_m, std::int32_t voxel) const {
  const Index3 index = frame_.unlinear(voxel);
  double squared = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = frame_.faceOf(axis, index[axis]);
    const double hi = frame_.faceOf(axis, index[axis] + 1);
    const double outside = std::max({lo - point_m[axis], 0.0, point_m[axis] - hi});
    squared += outside * outside;
  }
  return squared;
}

double DistanceField::boundaryDistance_m(const Eigen::Vector3d& point_m) const {
  if (!unknown_is_blocked_) return kInfinity;
  double inside = kInfinity;  // to the nearest face of the grid's extent (frame_.bounds(), without building it)
  for (int axis = 0; axis < 3; ++axis)
    inside = std::min(
        {inside, point_m[axis] - frame_.faceOf(axis, 0), frame_.faceOf(axis, frame_.size()[axis]) - point_m[axis]});
  return std::max(inside, 0.0);
}

double DistanceField::distance_m(const Eigen::Vector3d& point_m) const {
  const double boundary = boundaryDistance_m(point_m);
  if (boundary == 0.0) return 0.0;
  const Index3& size = frame_.size();
  Index3 low, high;
  for (int axis = 0; axis < 3; ++axis) {
    const int centre = std::clamp(frame_.indexOf(axis, point_m[axis]), 0, size[axis] - 1);
    low[axis] = std::max(centre - 1, 0);
    high[axis] = std::min(centre + 1, size[axis] - 1);
  }
  // Neighbouring voxels mostly share their nearest blocked voxel: each distinct one is measured
  // once, by its squared distance (the square root of the least is the least square root, to the
  // bit: the square root is monotone and correctly rounded).
  std::array<std::int32_t, 27> features;
  int distinct = 0;
  for (int k = low[2]; k <= high[2]; ++k)
    for (int j = low[1]; j <= high[1]; ++j) {
      const std::size_t row = frame_.linear(0, j, k);
      for (int i = low[0]; i <= high[0]; ++i) {
        const std::int32_t feature = nearest_[row + i];
        if (feature >= 0 &&
            std::find(features.begin(), features.begin() + distinct, feature) == features.begin() + distinct)
          features[distinct++] = feature;
      }
    }
  double best_squared = kInfinity;
  for (int f = 0; f < distinct; ++f) best_squared = std::min(best_squared, boxSquared_m2(point_m, features[f]));
  return std::min(boundary, std::sqrt(best_squared));
}

double DistanceField::lowerBound_m(const Eigen::Vector3d& point_m) const {
  const double boundary = boundaryDistance_m(point_m);
  const int i = frame_.indexOf(0, point_m.x()), j = frame_.indexOf(1, point_m.y()), k = frame_.indexOf(2, point_m.z());
  if (!frame_.inside(i, j, k)) return 0.0;
  const std::int32_t feature = nearest_[frame_.linear(i, j, k)];
  if (feature < 0) return boundary;
  // The nearest blocked box to any point of this voxel is at least the centre-to-centre
  // distance minus both half diagonals.
  const Eigen::Vector3d centre(frame_.centreOf(0, i), frame_.centreOf(1, j), frame_.centreOf(2, k));
  const double centre_distance = (centreOf(feature) - centre).norm();
  const double half_diagonal = 0.5 * std::sqrt(3.0) * frame_.resolution_m();
  return std::min(boundary, std::max(0.0, centre_distance - 2.0 * half_diagonal));
}

Eigen::Vector3d DistanceField::centreOf(std::int32_t voxel) const {
  const Index3 index = frame_.unlinear(voxel);
  return Eigen::Vector3d(frame_.centreOf(0, index[0]), frame_.centreOf(1, index[1]), frame_.centreOf(2, index[2]));
}

}  // namespace ceilplan::environment
