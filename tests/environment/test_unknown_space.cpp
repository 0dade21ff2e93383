// The unknown-space policy (occupied, free, fill) and the map index that every vehicle's
// Environment shares.

#include "analytic_maps.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/environment/environment.hpp"
#include "ceilplan/environment/map_index.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace ceilplan::environment {
namespace {

using testing::analyticMap;
using testing::quad;
using testing::singleRotor;

constexpr double kNone = std::numeric_limits<double>::infinity();

bool inBox(const Eigen::Vector3d& c, double x0, double x1, double y0, double y1, double z0, double z1) {
  return c.x() >= x0 && c.x() < x1 && c.y() >= y0 && c.y() < y1 && c.z() >= z0 && c.z() < z1;
}

// A 5.2 x 3.6 x 2.8 m hall inside 0.4 m walls, 0.2 m floor and ceiling (underside at 3.0 m),
// scanned but for five unknown regions:
//   small:    a 0.4 m cube in mid-air;
//   large:    1.5 x 1.2 x 1.0 m in mid-air;
//   ceiling:  0.5 x 0.4 x 0.3 m just under the ceiling;
//   wall:     a void inside a wall, with occupied voxels all round;
//   opening:  a 0.6 m hole through the west wall, open to the unmapped outside.
OccupancyMap hall(double resolution) {
  return analyticMap({-3, -2, 0}, {3, 2, 3.2}, resolution, [](const Eigen::Vector3d& c) {
    if (inBox(c, -1.5, -1.1, -0.2, 0.2, 1.4, 1.8)) return CellState::Unknown;  // small
    if (inBox(c, 0.5, 2.0, -0.6, 0.6, 1.0, 2.0)) return CellState::Unknown;    // large
    if (inBox(c, -2.5, -2.0, 0.8, 1.2, 2.7, 3.0)) return CellState::Unknown;   // ceiling
    if (inBox(c, 2.7, 2.9, 0.0, 0.2, 1.0, 1.2)) return CellState::Unknown;     // wall
    if (inBox(c, -3.0, -2.4, -0.2, 0.2, 1.0, 1.4)) return CellState::Unknown;  // opening
    if (c.z() < 0.2 || c.z() >= 3.0 || std::abs(c.x()) > 2.6 || std::abs(c.y()) > 1.6) return CellState::Occupied;
    return CellState::Free;
  });
}

const Eigen::Vector3d kSmall(-1.3, 0.0, 1.6), kLarge(1.25, 0.0, 1.5), kCeiling(-2.25, 1.0, 2.85), kWall(2.8, 0.1, 1.1),
    kOpening(-2.7, 0.0, 1.2);

std::shared_ptr<const MapIndex> indexed(const OccupancyMap& map, UnknownPolicy policy, double fill_max_m = 1.0) {
  MapIndexOptions options;
  options.unknown.policy = policy;
  options.unknown.fill_max_m = fill_max_m;
  return MapIndex::build(map, options);
}

TEST(UnknownSpace, PoliciesHaveNamesAndBadValuesAreRefused) {
  EXPECT_EQ(unknownPolicyFromName("fill"), UnknownPolicy::Fill);
  EXPECT_EQ(unknownPolicyName(UnknownPolicy::Free), "free");
  EXPECT_THROW(unknownPolicyFromName("maybe"), ceilplan::InputError);
  UnknownSpace unknown{UnknownPolicy::Fill, 0.5};
  EXPECT_EQ(unknown.describe(), "fill (pockets up to 0.5 m)");
  for (const double bad : {0.0, -1.0, std::nan(""), kNone}) {
    unknown.fill_max_m = bad;
    EXPECT_THROW(unknown.validate(), ceilplan::InputError) << bad;
  }
  const OccupancyMap map = hall(0.1);
  MapIndexOptions options;
  options.unknown = unknown;
  EXPECT_THROW(MapIndex(map, options), ceilplan::InputError);
}

TEST(UnknownSpace, OccupiedAssumesNothing) {
  const OccupancyMap map = hall(0.1);
  const auto index = indexed(map, UnknownPolicy::Occupied);
  for (const auto& p : {kSmall, kLarge, kCeiling, kWall, kOpening}) EXPECT_FALSE(index->isAssumedFree(p));
  EXPECT_NEAR(index->unknownSummary().unknown_volume_m3,
              0.4 * 0.4 * 0.4 + 1.5 * 1.2 * 1.0 + 0.5 * 0.4 * 0.3 + 0.2 * 0.2 * 0.2 + 0.6 * 0.4 * 0.4, 1e-9);
  EXPECT_EQ(index->unknownSummary().assumed_free_volume_m3, 0.0);
  const Environment environment(index, quad());
  const auto violation = environment.stateViolation(kSmall);
  ASSERT_TRUE(violation);
  EXPECT_EQ(violation->kind, ViolationKind::Unknown);
  EXPECT_NE(violation->describe().find("unknown-space policy"), std::string::npos) << violation->describe();
  EXPECT_FALSE(environment.assumesFree(kSmall + Eigen::Vector3d(0, 0, -0.3)));
}

TEST(UnknownSpace, FillFreesSmallPocketsInFreeSpaceOnly) {
  const OccupancyMap map = hall(0.1);
  const auto index = indexed(map, UnknownPolicy::Fill, 1.0);
  EXPECT_TRUE(index->isAssumedFree(kSmall));
  EXPECT_TRUE(index->isAssumedFree(kCeiling));      // touches the ceiling and free air
  EXPECT_FALSE(index->isAssumedFree(kLarge));       // 1.5 m: larger than 1 m
  EXPECT_FALSE(index->isAssumedFree(kWall));        // no free voxel beside it
  EXPECT_FALSE(index->isAssumedFree(kOpening));     // open to the outside of the map
  EXPECT_FALSE(index->isAssumedFree({0, 0, 1.5}));  // known free: not an assumption
  const UnknownSpaceSummary& summary = index->unknownSummary();
  EXPECT_EQ(summary.regions, 5u);
  EXPECT_EQ(summary.filled_regions, 2u);
  EXPECT_NEAR(summary.assumed_free_volume_m3, 0.4 * 0.4 * 0.4 + 0.5 * 0.4 * 0.3, 1e-9);

  const Environment environment(index, quad());
  EXPECT_TRUE(environment.isStateValid(kSmall));
  EXPECT_TRUE(environment.assumesFree(kSmall));
  EXPECT_FALSE(environment.isStateValid(kLarge));
  EXPECT_FALSE(environment.assumesFree({0.0, -1.0, 0.8}));  // far from every pocket
}

TEST(UnknownSpace, FreeAssumesEveryUnknownVoxelInsideTheMap) {
  const OccupancyMap map = hall(0.1);
  const auto index = indexed(map, UnknownPolicy::Free);
  for (const auto& p : {kSmall, kLarge, kCeiling, kWall, kOpening})
    EXPECT_TRUE(index->isAssumedFree(p)) << p.transpose();
  EXPECT_NEAR(index->unknownSummary().assumed_free_volume_m3, index->unknownSummary().unknown_volume_m3, 1e-12);
  EXPECT_TRUE(Environment(index, quad()).isStateValid(kLarge));
}

TEST(UnknownSpace, ThePocketSizeIsInMetresWhateverTheResolution) {
  // The large pocket is exactly 1.5 m long: filled up to 1.5 m, not below, at 0.1 and 0.05 m.
  for (const double resolution : {0.1, 0.05}) {
    const OccupancyMap map = hall(resolution);
    EXPECT_TRUE(indexed(map, UnknownPolicy::Fill, 1.5)->isAssumedFree(kLarge)) << resolution;
    EXPECT_FALSE(indexed(map, UnknownPolicy::Fill, 1.45)->isAssumedFree(kLarge)) << resolution;
    EXPECT_TRUE(indexed(map, UnknownPolicy::Fill, 0.4)->isAssumedFree(kSmall)) << resolution;
    EXPECT_FALSE(indexed(map, UnknownPolicy::Fill, 0.35)->isAssumedFree(kSmall)) << resolution;
  }
}

TEST(UnknownSpace, PocketsTouchingAtAnEdgeOrCornerAreOneRegion) {
  // Two 0.3 m cubes in mid-air meeting only along an edge: one region 0.6 m across.
  const OccupancyMap map = analyticMap({-2, -2, 0}, {2, 2, 3}, 0.1, [](const Eigen::Vector3d& c) {
    if (inBox(c, 0.0, 0.3, 0.0, 0.3, 1.0, 1.3) || inBox(c, 0.3, 0.6, 0.3, 0.6, 1.0, 1.3)) return CellState::Unknown;
    if (inBox(c, -1.0, -0.7, 0.0, 0.3, 1.0, 1.3) || inBox(c, -0.7, -0.4, 0.0, 0.3, 1.3, 1.6)) return CellState::Unknown;
    return c.z() < 0.2 || c.z() >= 2.8 ? CellState::Occupied : CellState::Free;
  });
  const auto narrow = indexed(map, UnknownPolicy::Fill, 0.5);
  EXPECT_EQ(narrow->unknownSummary().regions, 2u);
  EXPECT_EQ(narrow->unknownSummary().filled_regions, 0u);
  const auto wide = indexed(map, UnknownPolicy::Fill, 0.6);
  EXPECT_EQ(wide->unknownSummary().filled_regions, 2u);
}

TEST(UnknownSpace, FilledSpaceIsFreeAirForTheGapsAndTheClearance) {
  const OccupancyMap map = hall(0.1);
  const auto occupied = indexed(map, UnknownPolicy::Occupied);
  const auto fill = indexed(map, UnknownPolicy::Fill, 1.0);
  // Below the pocket under the ceiling: unknown first means no surface; filled, the ceiling counts.
  const Eigen::Vector3d below_pocket(-2.25, 1.0, 2.0);
  EXPECT_EQ(Environment(occupied, singleRotor()).ceilingGapAt(below_pocket), kNone);
  EXPECT_NEAR(Environment(fill, singleRotor()).ceilingGapAt(below_pocket), 1.0, 1e-9);
  EXPECT_NEAR(Environment(fill, singleRotor()).ceiling(below_pocket).nearest_gap_m, 3.0 - 2.03, 1e-9);
  // Below the small pocket: 0.3 m to its underside, or 0.9 m to the floor once it is filled.
  const Eigen::Vector3d below_small(-1.3, 0.0, 1.1);
  EXPECT_NEAR(Environment(occupied, quad()).clearance_m(below_small), 0.3, 1e-9);
  EXPECT_NEAR(Environment(fill, quad()).clearance_m(below_small), 0.9, 1e-9);
}

TEST(UnknownSpace, APathSaysWhereItReliesOnThePolicy) {
  const OccupancyMap map = hall(0.1);
  std::vector<Eigen::Vector3d> path{{-1.9, 0.0, 1.6}, {-1.0, 0.0, 1.6}, {0.0, 0.0, 1.6}};
  EXPECT_EQ(Environment(indexed(map, UnknownPolicy::Occupied), quad()).assumedFreeAlong(path).length_m, 0.0);

  const Environment environment(indexed(map, UnknownPolicy::Fill, 1.0), quad());
  EXPECT_FALSE(environment.checkPathDensely(path));
  const AssumedFreeStretches stretches = environment.assumedFreeAlong(path);
  // The inflated cylinder (radius 0.46 m) overlaps the small pocket (x in [-1.5, -1.1)) from
  // x = -1.96 to -0.64: from the start to 1.26 m along the path, across the middle waypoint.
  ASSERT_EQ(stretches.intervals.size(), 1u);
  const double step = environment.denseStep_m();
  EXPECT_EQ(stretches.intervals[0].from_m, 0.0);
  EXPECT_NEAR(stretches.intervals[0].to_m, 1.26, step);
  EXPECT_NEAR(stretches.intervals[0].from_point_m.x(), -1.9, 1e-12);
  EXPECT_NEAR(stretches.intervals[0].to_point_m.x(), -0.64, step);
  EXPECT_NEAR(stretches.length_m, 1.26, step);
  // Under free, a path on to x = 0.3 also relies on the large pocket (x >= 0.5) from x = 0.04.
  path.push_back({0.3, 0.0, 1.6});
  const AssumedFreeStretches bolder = Environment(indexed(map, UnknownPolicy::Free), quad()).assumedFreeAlong(path);
  ASSERT_EQ(bolder.intervals.size(), 2u);
  EXPECT_NEAR(bolder.intervals[1].from_m, 1.94, step);
  EXPECT_NEAR(bolder.intervals[1].to_m, 2.2, 1e-12);
  EXPECT_NEAR(bolder.length_m, 1.26 + 0.26, 2 * step);
}

TEST(UnknownSpace, UnderFillTheFastPathsAgreeWithAVoxelScan) {
  const OccupancyMap map = hall(0.1);
  const auto index = indexed(map, UnknownPolicy::Fill, 1.0);
  const Environment environment(index, quad());
  const GridFrame& frame = index->grid().frame();
  std::mt19937 random(5);
  std::uniform_real_distribution<double> x(-2.95, 2.95), y(-1.95, 1.95), z(0.05, 3.15);
  int blocked = 0, relied = 0;
  for (int n = 0; n < 20000; ++n) {
    const Eigen::Vector3d p(x(random), y(random), z(random));
    // The specification: a voxel blocks if occupied, or unknown and not assumed free.
    bool expected_blocked = false, expected_relies = false;
    testing::anyVoxelInCylinder(frame, environment.vehicle(), p, [&](int i, int j, int k) {
      const Eigen::Vector3d centre(frame.centreOf(0, i), frame.centreOf(1, j), frame.centreOf(2, k));
      const CellState state = index->grid().at(i, j, k);
      const bool assumed = index->isAssumedFree(centre);
      expected_relies = expected_relies || assumed;
      expected_blocked = expected_blocked || state == CellState::Occupied || (state == CellState::Unknown && !assumed);
      return false;  // every voxel: both answers are wanted
    });
    ASSERT_EQ(environment.isStateValid(p), !expected_blocked) << p.transpose();
    ASSERT_EQ(environment.assumesFree(p), expected_relies) << p.transpose();
    blocked += expected_blocked;
    relied += expected_relies;
  }
  EXPECT_GT(blocked, 5000);
  EXPECT_GT(relied, 100);
}

TEST(MapIndex, EveryVehicleOnAMapSharesOneIndex) {
  const OccupancyMap map = hall(0.1);
  MapIndexOptions options;
  options.unknown.policy = UnknownPolicy::Free;  // the pockets would leave the wide vehicle no room
  const auto index = MapIndex::build(map, options);
  const Environment plain(index, quad());
  VehicleGeometry standoff = quad();
  standoff.margin_m += 0.5;  // free mode's standoff grows the margins
  standoff.top_margin_m += 0.5;
  const Environment wide(index, standoff);
  EXPECT_EQ(plain.index().get(), wide.index().get());
  EXPECT_EQ(&plain.grid(), &wide.grid());  // the grid was not built again
  EXPECT_EQ(&plain.columns(), &wide.columns());
  EXPECT_EQ(index.use_count(), 3);
  // Sharing changes no answer: the same as an Environment that indexed the map itself.
  const Environment alone(map, standoff, {}, options);
  EXPECT_NE(alone.index().get(), index.get());
  std::mt19937 random(3);
  std::uniform_real_distribution<double> x(-2.9, 2.9), y(-1.9, 1.9), z(0.1, 3.1);
  int valid = 0;
  for (int n = 0; n < 3000; ++n) {
    const Eigen::Vector3d p(x(random), y(random), z(random));
    ASSERT_EQ(wide.isStateValid(p), alone.isStateValid(p)) << p.transpose();
    ASSERT_EQ(wide.clearance_m(p), alone.clearance_m(p)) << p.transpose();
    valid += wide.isStateValid(p);
  }
  EXPECT_GT(valid, 100);
  EXPECT_THROW(Environment(std::shared_ptr<const MapIndex>(), quad()), ceilplan::Error);
}

TEST(MapIndex, TheIndexDoesNotDependOnTheNumberOfThreads) {
  const OccupancyMap map = hall(0.05);
  MapIndexOptions one, three;
  one.workers = 1;
  three.workers = 3;
  one.unknown.policy = three.unknown.policy = UnknownPolicy::Fill;
  const MapIndex a(map, one), b(map, three);
  ASSERT_EQ(a.columns().runs().size(), b.columns().runs().size());
  for (std::size_t r = 0; r < a.columns().runs().size(); ++r) {
    ASSERT_EQ(a.columns().runs()[r].lo, b.columns().runs()[r].lo);
    ASSERT_EQ(a.columns().runs()[r].hi, b.columns().runs()[r].hi);
  }
  const GridFrame& frame = a.grid().frame();
  for (std::size_t v = 0; v < frame.voxelCount(); v += 7) {
    ASSERT_EQ(a.grid().atLinear(v), b.grid().atLinear(v));
    ASSERT_EQ(a.distance().horizontalSquared(v), b.distance().horizontalSquared(v));
  }
  std::mt19937 random(9);
  std::uniform_real_distribution<double> x(-3, 3), y(-2, 2), z(0, 3.2);
  for (int n = 0; n < 2000; ++n) {
    const Eigen::Vector3d p(x(random), y(random), z(random));
    ASSERT_EQ(a.distance().distance_m(p), b.distance().distance_m(p));
  }
}

}  // namespace
}  // namespace ceilplan::environment
