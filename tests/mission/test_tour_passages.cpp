// Tours complete where the map is passable: a doorway one voxel wider than the vehicle, which
// no node of the tour's 0.4 m roadmap fits, is found by the default leg planner; and targets
// seen from the same viewpoint are toured, the leg between them flown as no flight.

#include "analytic_maps.hpp"

#include "ceilplan/mission/tour_planner.hpp"
#include "ceilplan/planner/planner_factory.hpp"

#include <gtest/gtest.h>

namespace ceilplan::mission {
namespace {

using testing::CellState;

// Two rooms at 0.1 m, floor top 0.2 m, ceiling underside 2.4 m, joined through a 0.2 m wall at
// x [0, 0.2) by a doorway from y = 0.4 to 0.4 + width, floor to ceiling.
environment::OccupancyMap twoRooms(double width_m) {
  return testing::analyticMap({-2.0, -2.0, 0.0}, {2.2, 2.0, 2.8}, 0.1, [=](const Eigen::Vector3d& c) {
    if (c.z() < 0.2 || c.z() > 2.4) return CellState::Occupied;
    if (c.x() > 0.0 && c.x() < 0.2) return c.y() > 0.4 && c.y() < 0.4 + width_m ? CellState::Free : CellState::Occupied;
    return CellState::Free;
  });
}

InspectionTarget target(const std::string& name, const Eigen::Vector3d& point_m) {
  InspectionTarget t;
  t.name = name;
  t.point_m = point_m;
  t.dwell_s = 10.0;
  return t;
}

// Home in the left room, ceiling targets in both.
Mission acrossTheDoorway() {
  Mission mission;
  mission.home_m = {-1.2, -1.0, 0.8};
  mission.targets = {target("left", {-1.0, 1.0, 2.4}), target("right_near", {1.2, -1.0, 2.4}),
                     target("right_far", {1.4, 1.2, 2.4})};
  return mission;
}

PlanningContext contextFor(environment::OccupancyMap map) {
  return PlanningContext(std::move(map), Vehicle::defaultQuad(), BatterySpec{}, PlanningOptions{});
}

// Whether a path crosses the wall's middle plane (x = 0.1) in the doorway, and only there.
bool crossesOnlyThroughTheDoorway(const std::vector<Eigen::Vector3d>& path, double width_m) {
  bool crossed = false;
  for (std::size_t k = 1; k < path.size(); ++k) {
    const Eigen::Vector3d &a = path[k - 1], &b = path[k];
    if ((a.x() < 0.1) == (b.x() < 0.1)) continue;
    const Eigen::Vector3d crossing = a + (b - a) * ((0.1 - a.x()) / (b.x() - a.x()));
    if (crossing.y() <= 0.4 || crossing.y() >= 0.4 + width_m) return false;
    crossed = true;
  }
  return crossed;
}

class TourThroughADoorway : public ::testing::TestWithParam<double> {};

// 1.0 m: the vehicle's 0.92 m with its margins, rounded up to whole voxels; 1.1 m: one voxel more.
TEST_P(TourThroughADoorway, TheDefaultLegPlannerFindsItInBothModes) {
  const double width_m = GetParam();
  const PlanningContext context = contextFor(twoRooms(width_m));
  // No node of the tour's 0.4 m lattice fits in the doorway: only refinement finds it.
  const environment::GridFrame& frame = context.environment().grid().frame();
  for (int k = 0; k < frame.size()[2]; k += 4)
    for (int j = 0; j < frame.size()[1]; j += 4)
      for (int i = 0; i < frame.size()[0]; i += 4) {
        const Eigen::Vector3d p(frame.centreOf(0, i), frame.centreOf(1, j), frame.centreOf(2, k));
        if (std::abs(p.x() - 0.1) < 0.1) {
          ASSERT_FALSE(context.baseRules().isStateValid(p)) << p.transpose();
        }
      }
  const Mission mission = acrossTheDoorway();
  TourOptions options;
  ASSERT_EQ(options.planner, planner::defaultTourPlannerName());
  ASSERT_EQ(options.lattice_spacing_m, 0.4);
  for (const FlightMode mode : {FlightMode::Ceiling, FlightMode::Free}) {
    const TourResult tour = planTour(mission, context, mode, options);
    const std::string name = flightModeName(mode);
    ASSERT_EQ(tour.plan.sorties.size(), 1u) << name;
    EXPECT_EQ(tour.plan.sorties[0].targets.size(), 3u) << name;
    // Every leg flown between the rooms goes through the doorway, and passes the dense re-check.
    int crossings = 0;
    for (const SortieLeg& leg : tour.plan.sorties[0].legs) {
      const std::vector<Eigen::Vector3d>& path = tour.legs[leg.from][leg.to].waypoints;
      EXPECT_FALSE(context.baseRules().checkPathDensely(path)) << name;
      if ((path.front().x() < 0.1) != (path.back().x() < 0.1)) {
        ++crossings;
        EXPECT_TRUE(crossesOnlyThroughTheDoorway(path, width_m))
            << name << ": " << tour.names[leg.from] << " -> " << tour.names[leg.to];
      }
    }
    EXPECT_EQ(crossings, 2) << name;  // there and back
  }
}

INSTANTIATE_TEST_SUITE_P(Widths, TourThroughADoorway, ::testing::Values(1.0, 1.1));

TEST(TourWithSharedViewpoints, TargetsSeenFromOnePlaceAreToured) {
  // Two targets at one point (inspected twice, for two dwells) share their viewpoint in both modes.
  Mission mission = acrossTheDoorway();
  mission.targets.push_back(target("left_again", mission.targets[0].point_m));
  mission.targets.back().dwell_s = 5.0;
  const PlanningContext context = contextFor(twoRooms(1.1));
  for (const FlightMode mode : {FlightMode::Ceiling, FlightMode::Free}) {
    const std::string name = flightModeName(mode);
    const TourResult tour = planTour(mission, context, mode);
    ASSERT_EQ(tour.stops.size(), 4u);
    EXPECT_EQ(tour.stops[0].viewpoint.position_m, tour.stops[3].viewpoint.position_m) << name;
    const TourLeg& between = tour.legs[1][4];
    EXPECT_EQ(between.evaluation.length_m, 0.0) << name;
    EXPECT_EQ(between.evaluation.charge_ah, 0.0) << name;
    // Both visited, and both dwells flown: 10 s and 5 s of hovering there.
    ASSERT_EQ(tour.plan.sorties.size(), 1u) << name;
    EXPECT_EQ(tour.plan.sorties[0].targets.size(), 4u) << name;
    double dwell_s = 0.0;
    for (const SortieRecord& sortie : tour.record.sorties)
      for (std::size_t i = 1; i < sortie.samples.size(); ++i)
        if (sortie.phases[i] == FlightPhase::Dwell && sortie.phases[i - 1] == FlightPhase::Dwell &&
            sortie.steps[i] == sortie.steps[i - 1])
          dwell_s += sortie.samples[i].t_s - sortie.samples[i - 1].t_s;
    EXPECT_NEAR(dwell_s, 10.0 + 10.0 + 10.0 + 5.0, 1e-6) << name;
  }
}

}  // namespace
}  // namespace ceilplan::mission
