// Where a route from one place reaches: a flood of the lattice from the origin, sound (a
// route exists wherever it says so) but blind to passages its lattice does not fit through.

#include "planner_fixtures.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/planner/planner_factory.hpp"
#include "ceilplan/planner/reachable_space.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace ceilplan::testing {
namespace {

// Two rooms at 0.1 m, floor top 0.2 m, ceiling underside 2.4 m, a 0.2 m wall at x [0, 0.2)
// with a doorway from y = -1.0 to -1.0 + width, floor to ceiling (none for width 0).
environment::OccupancyMap roomsWithADoorway(double width_m) {
  return analyticMap({-2.0, -2.0, 0.0}, {2.2, 2.0, 2.8}, 0.1, [=](const Eigen::Vector3d& c) {
    if (c.z() < 0.2 || c.z() > 2.4) return CellState::Occupied;
    if (c.x() > 0.0 && c.x() < 0.2)
      return c.y() > -1.0 && c.y() < -1.0 + width_m ? CellState::Free : CellState::Occupied;
    return CellState::Free;
  });
}

const Eigen::Vector3d kOrigin(-1.2, 0.0, 1.2);
const std::vector<Eigen::Vector3d> kRightRoom{{1.4, 1.2, 1.2}, {1.3, -1.3, 0.6}, {1.5, 0.0, 2.0}};

TEST(ReachableSpace, ReachesTheNextRoomThroughAWideDoorwayAndEveryAnswerHasARoute) {
  const CeilingScene scene(roomsWithADoorway(2.0));
  const planner::ReachableSpace space(scene.rules, kOrigin, 0.4);
  EXPECT_DOUBLE_EQ(space.spacing_m(), 0.4);
  for (const Eigen::Vector3d& p : kRightRoom) {
    ASSERT_TRUE(space.reaches(p)) << p.transpose();
    planner::PlanRequest request;
    request.start_m = kOrigin;
    request.goal_m = p;
    request.planner = planner::referencePlannerName();
    EXPECT_NO_THROW(scene.planner.plan(request)) << p.transpose();
  }
  EXPECT_TRUE(space.reaches(kOrigin + Eigen::Vector3d(0.05, 0.0, 0.0)));  // next to the origin, between nodes
}

TEST(ReachableSpace, ReachesNothingBeyondAClosedWall) {
  const CeilingScene scene(roomsWithADoorway(0.0));
  const planner::ReachableSpace space(scene.rules, kOrigin, 0.4);
  EXPECT_TRUE(space.reaches({-1.0, 1.4, 2.0}));
  for (const Eigen::Vector3d& p : kRightRoom) {
    ASSERT_TRUE(scene.rules.isStateValid(p));
    EXPECT_FALSE(space.reaches(p)) << p.transpose();
  }
  EXPECT_FALSE(space.reaches({0.1, 0.0, 1.2}));  // inside the wall
  EXPECT_FALSE(space.reaches({0.0, 0.0, std::numeric_limits<double>::quiet_NaN()}));
}

TEST(ReachableSpace, IsBlindToADoorwayNoNodeOfItsLatticeFitsThrough) {
  // 1.1 m: the vehicle's 0.92 m with its margins, one voxel more than whole voxels need; the
  // roadmap's refinement finds it (test_narrow_passages.cpp), a 0.4 m flood does not: callers
  // fall back. A flood at the map's resolution does.
  const CeilingScene scene(roomsWithADoorway(1.1));
  EXPECT_FALSE(planner::ReachableSpace(scene.rules, kOrigin, 0.4).reaches(kRightRoom[0]));
  EXPECT_TRUE(planner::ReachableSpace(scene.rules, kOrigin, 0.1).reaches(kRightRoom[0]));
}

TEST(ReachableSpace, TheSameWhateverTheThreads) {
  const CeilingScene scene(roomsWithADoorway(2.0));
  const planner::ReachableSpace one(scene.rules, kOrigin, 0.2, 1), two(scene.rules, kOrigin, 0.2, 2);
  EXPECT_GT(one.reachedNodeCount(), 1000u);
  EXPECT_EQ(one.reachedNodeCount(), two.reachedNodeCount());
}

TEST(ReachableSpace, RefusesAnInvalidOriginAndABadSpacing) {
  const CeilingScene scene(roomsWithADoorway(2.0));
  EXPECT_THROW(planner::ReachableSpace(scene.rules, {0.1, 1.5, 1.2}, 0.4), InputError);
  EXPECT_THROW(planner::ReachableSpace(scene.rules, {9.0, 0.0, 1.2}, 0.4), InputError);
  EXPECT_THROW(planner::ReachableSpace(scene.rules, kOrigin, 0.0), InputError);
  EXPECT_THROW(planner::ReachableSpace(scene.rules, kOrigin, std::numeric_limits<double>::quiet_NaN()), InputError);
}

}  // namespace
}  // namespace ceilplan::testing
