// Ceiling and ground gaps on analytic rooms whose surfaces lie on voxel faces: the answers
// are exact (to 1e-6 m), measured from the rotor plane (0.03 m above the body centre).

#include "analytic_maps.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/environment/environment.hpp"
#include "ceilplan/environment/vertical_ceiling_test.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

namespace ceilplan::environment {
namespace {

using testing::analyticMap;
using testing::quad;
using testing::room;
using testing::singleRotor;
constexpr double kExact = 1e-6;
constexpr double kNone = std::numeric_limits<double>::infinity();

// A ceiling rising 0.1 m every 0.2 m of x, from 2.5 m at x = 0.
OccupancyMap slopedCeiling() {
  return room([](double x, double) { return 2.5 + 0.1 * std::floor(x / 0.2); });
}

// Unknown space from 2.5 m up, but where x > 0.3 an occupied ceiling from 2.4 m.
OccupancyMap unknownCeiling() {
  return analyticMap({-2, -2, 0}, {2, 2, 4}, 0.1, [](const Eigen::Vector3d& c) {
    if (c.z() < 0.2 || (c.x() > 0.3 && c.z() > 2.4)) return CellState::Occupied;
    return c.z() < 2.5 ? CellState::Free : CellState::Unknown;
  });
}

// The default unknown-space policy, and unknown space as a surface.
std::array<EnvironmentOptions, 2> bothPolicies() {
  EnvironmentOptions cautious;
  cautious.unknown_is_surface = true;
  return {EnvironmentOptions{}, cautious};
}

TEST(CeilingGap, FlatCeilingOnAVoxelFaceGivesTheExactGapForEveryRotor) {
  const OccupancyMap map = room([](double, double) { return 3.0; });
  const Environment environment(map, quad());
  const SurfaceGaps gaps = environment.ceiling({0.0, 0.0, 2.7});
  ASSERT_EQ(gaps.rotors.size(), 4u);
  for (const RotorGap& rotor : gaps.rotors) {
    EXPECT_NEAR(rotor.nearest_gap_m, 3.0 - 2.73, kExact);
    EXPECT_NEAR(rotor.mean_gap_m, 3.0 - 2.73, kExact);
    EXPECT_NEAR(rotor.coverage, 1.0, 1e-12);
  }
  EXPECT_NEAR(gaps.nearest_gap_m, 0.27, kExact);
  EXPECT_NEAR(gaps.mean_gap_m, 0.27, kExact);
  EXPECT_NEAR(gaps.coverage, 1.0, 1e-12);
  EXPECT_NEAR(environment.ceilingGapAt({0.05, -0.35, 1.234}), 3.0 - 1.234, kExact);
}

TEST(CeilingGap, CoverageCountsOnlySurfacesWithinReachButTheGapIsReportedAnyway) {
  const OccupancyMap map = room([](double, double) { return 3.0; });
  const Environment environment(map, quad());  // reach 4 R = 0.508 m
  const SurfaceGaps gaps = environment.ceiling({0.0, 0.0, 2.0});
  EXPECT_NEAR(gaps.nearest_gap_m, 0.97, kExact);
  EXPECT_EQ(gaps.coverage, 0.0);
  EXPECT_EQ(gaps.mean_gap_m, kNone);
}

TEST(CeilingGap, SlopedCeilingTakesTheLowestVoxelFaceOverEachDisc) {
  // The underside rises 0.1 m every 0.2 m in x: a 1:2 slope, stepped at the voxel size.
  const OccupancyMap map = room([](double x, double) { return 2.5 + 0.1 * std::floor(x / 0.2); });
  const Environment environment(map, quad());
  EXPECT_NEAR(environment.ceilingGapAt({0.55, 0.0, 2.3}), 2.5 + 0.2 - 2.3, kExact);
  EXPECT_NEAR(environment.ceilingGapAt({-0.05, 0.0, 2.3}), 2.4 - 2.3, kExact);
  // Rotors sit at x = +-0.159; a disc of radius 0.127 spans x in [0.032, 0.286] or [-0.286, -0.032].
  const SurfaceGaps gaps = environment.ceiling({0.0, 0.0, 2.1});
  for (const RotorGap& rotor : gaps.rotors) {
    const bool front = rotor.nearest_gap_m > 0.3;
    // Front discs: underside 2.5 (x < 0.2) and 2.6 (x >= 0.2); rear discs: 2.4 (x >= -0.2) and 2.3.
    EXPECT_NEAR(rotor.nearest_gap_m, front ? 2.5 - 2.13 : 2.3 - 2.13, kExact);
    EXPECT_NEAR(rotor.coverage, 1.0, 1e-12);
    const double high = front ? 2.6 - 2.13 : 2.4 - 2.13;
    EXPECT_GT(rotor.mean_gap_m, rotor.nearest_gap_m);
    EXPECT_LT(rotor.mean_gap_m, high);
  }
  EXPECT_NEAR(gaps.nearest_gap_m, 0.17, kExact);
}

TEST(CeilingGap, SteppedCeilingSplitsTheRotorsBetweenTwoHeights) {
  const OccupancyMap map = room([](double x, double) { return x < 0 ? 3.0 : 2.6; });
  const Environment environment(map, quad());
  const SurfaceGaps gaps = environment.ceiling({0.0, 0.0, 2.2});
  int low = 0, high = 0;
  for (const RotorGap& rotor : gaps.rotors) {
    if (rotor.coverage > 0.5) {
      ++low;
      EXPECT_NEAR(rotor.nearest_gap_m, 2.6 - 2.23, kExact);
      EXPECT_NEAR(rotor.coverage, 1.0, 1e-12);
    } else {
      ++high;
      EXPECT_NEAR(rotor.nearest_gap_m, 3.0 - 2.23, kExact);  // beyond the 0.508 m reach
      EXPECT_EQ(rotor.coverage, 0.0);
    }
  }
  EXPECT_EQ(low, 2);
  EXPECT_EQ(high, 2);
  EXPECT_NEAR(gaps.coverage, 0.5, 1e-12);
  EXPECT_NEAR(gaps.mean_gap_m, 0.37, kExact);
}

TEST(CeilingGap, BeamEdgeThroughTheRotorAxisCoversExactlyHalfTheDisc) {
  // A beam (underside 2.5 m) over x >= 0 only; elsewhere free up to the room's 3.5 m ceiling.
  const OccupancyMap map = room([](double x, double) { return x >= 0 ? 2.5 : 3.5; });
  const Environment environment(map, singleRotor());
  const SurfaceGaps gaps = environment.ceiling({0.0, 0.05, 2.2});
  EXPECT_NEAR(gaps.rotors[0].coverage, 0.5, 1e-12);
  EXPECT_NEAR(gaps.rotors[0].nearest_gap_m, 0.27, kExact);
  EXPECT_NEAR(gaps.rotors[0].mean_gap_m, 0.27, kExact);
  // Moving the disc a quarter radius under the beam: the exact circular-segment share.
  const double d = 0.127 / 4;
  const double r = 0.127;
  const double outside = (r * r * std::acos(d / r) - d * std::sqrt(r * r - d * d)) / (M_PI * r * r);
  EXPECT_NEAR(environment.ceiling({d, 0.05, 2.2}).rotors[0].coverage, 1.0 - outside, 1e-12);
}

TEST(CeilingGap, UnknownAboveMeansNoCeilingUnlessTheOptionSaysOtherwise) {
  // Free up to 2.5 m, unknown above: a scan that never saw the ceiling.
  const OccupancyMap map = analyticMap({-2, -2, 0}, {2, 2, 4}, 0.1, [](const Eigen::Vector3d& c) {
    if (c.z() < 0.2) return CellState::Occupied;
    return c.z() < 2.5 ? CellState::Free : CellState::Unknown;
  });
  const Environment by_default(map, quad());
  const SurfaceGaps gaps = by_default.ceiling({0.0, 0.0, 2.2});
  EXPECT_EQ(gaps.nearest_gap_m, kNone);
  EXPECT_EQ(gaps.coverage, 0.0);
  EXPECT_EQ(by_default.ceilingGapAt({0.0, 0.0, 2.2}), kNone);

  EnvironmentOptions options;
  options.unknown_is_surface = true;
  const Environment cautious(map, quad(), options);
  EXPECT_NEAR(cautious.ceiling({0.0, 0.0, 2.2}).nearest_gap_m, 0.27, kExact);
  EXPECT_NEAR(cautious.ceiling({0.0, 0.0, 2.2}).coverage, 1.0, 1e-12);
}

// The candidate views ask only whether the nearest gap reaches a bound: the same answer as the
// full query at every height under sloped, stepped and unknown ceilings, bounds on a gap included.
TEST(CeilingGap, AtLeastAnswersAsTheNearestGapOfTheFullQuery) {
  const OccupancyMap sloped = slopedCeiling();
  const OccupancyMap stepped = room([](double x, double y) { return x < 0 ? 3.0 : (y < 0.1 ? 2.6 : 2.8); });
  const OccupancyMap unknown = unknownCeiling();
  int below = 0, above = 0;
  for (const OccupancyMap* map : {&sloped, &stepped, &unknown})
    for (const EnvironmentOptions& options : bothPolicies()) {
      const Environment environment(*map, quad(), options);
      for (double x = -0.6; x <= 0.6; x += 0.037)
        for (double z = 1.8; z <= 2.4; z += 0.043) {
          const Eigen::Vector3d body(x, 0.05 - 0.3 * x, z);
          const double nearest_m = environment.ceiling(body).nearest_gap_m;
          for (const double bound_m : {0.03, 0.1, 0.25, nearest_m, std::nextafter(nearest_m, kNone)}) {
            const bool at_least = environment.ceilingGapAtLeast(body, bound_m);
            EXPECT_EQ(at_least, nearest_m >= bound_m) << body.transpose() << " bound " << bound_m;
            (at_least ? above : below) += 1;
          }
        }
    }
  EXPECT_GT(below, 100);
  EXPECT_GT(above, 100);
}

// The viewpoint search's bisection asks ceilingGapAtLeast at many heights on one vertical line:
// VerticalCeilingTest answers from the columns under the discs found once, the same as the full
// query at every height, bounds on a gap included, also past a thin slab (a column's span at the
// line's first height no longer holds there), off the line and outside the map.
TEST(CeilingGap, TheVerticalTestAnswersAsCeilingGapAtLeastOnTheWholeLine) {
  const OccupancyMap sloped = slopedCeiling();
  const OccupancyMap slab = analyticMap({-2, -2, 0}, {2, 2, 4}, 0.1, [](const Eigen::Vector3d& c) {
    const bool thin_slab = c.x() < 0.2 && c.z() > 2.0 && c.z() < 2.1;
    return c.z() < 0.2 || c.z() > 3.0 || thin_slab ? CellState::Occupied : CellState::Free;
  });
  const OccupancyMap unknown = unknownCeiling();
  int below = 0, above = 0;
  for (const OccupancyMap* map : {&sloped, &slab, &unknown})
    for (const EnvironmentOptions& options : bothPolicies()) {
      const Environment environment(*map, quad(), options);
      for (double x = -0.6; x <= 0.6; x += 0.083) {
        const Eigen::Vector3d line(x, 0.05 - 0.3 * x, 1.6);
        const VerticalCeilingTest vertical(environment, line);
        for (double z = 1.6; z <= 3.2; z += 0.0137) {
          const Eigen::Vector3d body(line.x(), line.y(), z);
          const double nearest_m = environment.ceiling(body).nearest_gap_m;
          for (const double bound_m : {0.03, 0.1, 0.25, nearest_m, std::nextafter(nearest_m, kNone)}) {
            const bool at_least = environment.ceilingGapAtLeast(body, bound_m);
            ASSERT_EQ(vertical.gapAtLeast(body, bound_m), at_least) << body.transpose() << " bound " << bound_m;
            ASSERT_EQ(vertical.gapAtLeast(body + Eigen::Vector3d(0.031, 0, 0), bound_m),
                      environment.ceilingGapAtLeast(body + Eigen::Vector3d(0.031, 0, 0), bound_m));
            (at_least ? above : below) += 1;
          }
        }
      }
      EXPECT_THROW(VerticalCeilingTest(environment, {2.5, 0, 1}), ceilplan::InputError);
      const VerticalCeilingTest inside(environment, {0, 0, 1});
      EXPECT_THROW(inside.gapAtLeast({0, 0, 4.5}, 0.03), ceilplan::InputError);
    }
  EXPECT_GT(below, 1000);
  EXPECT_GT(above, 1000);
}

TEST(GroundGap, MeasuresDownToTheFloorsUpperFace) {
  const OccupancyMap map = room([](double, double) { return 3.0; });
  const Environment environment(map, quad());
  const SurfaceGaps gaps = environment.ground({0.3, -0.2, 0.5});
  EXPECT_NEAR(gaps.nearest_gap_m, 0.53 - 0.2, kExact);
  EXPECT_NEAR(gaps.coverage, 1.0, 1e-12);  // 0.33 m is within 5 R = 0.635 m
  EXPECT_NEAR(environment.groundGapAt({0.3, -0.2, 1.7}), 1.5, kExact);
}

TEST(Queries, APointOutsideTheMapIsAnErrorThatSaysSo) {
  const OccupancyMap map = room([](double, double) { return 3.0; });
  const Environment environment(map, quad());
  EXPECT_FALSE(environment.contains({2.5, 0, 1}));
  EXPECT_THROW(environment.ceilingGapAt({2.5, 0, 1}), ceilplan::InputError);
  EXPECT_THROW(environment.ceilingGapAtLeast({2.5, 0, 1}, 0.03), ceilplan::InputError);
  EXPECT_THROW(environment.ground({0, 0, -1}), ceilplan::InputError);
  EXPECT_THROW(environment.clearance_m({0, 9, 1}), ceilplan::InputError);
  try {
    environment.ceiling({0, 0, 10});
    FAIL() << "expected an error";
  } catch (const ceilplan::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("outside the map"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(environment.isStateValid({2.5, 0, 1}));
}

TEST(Queries, ARotorDiscReachingPastTheMapEdgeSeesNoCeilingThere) {
  const OccupancyMap map = room([](double, double) { return 3.0; });
  const Environment environment(map, singleRotor());
  // Disc centred on the map's x = 2 m edge: half of it lies outside, where all is unknown.
  EXPECT_NEAR(environment.ceiling({1.9999999, 0.05, 2.7}).rotors[0].coverage, 0.5, 1e-6);
}

}  // namespace
}  // namespace ceilplan::environment
