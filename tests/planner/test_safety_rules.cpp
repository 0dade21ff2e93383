// SafetyRules: what it accepts, the dense re-check accepts; a minimum rotor gap beyond the
// cylinder's is enforced.

#include "planner_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace ceilplan::testing {
namespace {

double beams(double x, double) { return std::fmod(x + 10.0, 1.5) < 0.3 ? 3.0 : 3.5; }

TEST(SafetyRules, EveryAcceptedMotionPassesTheDenseRecheck) {
  const environment::OccupancyMap map = corridor(beams);
  const environment::Environment environment(map, quad());
  const planner::SafetyRules rules(environment, 0.05);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> x(-0.4, 6.4), y(-2.4, 2.4), z(2.5, 3.45), step(-0.6, 0.6);
  int accepted = 0;
  for (int k = 0; k < 3000; ++k) {
    // Short motions grazing the beams' corners, where a coarse check can clip a voxel.
    const Eigen::Vector3d a(x(random), y(random), z(random));
    const Eigen::Vector3d b = a + Eigen::Vector3d(step(random), step(random), 0.3 * step(random));
    if (!environment.contains(b) || !rules.isMotionValid(a, b)) continue;
    ++accepted;
    EXPECT_FALSE(rules.checkPathDensely({a, b})) << a.transpose() << " -> " << b.transpose();
  }
  EXPECT_GT(accepted, 300);
}

TEST(SafetyRules, SkippingStatesWithinTheValidReachChangesNoAnswer) {
  // Long motions across open space and into the beams: the states skipped far from structure
  // (Environment::validReach_m) never hide a collision, so accepting and rejecting both agree
  // with the dense re-check's exact test of every state.
  const environment::OccupancyMap map = corridor(beams);
  const environment::Environment environment(map, quad());
  const planner::SafetyRules rules(environment, 0.05);
  std::mt19937 random(13);
  std::uniform_real_distribution<double> x(-0.4, 6.4), y(-2.4, 2.4), z(0.3, 3.45);
  int accepted = 0, rejected = 0;
  for (int k = 0; k < 1500; ++k) {
    const Eigen::Vector3d a(x(random), y(random), z(random)), b(x(random), y(random), z(random));
    if (!environment.contains(a) || !environment.contains(b)) continue;
    const bool valid = rules.isMotionValid(a, b);
    EXPECT_EQ(valid, !rules.checkPathDensely({a, b})) << a.transpose() << " -> " << b.transpose();
    ++(valid ? accepted : rejected);
  }
  EXPECT_GT(accepted, 100);
  EXPECT_GT(rejected, 100);
}

TEST(SafetyRules, AMotionIsValidExactlyWhenEveryDenseStateIs) {
  // Near structure the footprint masks clear the states a motion has in one grid column at
  // once (Environment::columnSurelyValid): motions hugging the beams and the ceiling, level,
  // vertical and slanted, as lattice edges and refined paths fly them, are accepted exactly when
  // each of their states, a dense step apart, is valid alone.
  const environment::OccupancyMap map = corridor(beams);
  const environment::Environment environment(map, quad());
  const planner::SafetyRules rules(environment, 0.05);
  const double dense_step_m = environment.denseStep_m();
  const auto everyStateValid = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const long steps = std::max(1L, static_cast<long>(std::ceil((b - a).norm() / dense_step_m)));
    for (long s = 0; s <= steps; ++s)
      if (!rules.isStateValid(a + (b - a) * (static_cast<double>(s) / steps))) return false;
    return true;
  };
  std::mt19937 random(17);
  std::uniform_real_distribution<double> x(-0.4, 6.4), y(-2.4, 2.4), z(2.6, 3.45), step(-0.7, 0.7);
  int accepted = 0, rejected = 0;
  for (int k = 0; k < 3000; ++k) {
    const Eigen::Vector3d a(x(random), y(random), z(random));
    Eigen::Vector3d offset(step(random), step(random), 0.5 * step(random));
    if (k % 3 == 0) offset.head<2>().setZero();  // vertical, one column
    if (k % 3 == 1) offset.z() = 0.0;            // level, under the beams
    const Eigen::Vector3d b = a + offset;
    if (!environment.contains(b)) continue;
    const bool valid = rules.isMotionValid(a, b);
    EXPECT_EQ(valid, everyStateValid(a, b)) << a.transpose() << " -> " << b.transpose();
    ++(valid ? accepted : rejected);
  }
  EXPECT_GT(accepted, 300);
  EXPECT_GT(rejected, 300);
}

TEST(SafetyRules, AColumnTheMasksClearHoldsOnlyValidStates) {
  const environment::OccupancyMap map = corridor(beams);
  const environment::Environment environment(map, quad());
  const environment::GridFrame& frame = environment.grid().frame();
  std::mt19937 random(19);
  std::uniform_real_distribution<double> x(-0.4, 6.4), y(-2.4, 2.4), z(0.3, 3.45), unit(0.0, 1.0);
  int cleared = 0, undecided = 0;
  for (int k = 0; k < 2000; ++k) {
    const double low_z = z(random), high_z = std::min(3.45, low_z + 0.4 * unit(random));
    const int i = frame.indexOf(0, x(random)), j = frame.indexOf(1, y(random));
    if (!environment.columnSurelyValid(i, j, low_z, high_z)) {
      ++undecided;
      continue;
    }
    ++cleared;
    for (int n = 0; n < 20; ++n) {  // anywhere in the column, at any height between
      const Eigen::Vector3d state(frame.faceOf(0, i) + frame.resolution_m() * unit(random),
                                  frame.faceOf(1, j) + frame.resolution_m() * unit(random),
                                  low_z + (high_z - low_z) * unit(random));
      if (environment.contains(state)) {
        EXPECT_TRUE(environment.isStateValid(state)) << state.transpose();
      }
    }
  }
  EXPECT_GT(cleared, 200);
  EXPECT_GT(undecided, 200);
}

TEST(SafetyRules, AMinimumGapLargerThanTheCylinderAllowsIsEnforced) {
  const environment::OccupancyMap map = corridor(flatCeiling);
  const environment::Environment environment(map, quad());
  const planner::SafetyRules loose(environment, 0.05), strict(environment, 0.15);
  const Eigen::Vector3d hugging(3.0, 0.0, bodyHeightUnder(3.5));  // rotor plane 7 cm under the ceiling
  EXPECT_TRUE(loose.isStateValid(hugging));
  EXPECT_FALSE(strict.isStateValid(hugging));
  EXPECT_FALSE(strict.isMotionValid({3.0, 0.0, 2.5}, hugging));
  EXPECT_TRUE(strict.checkPathDensely({{3.0, 0.0, 2.5}, hugging}));
}

}  // namespace
}  // namespace ceilplan::testing
