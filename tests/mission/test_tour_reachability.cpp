// Stops where a route from home reaches them: a target seen both from the hall and, through a
// slot narrower than the vehicle, from a closet no route enters is inspected from the hall,
// although hovering under the closet's low ceiling would draw less (as a fine scan's recess
// between ceiling lamps did on geb079 at 0.02 m).

#include "analytic_maps.hpp"

#include "ceilplan/mission/tour_planner.hpp"
#include "ceilplan/planner/reachable_space.hpp"

#include <gtest/gtest.h>

namespace ceilplan::mission {
namespace {

using testing::CellState;

// At 0.1 m: a hall (x < 0.8, floor top 0.2 m, ceiling underside 2.8 m) and, behind a wall at
// x [0.8, 1.0), a closet x [1.0, 2.2) x y (-1, 1) under a low ceiling at 2.0 m. The wall has
// a slot |y| < 0.2, z (1.0, 2.0): 0.4 m wide, where the vehicle with its margins is 0.92 m.
environment::OccupancyMap hallAndClosetBehindASlot() {
  return testing::analyticMap({-3.0, -2.0, 0.0}, {2.6, 2.0, 3.0}, 0.1, [](const Eigen::Vector3d& c) {
    if (c.z() < 0.2 || c.z() > 2.8) return CellState::Occupied;
    if (c.x() < 0.8) return CellState::Free;
    if (c.x() < 1.0) return std::abs(c.y()) < 0.2 && c.z() > 1.0 && c.z() < 2.0 ? CellState::Free : CellState::Occupied;
    return c.x() < 2.2 && std::abs(c.y()) < 1.0 && c.z() < 2.0 ? CellState::Free : CellState::Occupied;
  });
}

const Eigen::Vector3d kHome(-2.0, 0.0, 1.2);

bool inTheCloset(const Eigen::Vector3d& p) { return p.x() > 1.0; }

InspectionTarget closetCeiling() {
  InspectionTarget target;
  target.name = "closet_ceiling";
  target.point_m = {1.6, 0.0, 2.0};
  target.dwell_s = 10.0;
  return target;
}

PlanningContext closetContext() {
  return PlanningContext(hallAndClosetBehindASlot(), Vehicle::defaultQuad(), BatterySpec{}, PlanningOptions{});
}

TEST(ReachableViewpoints, TheHallIsReachedAndTheClosetBehindTheSlotIsNot) {
  const PlanningContext context = closetContext();
  const planner::ReachableSpace space(context.baseRules(), kHome, 0.4);
  EXPECT_GT(space.reachedNodeCount(), 0u);
  EXPECT_TRUE(space.reaches({0.2, 0.0, 1.6}));
  EXPECT_TRUE(space.reaches({-2.5, 1.4, 2.4}));
  const Eigen::Vector3d in_the_closet(1.6, 0.0, 1.5);
  ASSERT_TRUE(context.baseRules().isStateValid(in_the_closet));  // the closet holds the vehicle
  EXPECT_FALSE(space.reaches(in_the_closet));
  EXPECT_FALSE(space.reaches({0.9, 0.0, 1.5}));   // in the slot: not a valid state
  EXPECT_FALSE(space.reaches({10.0, 0.0, 1.5}));  // outside the map
}

TEST(ReachableViewpoints, TheCheapestViewpointIsInTheClosetAndTheReachableOneInTheHall) {
  const PlanningContext context = closetContext();
  const planner::ReachableSpace space(context.baseRules(), kHome, 0.4);
  ViewpointOptions options;
  const Viewpoint anywhere = chooseViewpoint(closetCeiling(), context.environment(), context.energy(), options);
  EXPECT_TRUE(inTheCloset(anywhere.position_m)) << anywhere.position_m.transpose();

  options.reachable = [&space](const Eigen::Vector3d& p) { return space.reaches(p); };
  const Viewpoint reached = chooseViewpoint(closetCeiling(), context.environment(), context.energy(), options);
  EXPECT_TRUE(reached.reachable);
  EXPECT_FALSE(inTheCloset(reached.position_m)) << reached.position_m.transpose();
  EXPECT_TRUE(space.reaches(reached.position_m));
  EXPECT_GT(reached.dwell_current_a, anywhere.dwell_current_a);  // the closet's low ceiling would have helped

  // Where no position is reachable, the best of all is kept and says so.
  options.reachable = [](const Eigen::Vector3d&) { return false; };
  const Viewpoint fallback = chooseViewpoint(closetCeiling(), context.environment(), context.energy(), options);
  EXPECT_FALSE(fallback.reachable);
  EXPECT_EQ(fallback.position_m, anywhere.position_m);
}

TEST(ReachableViewpoints, ATourInspectsTheClosetCeilingThroughTheSlotInBothModes) {
  const PlanningContext context = closetContext();
  Mission mission;
  mission.home_m = kHome;
  mission.targets = {closetCeiling()};
  for (const FlightMode mode : {FlightMode::Ceiling, FlightMode::Free}) {
    const TourResult tour = planTour(mission, context, mode, TourOptions{});
    ASSERT_EQ(tour.stops.size(), 1u);
    // Ceiling mode first chose the closet, and chose again; free mode's standoff kept it in the hall.
    EXPECT_EQ(tour.stops_rechosen, mode == FlightMode::Ceiling) << flightModeName(mode);
    EXPECT_TRUE(tour.stops[0].viewpoint.reachable) << flightModeName(mode);
    EXPECT_FALSE(inTheCloset(tour.stops[0].viewpoint.position_m)) << flightModeName(mode);
    for (const SortieRecord& sortie : tour.record.sorties)
      for (const planner::PathSample& sample : sortie.samples) {
        EXPECT_FALSE(inTheCloset(sample.position_m)) << flightModeName(mode);
      }
  }
}

}  // namespace
}  // namespace ceilplan::mission
