// The tours' roadmap on the shipped bridge (maps/bridge.yaml, 0.1 m voxels): its searches cost a
// lattice edge only when they still need it (lazily, under a lower bound of its cost), and route
// to the bit as searches over the lattice with every edge costed do.

#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/mission/planning_context.hpp"
#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/lattice_roadmap.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace ceilplan::mission {
namespace {

const std::filesystem::path kBridge = std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/bridge.yaml";

// Home, and stops under the deck at both ends and in the middle of the 48 m bridge.
const std::vector<Eigen::Vector3d> kPlaces{
    {-4.0, 0.0, 0.5}, {1.9, 2.525, 5.91}, {21.9, -0.275, 5.91}, {45.725, 2.7, 5.91}, {41.725, -2.9, 5.91}};

planner::LatticeSettings tourLattice() {
  planner::LatticeSettings settings;
  settings.spacing_m = 0.8;  // coarser than a tour's 0.4 m: the whole lattice is costed below
  settings.workers = 2;
  return settings;
}

TEST(ShippedRoadmap, LazySearchesRouteOnTheBridgeAsSearchesOverEveryEdgeDo) {
  const Mission mission = io::readMission(kBridge);
  const PlanningContext context(mission);
  const PlanningContext::Mode ceiling = context.mode(FlightMode::Ceiling);
  for (const Eigen::Vector3d& place : kPlaces) ASSERT_TRUE(ceiling.rules->isStateValid(place)) << place.transpose();
  const planner::FlightPlanner planner(*ceiling.rules, *ceiling.model, context.objective(kPlaces[0], kPlaces[3]));
  planner::LatticeRoadmap lazy(planner.spaceInformation(), tourLattice());
  planner::LatticeRoadmap whole(planner.spaceInformation(), tourLattice());
  lazy.build(planner.objective(), kPlaces);
  whole.build(planner.objective(), kPlaces);
  whole.completeGraph();

  // One search from home to the far end of the bridge leaves most edges uncosted.
  const auto far_end = lazy.routesFrom(0, {3});
  ASSERT_TRUE(far_end[3]);
  EXPECT_LT(lazy.edgeCount(), whole.edgeCount() * 6 / 10);
  EXPECT_EQ(far_end[3]->waypoints, whole.routesFrom(0, {3})[3]->waypoints);
  EXPECT_EQ(far_end[3]->cost, whole.routesFrom(0, {3})[3]->cost);

  const int places = static_cast<int>(kPlaces.size());
  for (int from = 0; from < places; ++from) {
    const auto routes = lazy.routesFrom(from), expected = whole.routesFrom(from);
    for (int to = 0; to < places; ++to) {
      ASSERT_EQ(routes[to].has_value(), to != from) << from << " -> " << to;
      if (to == from) continue;
      EXPECT_EQ(routes[to]->cost, expected[to]->cost) << from << " -> " << to;
      EXPECT_EQ(routes[to]->waypoints, expected[to]->waypoints) << from << " -> " << to;
    }
  }
  EXPECT_LE(lazy.edgeCount(), whole.edgeCount());
}

}  // namespace
}  // namespace ceilplan::mission
