// State and motion validity: the vehicle is a vertical cylinder (radius 0.36 m, from 0.12 m
// below to 0.06 m above the body centre) kept 0.10 m clear sideways and below, 0.02 m above.

#include "analytic_maps.hpp"

#include "ceilplan/environment/environment.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <random>

namespace ceilplan::environment {
namespace {

using testing::analyticMap;
using testing::quad;

// Floor top at 0.2 m, ceiling underside at 3.0 m, a pillar over x in [1.0, 1.4), y in [-0.2, 0.2).
OccupancyMap pillarRoom(double unknown_beyond_x = 99.0) {
  return analyticMap({-2, -2, 0}, {2, 2, 3.4}, 0.1, [=](const Eigen::Vector3d& c) {
    if (c.x() > unknown_beyond_x) return CellState::Unknown;
    if (c.z() < 0.2 || c.z() > 3.0) return CellState::Occupied;
    if (c.x() > 1.0 && c.x() < 1.4 && std::abs(c.y()) < 0.2) return CellState::Occupied;
    return CellState::Free;
  });
}

constexpr double kTiny = 1e-6;

MapIndexOptions freeUnknown() {
  MapIndexOptions options;
  options.unknown.policy = UnknownPolicy::Free;
  return options;
}

TEST(StateValidity, TheVehicleMayHugTheCeilingUpToItsTopMargin) {
  const OccupancyMap map = pillarRoom();
  const Environment environment(map, quad());
  const double highest = 3.0 - 0.06 - 0.02;
  EXPECT_TRUE(environment.isStateValid({0, 0, highest - kTiny}));
  const auto violation = environment.stateViolation({0, 0, highest + kTiny});
  ASSERT_TRUE(violation);
  EXPECT_EQ(violation->kind, ViolationKind::Occupied);
  // Hugging the ceiling the rotors see it 0.05 m above: the regime the planner is after.
  EXPECT_NEAR(environment.ceiling({0, 0, highest - kTiny}).nearest_gap_m, 0.05, 1e-5);
}

TEST(StateValidity, SidewaysAndBelowTheMarginIsTheCollisionRadiusPlusMargin) {
  const OccupancyMap map = pillarRoom();
  const Environment environment(map, quad());
  const double reach = 0.36 + 0.10;
  EXPECT_TRUE(environment.isStateValid({1.0 - reach - kTiny, 0, 1.5}));
  EXPECT_FALSE(environment.isStateValid({1.0 - reach + kTiny, 0, 1.5}));
  EXPECT_TRUE(environment.isStateValid({0, 0, 0.2 + 0.12 + 0.10 + kTiny}));
  EXPECT_FALSE(environment.isStateValid({0, 0, 0.2 + 0.12 + 0.10 - kTiny}));
  // Past the pillar's corner the cylinder's round side counts, not its bounding square.
  const double offset = reach / std::sqrt(2.0) + 0.005;  // corner distance reach + 0.007
  EXPECT_TRUE(environment.isStateValid({1.0 - offset, 0.2 + offset, 1.5}));
}

TEST(StateValidity, UnknownSpaceIsAnObstacleUnlessTheOptionFreesIt) {
  const OccupancyMap map = pillarRoom(0.0);  // nothing known for x > 0
  const Environment cautious(map, quad());
  const auto violation = cautious.stateViolation({-0.3, -1.0, 1.5});
  ASSERT_TRUE(violation);
  EXPECT_EQ(violation->kind, ViolationKind::Unknown);
  const Environment bold(map, quad(), {}, freeUnknown());
  EXPECT_TRUE(bold.isStateValid({-0.3, -1.0, 1.5}));
}

TEST(StateValidity, TheFastPathAgreesWithTheExactCylinderTest) {
  const OccupancyMap map = pillarRoom();
  const Environment environment(map, quad());
  std::mt19937 random(7);
  std::uniform_real_distribution<double> xy(-2.0, 2.0), z(0.0, 3.4);
  int valid = 0;
  for (int n = 0; n < 3000; ++n) {
    const Eigen::Vector3d p(xy(random), xy(random), z(random));
    const bool fast = environment.isStateValid(p);
    EXPECT_EQ(fast, !environment.checkPathDensely({p})) << p.transpose();
    valid += fast;
  }
  EXPECT_GT(valid, 300);
  EXPECT_LT(valid, 2700);
}

// The specification of the cylinder test, voxel by voxel: the first blocking voxel (rows of
// columns, then bottom to top) the inflated cylinder overlaps by more than a face or a side.
std::optional<ViolationKind> scanCylinder(const Environment& environment, const Eigen::Vector3d& p,
                                          bool unknown_blocks) {
  std::optional<ViolationKind> found;
  testing::anyVoxelInCylinder(environment.grid().frame(), environment.vehicle(), p, [&](int i, int j, int k) {
    const CellState state = environment.grid().at(i, j, k);
    if (state == CellState::Occupied) found = ViolationKind::Occupied;
    if (state == CellState::Unknown && unknown_blocks) found = ViolationKind::Unknown;
    return found.has_value();
  });
  return found;
}

// Occupied slabs and pillars with unknown pockets next to them, and unknown beyond x = 1.5.
// 70 voxels high: the masks' bits span two words, the slab at 6.4 m straddles them.
OccupancyMap slabsAndPockets() {
  return analyticMap({-2, -2, 0}, {2, 2, 7.0}, 0.1, [](const Eigen::Vector3d& c) {
    if (c.x() > 1.5) return CellState::Unknown;
    if (c.z() < 0.2 || c.z() > 6.6 || (c.z() > 6.2 && c.z() < 6.5 && c.y() < 0.0)) return CellState::Occupied;
    if (c.x() > 0.3 && c.x() < 0.7 && c.z() > 1.0 && c.z() < 1.3) return CellState::Unknown;
    if (c.x() > 0.7 && c.x() < 1.0 && std::abs(c.y()) < 0.5) return CellState::Occupied;
    if (c.y() > 1.0 && c.z() > 2.0 && c.z() < 2.2) return CellState::Occupied;
    return CellState::Free;
  });
}

TEST(StateValidity, TheCylinderTestAndItsFastPathsAgreeWithAVoxelScan) {
  // Under both unknown-space policies, states close to everything (and poking out of the map).
  const OccupancyMap map = slabsAndPockets();
  for (const bool unknown_blocks : {true, false}) {
    const Environment environment(map, quad(), {}, unknown_blocks ? MapIndexOptions{} : freeUnknown());
    std::mt19937 random(11);
    std::uniform_real_distribution<double> xy(-1.95, 1.95), z(0.05, 6.95);
    int blocked = 0, unknown = 0;
    for (int n = 0; n < 40000; ++n) {
      const Eigen::Vector3d p(xy(random), xy(random), z(random));
      if (!environment.contains(p)) continue;  // the map ends where the known voxels end, at x = 1.5
      const std::optional<ViolationKind> expected = scanCylinder(environment, p, unknown_blocks);
      const auto violation = environment.checkPathDensely({p});  // the exact test, no fast path
      ASSERT_EQ(violation.has_value(), expected.has_value()) << p.transpose();
      // The fast paths (distance field, footprint masks) never decide otherwise.
      ASSERT_EQ(environment.isStateValid(p), !expected.has_value()) << p.transpose();
      if (!expected) continue;
      EXPECT_EQ(violation->kind, *expected) << p.transpose();
      ++blocked;
      unknown += *expected == ViolationKind::Unknown;
    }
    EXPECT_GT(blocked, 2000);
    if (unknown_blocks)
      EXPECT_GT(unknown, 200);
    else
      EXPECT_EQ(unknown, 0);
  }
}

// A random point at most `radius` from `centre` (on the sphere itself one time in four).
Eigen::Vector3d pointWithin(const Eigen::Vector3d& centre, double radius, std::mt19937& random) {
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Eigen::Vector3d direction = Eigen::Vector3d(normal(random), normal(random), normal(random)).normalized();
  const double u = unit(random);
  return centre + direction * radius * (u < 0.25 ? 1.0 : std::cbrt(u));
}

TEST(ValidReach, EveryStateWithinTheReachIsValidByTheExactTestUnderEveryPolicy) {
  const OccupancyMap map = slabsAndPockets();
  for (const UnknownPolicy policy : {UnknownPolicy::Occupied, UnknownPolicy::Free, UnknownPolicy::Fill}) {
    MapIndexOptions options;
    options.unknown.policy = policy;
    const Environment environment(map, quad(), {}, options);
    std::mt19937 random(5);
    std::uniform_real_distribution<double> xy(-1.95, 1.95), z(0.05, 6.95);
    int reaching = 0;
    double longest = 0.0;
    for (int n = 0; n < 4000; ++n) {
      const Eigen::Vector3d p(xy(random), xy(random), z(random));
      const double reach = environment.validReach_m(p);
      ASSERT_GE(reach, 0.0);
      if (reach == 0.0) continue;
      ++reaching;
      longest = std::max(longest, reach);
      ASSERT_TRUE(environment.isStateValid(p)) << p.transpose();
      for (int m = 0; m < 20; ++m) {
        const Eigen::Vector3d q = pointWithin(p, reach, random);
        ASSERT_TRUE(environment.contains(q)) << p.transpose() << " -> " << q.transpose();
        ASSERT_FALSE(environment.checkPathDensely({q})) << p.transpose() << " -> " << q.transpose();  // exact test
        ASSERT_TRUE(environment.isStateValid(q)) << p.transpose() << " -> " << q.transpose();
      }
    }
    // The reach is no formality: many states have one, some well over a voxel.
    EXPECT_GT(reaching, 400) << unknownPolicyName(policy);
    EXPECT_GT(longest, 0.5) << unknownPolicyName(policy);
  }
}

TEST(ValidReach, IsZeroAtAnInvalidStateAndOutsideAndStopsAtTheMapsBox) {
  const OccupancyMap map = pillarRoom(1.5);  // nothing known for x > 1.5: the box ends there
  const Environment cautious(map, quad());
  EXPECT_EQ(cautious.validReach_m({1.2, 0, 1.5}), 0.0);  // inside the pillar
  EXPECT_EQ(cautious.validReach_m({0, 0, 0.3}), 0.0);    // the cylinder's bottom margin in the floor
  EXPECT_EQ(cautious.validReach_m({0, -3, 1.5}), 0.0);   // outside the map
  EXPECT_EQ(cautious.validReach_m({0, 0, std::nan("")}), 0.0);
  // Mid-room: the lower bound (box, floor and ceiling a metre and more away) beyond the bounding sphere.
  EXPECT_GT(cautious.validReach_m({-1.0, -1.0, 1.6}), 0.2);
  // Under the free policy the field ignores the box, the reach does not: the body centre stays inside.
  const Environment bold(map, quad(), {}, freeUnknown());
  const Eigen::Vector3d near_edge(-1.0, -1.95, 1.6);
  EXPECT_GT(bold.validReach_m(near_edge), 0.0);
  EXPECT_LE(bold.validReach_m(near_edge), 0.05);
  EXPECT_FALSE(bold.contains(near_edge - Eigen::Vector3d(0, 0.05 + 1e-9, 0)));
}

TEST(Clearance, IsTheDistanceToTheNearestBlockedVoxelSurface) {
  const OccupancyMap map = pillarRoom();
  const Environment environment(map, quad());
  EXPECT_NEAR(environment.clearance_m({0, 0, 2.5}), 0.5, 1e-9);                       // ceiling
  EXPECT_NEAR(environment.clearance_m({0.7, 0.5, 1.5}), std::hypot(0.3, 0.3), 1e-9);  // pillar edge
  EXPECT_NEAR(environment.clearance_m({-1.8, 0, 1.5}), 0.2, 1e-9);                    // unknown beyond the map
  EXPECT_EQ(environment.clearance_m({1.2, 0, 1.5}), 0.0);                             // inside the pillar
  const Environment bold(map, quad(), {}, freeUnknown());
  EXPECT_NEAR(bold.clearance_m({-1.8, 0, 1.5}), 1.3, 1e-9);  // floor
}

TEST(MotionValidity, ASegmentThroughThePillarIsCaughtAndTheDenseCheckSaysWhere) {
  const OccupancyMap map = pillarRoom();
  const Environment environment(map, quad());
  const std::vector<Eigen::Vector3d> path{{-1, 0, 1.5}, {0.3, 0, 1.5}, {1.7, 0.1, 1.5}};
  EXPECT_TRUE(environment.isMotionValid(path[0], path[1]));
  EXPECT_FALSE(environment.isMotionValid(path[1], path[2]));
  const auto violation = environment.checkPathDensely(path);
  ASSERT_TRUE(violation);
  EXPECT_EQ(violation->segment, 1u);
  EXPECT_EQ(violation->kind, ViolationKind::Occupied);
  EXPECT_NEAR(violation->position_m.x(), 1.0 - 0.46, 0.02);
  EXPECT_NE(violation->describe().find("segment 1"), std::string::npos);
  EXPECT_FALSE(environment.checkPathDensely({path[0], path[1]}));
}

TEST(MotionValidity, LeavingTheMapIsAViolation) {
  const OccupancyMap map = pillarRoom();
  const Environment environment(map, quad());
  const auto violation = environment.motionViolation({0, -1, 1.5}, {0, -3, 1.5});
  ASSERT_TRUE(violation);
  EXPECT_NE(violation->kind, ViolationKind::Occupied);
}

}  // namespace
}  // namespace ceilplan::environment
