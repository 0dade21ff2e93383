// The distance field against brute force on random grids.

#include "ceilplan/environment/distance_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace ceilplan::environment {
namespace {

VoxelGrid randomGrid(std::mt19937& random) {
  VoxelGrid grid(GridFrame(0.1, {-5, 3, -2}, {14, 11, 9}));
  std::uniform_real_distribution<double> unit(0, 1);
  for (int k = 0; k < 9; ++k)
    for (int j = 0; j < 11; ++j)
      for (int i = 0; i < 14; ++i) {
        const double u = unit(random);
        grid.set(i, j, k, u < 0.03 ? CellState::Occupied : u < 0.05 ? CellState::Unknown : CellState::Free);
      }
  return grid;
}

double bruteForce(const VoxelGrid& grid, const Eigen::Vector3d& p, bool unknown_is_blocked) {
  const GridFrame& frame = grid.frame();
  double best = std::numeric_limits<double>::infinity();
  if (unknown_is_blocked) {
    const Eigen::AlignedBox3d box = frame.bounds();
    best = std::min((p - box.min()).minCoeff(), (box.max() - p).minCoeff());
  }
  for (int k = 0; k < frame.size()[2]; ++k)
    for (int j = 0; j < frame.size()[1]; ++j)
      for (int i = 0; i < frame.size()[0]; ++i) {
        const CellState state = grid.at(i, j, k);
        if (state == CellState::Free || (state == CellState::Unknown && !unknown_is_blocked)) continue;
        const Eigen::AlignedBox3d voxel(
            Eigen::Vector3d(frame.faceOf(0, i), frame.faceOf(1, j), frame.faceOf(2, k)),
            Eigen::Vector3d(frame.faceOf(0, i + 1), frame.faceOf(1, j + 1), frame.faceOf(2, k + 1)));
        best = std::min(best, voxel.exteriorDistance(p));
      }
  return best;
}

TEST(DistanceField, MatchesBruteForceAndItsLowerBoundNeverExceedsIt) {
  std::mt19937 random(11);
  int exact = 0, total = 0;
  double worst = 0.0;
  for (int trial = 0; trial < 6; ++trial) {
    const VoxelGrid grid = randomGrid(random);
    const bool unknown_is_blocked = trial % 2 == 0;
    const DistanceField field(grid, unknown_is_blocked);
    const Eigen::AlignedBox3d box = grid.frame().bounds();
    std::uniform_real_distribution<double> x(box.min().x(), box.max().x()), y(box.min().y(), box.max().y()),
        z(box.min().z(), box.max().z());
    for (int n = 0; n < 400; ++n) {
      const Eigen::Vector3d p(x(random), y(random), z(random));
      const double expected = bruteForce(grid, p, unknown_is_blocked);
      const double got = field.distance_m(p);
      EXPECT_GE(got, expected - 1e-12);
      EXPECT_LE(field.lowerBound_m(p), expected + 1e-12);
      worst = std::max(worst, got - expected);
      exact += std::abs(got - expected) < 1e-9;
      ++total;
    }
  }
  EXPECT_GE(exact, total * 99 / 100) << "exact in " << exact << " of " << total;
  EXPECT_LT(worst, 0.05) << "worst excess " << worst;  // half a voxel
}

TEST(DistanceField, WithNothingBlockedTheDistanceIsInfinite) {
  VoxelGrid grid(GridFrame(0.1, {0, 0, 0}, {4, 4, 4}));
  grid.fillBox({0, 0, 0}, {1, 1, 1}, CellState::Free);
  const DistanceField field(grid, false);
  EXPECT_EQ(field.distance_m({0.2, 0.2, 0.2}), std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace ceilplan::environment
