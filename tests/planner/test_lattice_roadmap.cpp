// LatticeRoadmap: one roadmap, one Dijkstra search per place, and an OMPL planner answering
// one query after another on the same roadmap. Its routes cost what the lattice A* finds
// between the same places, they do not depend on the thread count, and in free mode a route
// keeps the conventional standoff on its way, away from its own start and goal.

#include "planner_fixtures.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/parallel_for.hpp"
#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/lattice_planner.hpp"
#include "ceilplan/planner/lattice_roadmap.hpp"
#include "ceilplan/planner/planner_factory.hpp"
#include "ceilplan/planner/standoff.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

namespace ceilplan::testing {
namespace {

struct BeamRoom : CeilingScene {
  BeamRoom() : CeilingScene(beamRoom()) {}
  // Under the ceiling on either side of the beam, and low on the near side.
  std::vector<Eigen::Vector3d> places{{-0.8, -0.3, 1.9}, {1.0, 0.4, 1.9}, {-0.9, 0.5, 0.8}};
};

planner::LatticeSettings spacing(double spacing_m, int workers = 1) {
  planner::LatticeSettings settings;
  settings.spacing_m = spacing_m;
  settings.workers = workers;
  return settings;
}

TEST(LatticeRoadmap, RoutesAcrossTheBeamCostWhatTheLatticeAStarFinds) {
  BeamRoom room;
  planner::LatticeRoadmap roadmap(room.planner.spaceInformation(), spacing(0.3));
  roadmap.build(room.planner.objective(), room.places);
  for (const auto& [from, to] : std::vector<std::pair<int, int>>{{0, 1}, {1, 0}, {2, 1}, {1, 2}}) {
    const auto routes = roadmap.routesFrom(from);
    ASSERT_TRUE(routes[to]) << from << " -> " << to;
    planner::LatticePlanner lattice(room.planner.spaceInformation(), spacing(0.3));
    const Solved found = solveOnce(lattice, room.planner, room.places[from], room.places[to]);
    ASSERT_EQ(found.status, ompl::base::PlannerStatus::EXACT_SOLUTION);
    // Edge costs are stored in single precision.
    EXPECT_NEAR(routes[to]->cost, found.cost, 1e-5 * found.cost) << from << " -> " << to;
    EXPECT_NEAR(room.planner.objective().pathCost(routes[to]->waypoints), routes[to]->cost, 1e-5 * found.cost);
    EXPECT_EQ(routes[to]->waypoints.front(), room.places[from]);
    EXPECT_EQ(routes[to]->waypoints.back(), room.places[to]);
    EXPECT_FALSE(room.rules.checkPathDensely(routes[to]->waypoints)) << from << " -> " << to;
  }
  EXPECT_FALSE(roadmap.routesFrom(0)[0]);  // no route from a place to itself
}

// Places closer together than the lattice spacing join the lattice at the same nodes: the
// search looks up, at each node it closes, the joins into every goal that leave from it. Each
// route still costs what the lattice A* finds for that pair alone, both ways.
TEST(LatticeRoadmap, PlacesSharingTheirJoinNodesAreEachRoutedAsTheLatticeAStarRoutesThemAlone) {
  BeamRoom room;
  std::vector<Eigen::Vector3d> places{room.places[0]};
  for (const double dz : {0.0, -0.07})
    for (const double dy : {-0.07, 0.0, 0.07})
      for (const double dx : {-0.07, 0.07}) places.push_back(room.places[1] + Eigen::Vector3d(dx, dy, dz));
  planner::LatticeRoadmap roadmap(room.planner.spaceInformation(), spacing(0.3));
  roadmap.build(room.planner.objective(), places);
  const auto out = roadmap.routesFrom(0);
  for (int place = 1; place < static_cast<int>(places.size()); ++place)
    for (const auto& [from, to] : std::vector<std::pair<int, int>>{{0, place}, {place, 0}}) {
      const auto route = from == 0 ? out[to] : roadmap.routesFrom(from)[to];
      ASSERT_TRUE(route) << from << " -> " << to;
      planner::LatticePlanner lattice(room.planner.spaceInformation(), spacing(0.3));
      const Solved found = solveOnce(lattice, room.planner, places[from], places[to]);
      ASSERT_EQ(found.status, ompl::base::PlannerStatus::EXACT_SOLUTION) << from << " -> " << to;
      // Edge costs are stored in single precision.
      EXPECT_NEAR(route->cost, found.cost, 1e-5 * found.cost) << from << " -> " << to;
      EXPECT_EQ(route->waypoints.front(), places[from]);
      EXPECT_EQ(route->waypoints.back(), places[to]);
      EXPECT_FALSE(room.rules.checkPathDensely(route->waypoints)) << from << " -> " << to;
    }
}

// A tour of many places asks for a few goals at a time: the search stops once it has reached
// them (A* towards the nearest), and finds the routes the search to every place finds.
TEST(LatticeRoadmap, RoutesToAFewGoalsCostWhatTheSearchToEveryPlaceFinds) {
  BeamRoom room;
  planner::LatticeRoadmap roadmap(room.planner.spaceInformation(), spacing(0.3));
  roadmap.build(room.planner.objective(), room.places);
  for (int from = 0; from < 3; ++from) {
    const auto every = roadmap.routesFrom(from);
    for (const std::vector<int>& goals : std::vector<std::vector<int>>{{0, 1, 2}, {(from + 1) % 3}, {(from + 2) % 3}}) {
      const auto some = roadmap.routesFrom(from, goals);
      for (int to = 0; to < 3; ++to) {
        const bool asked = to != from && std::find(goals.begin(), goals.end(), to) != goals.end();
        ASSERT_EQ(some[to].has_value(), asked) << from << " -> " << to;
        if (!asked) continue;
        // Edge costs are stored in single precision; the order of additions may differ.
        EXPECT_NEAR(some[to]->cost, every[to]->cost, 1e-6 * every[to]->cost) << from << " -> " << to;
        EXPECT_FALSE(room.rules.checkPathDensely(some[to]->waypoints)) << from << " -> " << to;
      }
    }
  }
  EXPECT_THROW(roadmap.routesFrom(0, {3}), ceilplan::InputError);
}

// Like PRM: built on the first query, kept across clearQuery(), each answer what routesFrom
// gives between the same places.
TEST(LatticeRoadmap, AnswersOneQueryAfterAnotherOnTheSameRoadmap) {
  BeamRoom room;
  const ompl::base::PlannerPtr planner =
      planner::makePlanner(planner::defaultTourPlannerName(), room.planner.spaceInformation(), spacing(0.3));
  auto& roadmap = *planner->as<planner::LatticeRoadmap>();
  EXPECT_TRUE(planner::plannerInfo(planner->getName()).multiQuery());
  planner::LatticeRoadmap reference(room.planner.spaceInformation(), spacing(0.3));
  reference.build(room.planner.objective(), room.places);
  for (const auto& [from, to] : std::vector<std::pair<int, int>>{{0, 1}, {2, 1}, {1, 2}}) {
    const Solved solved = solveOnce(roadmap, room.planner, room.places[from], room.places[to]);
    ASSERT_EQ(solved.status, ompl::base::PlannerStatus::EXACT_SOLUTION) << from << " -> " << to;
    EXPECT_TRUE(roadmap.built());
    const auto expected = reference.routesFrom(from)[to];
    ASSERT_TRUE(expected);
    EXPECT_EQ(solved.waypoints, expected->waypoints);
    EXPECT_EQ(solved.cost, expected->cost);
    roadmap.clearQuery();
    EXPECT_TRUE(roadmap.built()) << "clearQuery keeps the roadmap";
  }
  roadmap.clear();
  EXPECT_FALSE(roadmap.built());
}

TEST(LatticeRoadmap, IsTheSameBuiltOnOneThreadOrThree) {
  BeamRoom room;
  planner::LatticeRoadmap a(room.planner.spaceInformation(), spacing(0.2, 1));
  planner::LatticeRoadmap b(room.planner.spaceInformation(), spacing(0.2, 3));
  a.build(room.planner.objective(), room.places);
  b.build(room.planner.objective(), room.places);
  EXPECT_EQ(a.edgeCount(), b.edgeCount());
  for (int from = 0; from < 3; ++from) {
    const auto routes_a = a.routesFrom(from), routes_b = b.routesFrom(from);
    for (int to = 0; to < 3; ++to) {
      ASSERT_EQ(routes_a[to].has_value(), routes_b[to].has_value());
      if (!routes_a[to]) continue;
      EXPECT_EQ(routes_a[to]->cost, routes_b[to]->cost);
      EXPECT_EQ(routes_a[to]->waypoints, routes_b[to]->waypoints);
    }
  }
}

// A 24 m hall with a beam under its ceiling every 2 m and places in its first 6 m. The roadmap
// checks and costs the lattice where its searches go, on any number of threads at once, and
// its routes are those of the lattice checked everywhere, to the bit.
TEST(LatticeRoadmap, ChecksTheLatticeWhereItsSearchesGoAndRoutesAsTheWholeLatticeDoes) {
  const CeilingScene hall(analyticMap({-0.7, -2.7, 0}, {24.7, 2.7, 3.0}, 0.1, [](const Eigen::Vector3d& c) {
    if (c.z() < 0.2 || c.z() > 2.6 || std::abs(c.y()) > 2.5 || c.x() < -0.5 || c.x() > 24.5) return CellState::Occupied;
    if (std::fmod(c.x() + 10.0, 2.0) < 0.2 && c.z() > 2.2) return CellState::Occupied;
    return CellState::Free;
  }));
  const std::vector<Eigen::Vector3d> places{
      {1.1, -1.0, 2.5}, {5.1, 1.0, 2.5}, {3.1, 0.0, 1.0}, {1.1, 1.5, 0.8}, {3.1, -2.0, 2.5}};
  planner::LatticeRoadmap lazy(hall.planner.spaceInformation(), spacing(0.4, 2));
  planner::LatticeRoadmap whole(hall.planner.spaceInformation(), spacing(0.4, 2));
  lazy.build(hall.planner.objective(), places);
  whole.build(hall.planner.objective(), places);
  whole.completeGraph();
  const std::size_t edges_built = lazy.edgeCount();
  std::vector<std::vector<std::optional<planner::RoadmapRoute>>> routes(places.size());
  parallelFor(places.size(), 3, [&](std::size_t from) { routes[from] = lazy.routesFrom(static_cast<int>(from)); });
  for (int from = 0; from < static_cast<int>(places.size()); ++from) {
    const auto expected = whole.routesFrom(from);
    for (int to = 0; to < static_cast<int>(places.size()); ++to) {
      ASSERT_EQ(routes[from][to].has_value(), to != from) << from << " -> " << to;
      if (to == from) continue;
      EXPECT_EQ(routes[from][to]->cost, expected[to]->cost) << from << " -> " << to;
      EXPECT_EQ(routes[from][to]->waypoints, expected[to]->waypoints) << from << " -> " << to;
    }
  }
  // Built: the walk joining the places; searched: the neighbourhood of the places' routes.
  EXPECT_LT(edges_built, lazy.edgeCount());
  EXPECT_LT(lazy.edgeCount(), whole.edgeCount() / 2);
  EXPECT_LT(lazy.validNodeCount(), whole.validNodeCount());
  EXPECT_LT(lazy.memoryBytes(), whole.memoryBytes());
}

// A tour's two modes cost motions differently under the same safety rules: their roadmaps share
// one LatticeValidity, route as each does alone, and check each edge once between them.
TEST(LatticeRoadmap, RoadmapsOfTwoModesShareWhatTheSafetyRulesAllow) {
  BeamRoom room;
  planner::CostModelOptions free_options;
  free_options.proximity_effects = false;
  const planner::FlightCostModel free_model(room.environment, room.energy, free_options);
  const planner::FlightPlanner free_planner(room.rules, free_model, planner::ObjectiveChoice{});
  const std::vector<const planner::FlightPlanner*> modes{&room.planner, &free_planner};
  const auto shared = std::make_shared<const planner::LatticeValidity>(room.rules, 0.2);
  std::size_t checked_alone = 0;
  for (const planner::FlightPlanner* mode : modes) {
    planner::LatticeRoadmap alone(mode->spaceInformation(), spacing(0.2));
    planner::LatticeRoadmap sharing(mode->spaceInformation(), spacing(0.2, 2));
    const auto own = std::make_shared<const planner::LatticeValidity>(room.rules, 0.2);
    alone.build(mode->objective(), room.places, own);
    sharing.build(mode->objective(), room.places, shared);
    for (int from = 0; from < 3; ++from) {
      const auto expected = alone.routesFrom(from), routes = sharing.routesFrom(from);
      for (int to = 0; to < 3; ++to) {
        ASSERT_EQ(routes[to].has_value(), to != from);
        if (to == from) continue;
        EXPECT_EQ(routes[to]->cost, expected[to]->cost) << from << " -> " << to;
        EXPECT_EQ(routes[to]->waypoints, expected[to]->waypoints) << from << " -> " << to;
      }
    }
    checked_alone += own->checkedEdgeCount();
  }
  EXPECT_GT(shared->checkedEdgeCount(), 0u);
  EXPECT_LT(shared->checkedEdgeCount(), checked_alone);
  // Made for other rules (another minimum ceiling gap), or another spacing: refused.
  const planner::SafetyRules other_rules(room.environment, 0.1);
  planner::LatticeRoadmap roadmap(room.planner.spaceInformation(), spacing(0.2));
  EXPECT_THROW(roadmap.build(room.planner.objective(), room.places,
                             std::make_shared<const planner::LatticeValidity>(other_rules, 0.2)),
               ceilplan::InputError);
  EXPECT_THROW(roadmap.build(room.planner.objective(), room.places,
                             std::make_shared<const planner::LatticeValidity>(room.rules, 0.3)),
               ceilplan::InputError);
}

TEST(LatticeRoadmap, SaysNothingOfAPlaceBehindAWall) {
  const CeilingScene scene(analyticMap({-1.2, -1.2, 0}, {1.6, 1.2, 2.4}, 0.1, [](const Eigen::Vector3d& c) {
    if (c.z() < 0.2 || c.z() > 2.0 || (c.x() > 0.2 && c.x() < 0.4)) return CellState::Occupied;
    return CellState::Free;
  }));
  // Right of the wall the vehicle fits in a strip 0.3 m wide.
  planner::LatticeRoadmap roadmap(scene.planner.spaceInformation(), spacing(0.2));
  roadmap.build(scene.planner.objective(), {{-0.6, 0.0, 1.0}, {1.0, 0.0, 1.0}, {-0.5, 0.5, 1.2}});
  const auto routes = roadmap.routesFrom(0);
  EXPECT_FALSE(routes[1]);
  EXPECT_TRUE(routes[2]);
}

TEST(LatticeRoadmap, RefusesBadOptionsAndPlacesOutsideTheMap) {
  BeamRoom room;
  EXPECT_THROW(planner::LatticeRoadmap(room.planner.spaceInformation(), spacing(0.0)), ceilplan::InputError);
  EXPECT_THROW(planner::LatticeRoadmap(room.planner.spaceInformation(), spacing(0.4, 0)), ceilplan::InputError);
  planner::LatticeRoadmap roadmap(room.planner.spaceInformation());
  EXPECT_THROW(roadmap.build(room.planner.objective(), {{9.0, 0.0, 1.0}}), ceilplan::InputError);
  roadmap.build(room.planner.objective(), room.places);
  EXPECT_THROW(roadmap.routesFrom(3), ceilplan::InputError);
}

// A 12 m corridor under a flat ceiling at 3.5 m; three places hugging the ceiling, 5.5 m apart.
// With a 1 m standoff preferred, the route from the first to the last backs off the ceiling and
// passes the middle place with the standoff kept.
TEST(LatticeRoadmap, InFreeModeARouteKeepsTheStandoffPastAnotherPlace) {
  const environment::OccupancyMap map =
      analyticMap({-0.7, -2.7, 0}, {12.7, 2.7, 4.2}, 0.1, [](const Eigen::Vector3d& c) {
        if (c.z() < 0.2 || std::abs(c.y()) > 2.5 || c.x() < -0.5 || c.x() > 12.5) return CellState::Occupied;
        if (c.z() < 3.5) return CellState::Free;
        return c.z() < 3.9 ? CellState::Occupied : CellState::Unknown;
      });
  const environment::Environment environment(map, quad());
  const energy::EnergyModel energy = paperEnergy();
  const std::vector<Eigen::Vector3d> places{{0.5, 0.0, 3.35}, {6.0, 0.0, 3.35}, {11.5, 0.0, 3.35}};
  const planner::SafetyRules rules(environment, 0.05);
  planner::CostModelOptions free_mode;
  free_mode.proximity_effects = false;
  free_mode.standoff_m = 1.0;
  const planner::FlightCostModel model(environment, energy, free_mode);
  const planner::FlightPlanner planner(rules, model, planner::ObjectiveChoice{});
  planner::LatticeRoadmap roadmap(planner.spaceInformation(), spacing(0.3));
  roadmap.build(planner.objective(), places);
  for (const auto& [from, to] : std::vector<std::pair<int, int>>{{0, 2}, {2, 0}}) {
    const auto routes = roadmap.routesFrom(from);
    ASSERT_TRUE(routes[to]) << from << " -> " << to;
    const std::vector<Eigen::Vector3d>& route = routes[to]->waypoints;
    EXPECT_FALSE(rules.checkPathDensely(route));
    // Past the middle place the airframe keeps 1 m, within the lattice's reach of it.
    double least_m = std::numeric_limits<double>::infinity();
    for (std::size_t k = 1; k < route.size(); ++k)
      for (int step = 0; step <= 20; ++step) {
        const Eigen::Vector3d p = route[k - 1] + (route[k] - route[k - 1]) * (step / 20.0);
        if (std::abs(p.x() - 6.0) < 1.5) least_m = std::min(least_m, planner::standoffAt(environment, p));
      }
    EXPECT_GT(least_m, 1.0 - 0.15) << from << " -> " << to;
  }
}

TEST(ParallelFor, RunsEveryIndexOnceAndRethrowsTheFailure) {
  std::vector<std::atomic<int>> runs(100);
  parallelFor(runs.size(), 3, [&](std::size_t i) { ++runs[i]; });
  for (const std::atomic<int>& count : runs) EXPECT_EQ(count.load(), 1);
  try {
    parallelFor(10, 2, [](std::size_t i) {
      if (i == 4) throw std::runtime_error("task 4 failed");
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "task 4 failed");
  }
}

}  // namespace
}  // namespace ceilplan::testing
