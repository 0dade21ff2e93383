// Complete where the map is passable: a doorway the coarse lattice misses is found by refining
// near it, and where there is no way through, the error names the gap and the rule that
// blocks it.

#include "planner_fixtures.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/planner/lattice_planner.hpp"
#include "ceilplan/planner/lattice_roadmap.hpp"
#include "ceilplan/planner/planner_factory.hpp"

#include <gtest/gtest.h>

#include <string>

namespace ceilplan::testing {
namespace {

// Two rooms at 0.1 m, floor top 0.2 m, ceiling 2.4 m, joined through a 0.2 m wall at x [0, 0.2)
// by a doorway from y_lo to y_hi, floor to ceiling; `door` says what fills the doorway's
// voxels (Free: open).
environment::OccupancyMap twoRooms(double y_lo, double y_hi, CellState door = CellState::Free) {
  return analyticMap({-2.0, -2.0, 0.0}, {2.2, 2.0, 2.8}, 0.1, [=](const Eigen::Vector3d& c) {
    if (c.z() < 0.2 || c.z() > 2.4) return CellState::Occupied;
    if (c.x() > 0.0 && c.x() < 0.2) return c.y() > y_lo && c.y() < y_hi ? door : CellState::Occupied;
    return CellState::Free;
  });
}

const Eigen::Vector3d kStart(-1.2, -1.0, 1.2), kGoal(1.4, 1.0, 1.2);

// The vehicle with its margins is 0.92 m wide (quad.yaml: 0.36 m radius, 0.10 m margin).
constexpr double kVehicleWidthM = 0.92;

// Whether a node of the default 0.4 m lattice in the wall's slab is valid: without one, the
// coarse lattice alone cannot pass.
bool coarseLatticeHasANodeInTheDoorway(const planner::SafetyRules& rules) {
  const environment::GridFrame& frame = rules.environment().grid().frame();
  for (int k = 0; k < frame.size()[2]; k += 4)
    for (int j = 0; j < frame.size()[1]; j += 4)
      for (int i = 0; i < frame.size()[0]; i += 4) {
        const Eigen::Vector3d p(frame.centreOf(0, i), frame.centreOf(1, j), frame.centreOf(2, k));
        if (std::abs(p.x() - 0.1) < 0.1 && rules.isStateValid(p)) return true;
      }
  return false;
}

// Whether a path crosses the wall's middle plane (x = 0.1) between y_lo and y_hi.
bool crossesTheWallBetween(const std::vector<Eigen::Vector3d>& path, double y_lo, double y_hi) {
  for (std::size_t k = 1; k < path.size(); ++k) {
    const Eigen::Vector3d &a = path[k - 1], &b = path[k];
    if ((a.x() < 0.1) != (b.x() < 0.1)) {
      const Eigen::Vector3d crossing = a + (b - a) * ((0.1 - a.x()) / (b.x() - a.x()));
      return crossing.y() > y_lo && crossing.y() < y_hi;
    }
  }
  return false;
}

// From kStart to kGoal with `planner_name`, the lattice planners at the tour's 0.4 m.
planner::PlanRequest acrossTheWall(const std::string& planner_name) {
  planner::PlanRequest request;
  request.start_m = kStart;
  request.goal_m = kGoal;
  request.planner = planner_name;
  request.lattice.spacing_m = 0.4;
  request.time_limit_s = 120.0;
  return request;
}

// The "no path" message of planning across the wall; empty when a path was found.
std::string noPathMessage(const CeilingScene& scene, const std::string& planner_name) {
  try {
    scene.planner.plan(acrossTheWall(planner_name));
  } catch (const ceilplan::NoPathError& e) {
    return e.what();
  }
  return "";
}

// Where the lattice A* finds the way across the wall blocked (it must find no path).
planner::Blockage blockageAcrossTheWall(const CeilingScene& scene) {
  planner::LatticePlanner lattice(scene.planner.spaceInformation());
  EXPECT_EQ(solveOnce(lattice, scene.planner, kStart, kGoal).status, ompl::base::PlannerStatus::ABORT);
  const std::optional<planner::Blockage> blockage = lattice.lastBlockage();
  EXPECT_TRUE(blockage);
  return blockage.value_or(planner::Blockage{});
}

class DoorwayOneVoxelWiderThanTheVehicle : public ::testing::TestWithParam<double> {};

// Doorways 1.0 m (the vehicle's width rounded up to whole voxels: 8 cm to spare) and 1.1 m
// (one voxel more) wide, placed so that no node of the 0.4 m lattice fits in them.
TEST_P(DoorwayOneVoxelWiderThanTheVehicle, TheLatticePlannerFindsTheWayThrough) {
  const double width_m = GetParam();
  const CeilingScene scene(twoRooms(0.4, 0.4 + width_m));
  ASSERT_FALSE(coarseLatticeHasANodeInTheDoorway(scene.rules));
  planner::LatticePlanner lattice(scene.planner.spaceInformation());  // 0.4 m, the tour's spacing
  const Solved solved = solveOnce(lattice, scene.planner, kStart, kGoal);
  ASSERT_EQ(solved.status, ompl::base::PlannerStatus::EXACT_SOLUTION);
  EXPECT_FALSE(scene.rules.checkPathDensely(solved.waypoints));
  EXPECT_NEAR(scene.planner.objective().pathCost(solved.waypoints), solved.cost, 1e-6 * solved.cost);
  EXPECT_TRUE(crossesTheWallBetween(solved.waypoints, 0.4, 0.4 + width_m));
  // And through FlightPlanner, post-processed and re-checked, as `ceilplan plan` runs it.
  const planner::PlanResult plan = scene.planner.plan(acrossTheWall(planner::referencePlannerName()));
  EXPECT_FALSE(scene.rules.checkPathDensely(plan.waypoints));
}

TEST_P(DoorwayOneVoxelWiderThanTheVehicle, TheRoadmapFindsTheWayThroughForEveryPlace) {
  const double width_m = GetParam();
  const CeilingScene scene(twoRooms(0.4, 0.4 + width_m));
  ASSERT_FALSE(coarseLatticeHasANodeInTheDoorway(scene.rules));
  // Home and a place in each room, one in a corner pocket the 0.4 m lattice does not reach.
  const std::vector<Eigen::Vector3d> places{kStart, kGoal, {-1.0, 1.5, 1.5}, {1.72, -1.52, 0.45}};
  planner::LatticeSettings settings;  // 0.4 m, the tour's spacing
  settings.workers = 2;
  planner::LatticeRoadmap roadmap(scene.planner.spaceInformation(), settings);
  roadmap.build(scene.planner.objective(), places);
  EXPECT_GT(roadmap.bridgeVertexCount(), 0u);
  for (int from = 0; from < 4; ++from) {
    const auto routes = roadmap.routesFrom(from);
    for (int to = 0; to < 4; ++to) {
      if (to == from) continue;
      ASSERT_TRUE(routes[to]) << from << " -> " << to;
      EXPECT_FALSE(scene.rules.checkPathDensely(routes[to]->waypoints)) << from << " -> " << to;
      EXPECT_NEAR(scene.planner.objective().pathCost(routes[to]->waypoints), routes[to]->cost, 1e-4 * routes[to]->cost);
      EXPECT_FALSE(roadmap.blockage(from, to));
    }
    const int across = from % 2 == 0 ? 1 : 0;  // places 0 and 2 are left of the wall, 1 and 3 right
    EXPECT_TRUE(crossesTheWallBetween(routes[across]->waypoints, 0.4, 0.4 + width_m)) << from;
  }
  // As an OMPL planner, one query at a time.
  const ompl::base::PlannerPtr planner =
      planner::makePlanner(planner::defaultTourPlannerName(), scene.planner.spaceInformation());
  const Solved solved = solveOnce(*planner, scene.planner, kStart, kGoal);
  ASSERT_EQ(solved.status, ompl::base::PlannerStatus::EXACT_SOLUTION);
  EXPECT_TRUE(crossesTheWallBetween(solved.waypoints, 0.4, 0.4 + width_m));
}

INSTANTIATE_TEST_SUITE_P(Widths, DoorwayOneVoxelWiderThanTheVehicle, ::testing::Values(1.0, 1.1));

TEST(RoadmapPlaces, APlaceInTheDoorwayDoesNotJoinTheRoomsForTheOthers) {
  // A place just past the wall in the 1.1 m doorway joins lattice nodes of both rooms. A search
  // ends at a place and never passes through it, so start and goal are still apart on the
  // lattice: the roadmap must refine between the rooms rather than count them as one.
  const CeilingScene scene(twoRooms(0.4, 1.5));
  const Eigen::Vector3d in_the_doorway(0.275, 0.975, 1.2);
  ASSERT_TRUE(scene.rules.isStateValid(in_the_doorway));
  planner::LatticeSettings settings;  // 0.4 m, the tour's spacing
  planner::LatticeRoadmap roadmap(scene.planner.spaceInformation(), settings);
  roadmap.build(scene.planner.objective(), {kStart, in_the_doorway, kGoal});
  for (int from = 0; from < 3; ++from) {
    const auto routes = roadmap.routesFrom(from);
    for (int to = 0; to < 3; ++to)
      if (to != from) {
        ASSERT_TRUE(routes[to]) << from << " -> " << to;
        EXPECT_FALSE(scene.rules.checkPathDensely(routes[to]->waypoints)) << from << " -> " << to;
      }
  }
}

// A hall (z up to 2.2 m) under a loft (z from 2.6 m), 6 x 6 m at 0.1 m, the slab between
// them pierced by six 1.2 m holes the scan never saw (unknown: obstacles under the default
// policy) and one shaft 1.0 m square, in the corner, that it did: the only way up, 8 cm wider
// than the vehicle and placed so that no node of the 0.4 m lattice fits in it.
environment::OccupancyMap hallUnderALoft() {
  return analyticMap({-3.0, -3.0, 0.0}, {3.0, 3.0, 5.0}, 0.1, [](const Eigen::Vector3d& c) {
    if (c.z() < 0.2 || c.z() > 4.6) return CellState::Occupied;
    if (c.z() < 2.2 || c.z() > 2.6) return CellState::Free;
    if (c.x() > 1.7 && c.x() < 2.7 && c.y() > 1.7 && c.y() < 2.7) return CellState::Free;  // the shaft
    for (const double x : {-2.0, 0.0})
      for (const double y : {-1.5, 0.5, 1.9})
        if (std::abs(c.x() - x) < 0.6 && std::abs(c.y() - y) < 0.6) return CellState::Unknown;
    return CellState::Occupied;
  });
}

TEST(WideSearch, ThePlannersFindTheOnlyShaftPastTheUnscannedHolesNearerTheirWay) {
  const CeilingScene scene(hallUnderALoft());
  const Eigen::Vector3d hall(-1.0, -1.0, 1.2), loft(-1.0, -1.0, 3.4);
  const auto inTheShaft = [](const Eigen::Vector3d& p) {
    return p.x() > 1.7 && p.x() < 2.7 && p.y() > 1.7 && p.y() < 2.7;
  };
  const environment::GridFrame& frame = scene.environment.grid().frame();
  for (int k = 0; k < frame.size()[2]; k += 4)
    for (int j = 0; j < frame.size()[1]; j += 4)
      for (int i = 0; i < frame.size()[0]; i += 4) {
        const Eigen::Vector3d p(frame.centreOf(0, i), frame.centreOf(1, j), frame.centreOf(2, k));
        if (p.z() > 2.2 && p.z() < 2.6 && inTheShaft(p)) {
          ASSERT_FALSE(scene.rules.isStateValid(p)) << p.transpose();
        }
      }
  // Where the path first crosses the slab's middle (z = 2.4).
  const auto climbsTheShaft = [&](const std::vector<Eigen::Vector3d>& path) {
    for (std::size_t k = 1; k < path.size(); ++k) {
      const Eigen::Vector3d &a = path[k - 1], &b = path[k];
      if ((a.z() < 2.4) != (b.z() < 2.4)) return inTheShaft(a + (b - a) * ((2.4 - a.z()) / (b.z() - a.z())));
    }
    return false;
  };
  // The roadmap of a tour, the lattice A* and the roadmap as single-query planners.
  planner::LatticeRoadmap roadmap(scene.planner.spaceInformation());
  roadmap.build(scene.planner.objective(), {hall, loft});
  const auto route = roadmap.routesFrom(0)[1];
  ASSERT_TRUE(route);
  EXPECT_FALSE(scene.rules.checkPathDensely(route->waypoints));
  EXPECT_TRUE(climbsTheShaft(route->waypoints));
  for (const std::string& name : {planner::referencePlannerName(), planner::defaultTourPlannerName()}) {
    const ompl::base::PlannerPtr planner = planner::makePlanner(name, scene.planner.spaceInformation());
    const Solved solved = solveOnce(*planner, scene.planner, hall, loft);
    ASSERT_EQ(solved.status, ompl::base::PlannerStatus::EXACT_SOLUTION) << name;
    EXPECT_FALSE(scene.rules.checkPathDensely(solved.waypoints)) << name;
    EXPECT_TRUE(climbsTheShaft(solved.waypoints)) << name;
  }
}

// A 4 x 4 m hall at 0.1 m with a dead-end slot 1.0 m wide (8 cm to spare, no lattice node
// fits) running 2 m east from its wall at x = 2.
environment::OccupancyMap hallWithASlot() {
  return analyticMap({-2.0, -2.0, 0.0}, {4.2, 2.0, 2.8}, 0.1, [](const Eigen::Vector3d& c) {
    if (c.z() < 0.2 || c.z() > 2.4) return CellState::Occupied;
    if (c.x() < 2.0) return CellState::Free;
    return c.x() < 4.0 && c.y() > 0.0 && c.y() < 1.0 ? CellState::Free : CellState::Occupied;
  });
}

TEST(Refinement, APlaceJoinedOnlyThroughAnotherPlaceIsReachedFromEveryPlace) {
  const CeilingScene scene(hallWithASlot());
  // Home in the hall, a place at the slot's mouth, one at its end: refinement joins the end to
  // the mouth, the nearest point of the rest of the roadmap; every route to the end passes the mouth.
  const std::vector<Eigen::Vector3d> places{{-1.2, -1.0, 1.2}, {2.1, 0.5, 1.2}, {3.4, 0.5, 1.2}};
  planner::LatticeRoadmap roadmap(scene.planner.spaceInformation());
  roadmap.build(scene.planner.objective(), places);
  EXPECT_GT(roadmap.bridgeVertexCount(), 0u);
  for (int from = 0; from < 3; ++from) {
    const auto routes = roadmap.routesFrom(from);
    for (int to = 0; to < 3; ++to) {
      if (to == from) continue;
      ASSERT_TRUE(routes[to]) << from << " -> " << to;
      EXPECT_FALSE(scene.rules.checkPathDensely(routes[to]->waypoints)) << from << " -> " << to;
      EXPECT_FALSE(roadmap.blockage(from, to)) << from << " -> " << to;
    }
  }
}

TEST(NoPath, TheRoadmapNamesTheGapBetweenPlacesItCannotJoin) {
  const CeilingScene scene(twoRooms(0.3, 1.1));  // 0.8 m wide
  planner::LatticeRoadmap roadmap(scene.planner.spaceInformation());
  roadmap.build(scene.planner.objective(), {kStart, kGoal, {-1.0, 1.5, 1.5}});
  EXPECT_FALSE(roadmap.routesFrom(0)[1]);
  EXPECT_TRUE(roadmap.routesFrom(0)[2]);
  EXPECT_FALSE(roadmap.blockage(0, 2));
  for (const auto& [from, to] : std::vector<std::pair<int, int>>{{0, 1}, {1, 2}}) {
    const std::optional<planner::Blockage> blockage = roadmap.blockage(from, to);
    ASSERT_TRUE(blockage) << from << " -> " << to;
    EXPECT_EQ(blockage->rule, planner::BlockingRule::Clearance);
    EXPECT_NEAR(blockage->position_m.y(), 0.7, 0.01) << blockage->describe();
    EXPECT_NEAR(blockage->width_m, 0.8, 0.005) << blockage->describe();
  }
  // The same, asked as one query.
  const std::string message = noPathMessage(scene, planner::defaultTourPlannerName());
  EXPECT_NE(message.find("the opening there is 0.80 m wide"), std::string::npos) << message;
}

TEST(NoPath, TheErrorNamesTheGapTooNarrowForTheVehicle) {
  const CeilingScene scene(twoRooms(0.3, 1.1));  // 0.8 m wide
  const planner::Blockage blockage = blockageAcrossTheWall(scene);
  EXPECT_EQ(blockage.rule, planner::BlockingRule::Clearance);
  // The middle of the doorway: in the wall, halfway across it and up it.
  EXPECT_NEAR(blockage.position_m.x(), 0.1, 0.1) << blockage.describe();
  EXPECT_NEAR(blockage.position_m.y(), 0.7, 0.01) << blockage.describe();
  EXPECT_NEAR(blockage.position_m.z(), 1.3, 0.01) << blockage.describe();
  EXPECT_NEAR(blockage.width_m, 0.8, 0.005) << blockage.describe();
  EXPECT_NEAR(blockage.needed_width_m, kVehicleWidthM, 1e-9);

  const std::string message = noPathMessage(scene, planner::referencePlannerName());
  EXPECT_NE(message.find("by the vehicle's clearance: the opening there is 0.80 m wide and 2.20 m high"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("the vehicle needs 0.92 x 0.30 m with its margins"), std::string::npos) << message;
  EXPECT_EQ(message.find("stride"), std::string::npos) << message;
}

TEST(NoPath, TheErrorNamesUnknownSpaceWhenItFillsTheGap) {
  const CeilingScene scene(twoRooms(0.3, 1.5, CellState::Unknown));  // wide enough, but never scanned
  const planner::Blockage blockage = blockageAcrossTheWall(scene);
  EXPECT_EQ(blockage.rule, planner::BlockingRule::Unknown) << blockage.describe();
  EXPECT_NEAR(blockage.position_m.x(), 0.1, 0.1) << blockage.describe();
  EXPECT_GT(blockage.position_m.y(), 0.3) << blockage.describe();
  EXPECT_LT(blockage.position_m.y(), 1.5) << blockage.describe();
  EXPECT_NE(blockage.describe().find("by unknown space"), std::string::npos) << blockage.describe();
}

TEST(NoPath, TheErrorNamesTheMapsEdgeWhenTheWayWouldLeaveTheMap) {
  // The wall's doorway is a notch 0.6 m wide at the map's edge (y up to 2.0): open beyond,
  // but there the map ends.
  const CeilingScene scene(twoRooms(1.4, 2.5));
  const planner::Blockage blockage = blockageAcrossTheWall(scene);
  EXPECT_EQ(blockage.rule, planner::BlockingRule::MapEdge) << blockage.describe();
  EXPECT_NEAR(blockage.position_m.x(), 0.1, 0.1) << blockage.describe();
  EXPECT_GT(blockage.position_m.y(), 1.4) << blockage.describe();
}

// The goal inside a vault walled on every side, away from the start: there is no gap to name,
// so the error says that the goal is enclosed and where, never a place the search made up.
TEST(NoPath, TheErrorSaysTheGoalIsEnclosedInASealedVault) {
  const CeilingScene scene(analyticMap({-2.0, -2.0, 0.0}, {2.2, 2.0, 2.8}, 0.1, [](const Eigen::Vector3d& c) {
    if (c.z() < 0.2 || c.z() > 2.4) return CellState::Occupied;
    const bool vault = c.x() > 0.2 && c.x() < 2.0 && c.y() > -0.2 && c.y() < 1.8;
    const bool inside = c.x() > 0.4 && c.x() < 1.8 && c.y() > 0.0 && c.y() < 1.6;
    return vault && !inside ? CellState::Occupied : CellState::Free;
  }));
  const Eigen::Vector3d goal(1.1, 0.8, 1.2);
  planner::LatticePlanner lattice(scene.planner.spaceInformation());
  EXPECT_EQ(solveOnce(lattice, scene.planner, kStart, goal).status, ompl::base::PlannerStatus::ABORT);
  const std::optional<planner::Blockage> blockage = lattice.lastBlockage();
  ASSERT_TRUE(blockage);
  const std::string text = blockage->describe();
  EXPECT_NE(text.find("the goal at (1.10, 0.80, 1.20) is enclosed"), std::string::npos) << text;
  EXPECT_EQ(text.find("(0.00, 0.00, 0.00)"), std::string::npos) << text;

  planner::PlanRequest request = acrossTheWall(planner::referencePlannerName());
  request.goal_m = goal;
  try {
    scene.planner.plan(request);
    ADD_FAILURE() << "a path into the sealed vault";
  } catch (const ceilplan::NoPathError& e) {
    EXPECT_NE(std::string(e.what()).find("is enclosed"), std::string::npos) << e.what();
  }
  // From inside the vault out, the start is the one enclosed.
  EXPECT_EQ(solveOnce(lattice, scene.planner, goal, kStart).status, ompl::base::PlannerStatus::ABORT);
  ASSERT_TRUE(lattice.lastBlockage());
  EXPECT_NE(lattice.lastBlockage()->describe().find("the start at (1.10, 0.80, 1.20) is enclosed"), std::string::npos)
      << lattice.lastBlockage()->describe();
}

}  // namespace
}  // namespace ceilplan::testing
