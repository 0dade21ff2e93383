// Viewpoints: in ceiling mode the vehicle hugs the surface above the target (least dwell
// current), in free mode it keeps the conventional standoff where it fits and takes the nearest
// such position, else the largest standoff that fits; every viewpoint is valid under the same
// rules in both modes, inside the standoff range and sees its target.

#include "ceilplan/mission/viewpoint.hpp"

#include "analytic_maps.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/paper_quad.hpp"
#include "ceilplan/planner/standoff.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace ceilplan::mission {
namespace {

using environment::Environment;

const energy::EnergyModel& paperQuad() {
  static const energy::EnergyModel model(energy::paperQuadParameters());
  return model;
}

// The airframe's bounding sphere, which free mode keeps the standoff from.
const double kAirframeRadiusM = std::hypot(0.36, 0.12);

ViewpointOptions freeMode() {
  ViewpointOptions options;
  options.mode = FlightMode::Free;
  options.standoff_m = 1.0;
  return options;
}

// A 4 x 4 m room with a flat ceiling at 3 m (floor top at 0.2 m).
struct FlatCeiling {
  environment::OccupancyMap map = testing::room([](double, double) { return 3.0; });
  Environment ceiling{map, testing::quad()};
};

const FlatCeiling& flat() {
  static const FlatCeiling scene;
  return scene;
}

InspectionTarget ceilingTarget() { return {"ceiling_centre", {0.05, 0.05, 3.0}, 0.3, 1.5, 60.0}; }

void expectUsable(const Viewpoint& viewpoint, const InspectionTarget& target, const Environment& environment) {
  EXPECT_TRUE(environment.isStateValid(viewpoint.position_m));
  EXPECT_GE(viewpoint.distance_m, target.standoff_min_m - 1e-9);
  EXPECT_LE(viewpoint.distance_m, target.standoff_max_m + 1e-9);
  EXPECT_NEAR(viewpoint.distance_m, (viewpoint.position_m - target.point_m).norm(), 1e-12);
  EXPECT_NEAR(viewpoint.dwell_charge_ah, viewpoint.dwell_current_a * target.dwell_s / 3600, 1e-12);
}

TEST(Viewpoint, CeilingModeHugsTheSurfaceAbove) {
  const InspectionTarget target = ceilingTarget();
  const Viewpoint viewpoint = chooseViewpoint(target, flat().ceiling, paperQuad());
  expectUsable(viewpoint, target, flat().ceiling);
  // Top of the airframe 0.06 m and its margin 0.02 m right under the ceiling: the rotor plane
  // (0.03 m above the body centre) 0.05 m below it.
  EXPECT_NEAR(viewpoint.ceiling_gap_m, 0.05, 1e-6);
  EXPECT_LT(viewpoint.dwell_current_a, 8.5);  // the paper: 8.0 A within 10 cm, 9.5 A in free air
  // Straight below at the nearest standoff draws more.
  EXPECT_LT(viewpoint.dwell_current_a, hoverCurrentA(flat().ceiling, paperQuad(), {0.05, 0.05, 2.7}, 0.65));
}

// Far from any ceiling, ceiling mode's least current is the ground's: a target on a wall 1 m up
// is inspected from low down (ground effect under the rotors), not from the nearest position
// straight out from the wall.
TEST(Viewpoint, CeilingModeWeighsTheGroundBelowToo) {
  const environment::OccupancyMap map = testing::analyticMap({-2, -2, 0}, {2, 2, 4}, 0.1, [](const Eigen::Vector3d& c) {
    return c.z() < 0.2 || c.x() > 1.0 ? environment::CellState::Occupied : environment::CellState::Free;
  });
  const Environment walled(map, testing::quad());
  const InspectionTarget target{"wall", {1.0, 0.05, 1.0}, 0.3, 1.5, 60.0};
  const Viewpoint viewpoint = chooseViewpoint(target, walled, paperQuad());
  expectUsable(viewpoint, target, walled);
  EXPECT_LT(viewpoint.position_m.z(), 0.7) << "viewpoint at " << viewpoint.position_m.transpose();
  const Eigen::Vector3d nearest(0.5, 0.05, 1.0);
  ASSERT_TRUE(walled.isStateValid(nearest));
  EXPECT_LT(viewpoint.dwell_current_a, hoverCurrentA(walled, paperQuad(), nearest, ViewpointOptions{}.soc) - 0.01);
}

TEST(Viewpoint, FreeModeKeepsTheConventionalStandoffAndTakesTheNearestPosition) {
  const InspectionTarget target = ceilingTarget();
  const Viewpoint viewpoint = chooseViewpoint(target, flat().ceiling, paperQuad(), freeMode());
  expectUsable(viewpoint, target, flat().ceiling);
  // 1 m from the ceiling to the airframe's bounding sphere: the nearest is straight below.
  EXPECT_GE(planner::standoffAt(flat().ceiling, viewpoint.position_m), 1.0 - 1e-3);
  EXPECT_NEAR(viewpoint.distance_m, 1.0 + kAirframeRadiusM, 0.025 + 1e-9);
  EXPECT_NEAR(viewpoint.position_m.x(), target.point_m.x(), 0.05);
  EXPECT_NEAR(viewpoint.position_m.y(), target.point_m.y(), 0.05);
  // Scored with the full model: out of the ceiling's reach, it draws more than ceiling mode.
  EXPECT_GT(viewpoint.dwell_current_a, chooseViewpoint(target, flat().ceiling, paperQuad()).dwell_current_a + 1.0);
}

TEST(Viewpoint, FreeModeTakesTheLargestStandoffThatFitsWhereTheConventionalOneDoesNot) {
  // A room 1.6 m high: nowhere is the airframe 1 m from both floor and ceiling. The largest
  // standoff is halfway up, 0.8 m from each, less the airframe's bounding sphere.
  const environment::OccupancyMap low = testing::room([](double, double) { return 1.8; });
  const Environment environment(low, testing::quad());
  const InspectionTarget target{"low_ceiling", {0.05, 0.05, 1.8}, 0.3, 1.5, 30.0};
  const Viewpoint viewpoint = chooseViewpoint(target, environment, paperQuad(), freeMode());
  expectUsable(viewpoint, target, environment);
  EXPECT_NEAR(planner::standoffAt(environment, viewpoint.position_m), 0.8 - kAirframeRadiusM, 0.01);
  EXPECT_NEAR(viewpoint.position_m.z(), 1.0, 0.02);
  EXPECT_NEAR(viewpoint.position_m.x(), target.point_m.x(), 0.05);
}

TEST(Viewpoint, FindsANarrowStandoffShellBetweenLatticePoints) {
  InspectionTarget target = ceilingTarget();
  target.standoff_min_m = 1.0;
  target.standoff_max_m = 1.08;  // thinner than a voxel
  expectUsable(chooseViewpoint(target, flat().ceiling, paperQuad(), freeMode()), target, flat().ceiling);
}

TEST(Viewpoint, StaysOnTheTargetsSideOfTheSurface) {
  // A point on the floor, looked at from above: the viewpoint must be in the room, and low
  // hovering is not cheaper than ground effect allows, but the ceiling is out of the range.
  const InspectionTarget target{"floor_mark", {0.05, 0.05, 0.2}, 0.5, 1.0, 10.0};
  const Viewpoint viewpoint = chooseViewpoint(target, flat().ceiling, paperQuad());
  expectUsable(viewpoint, target, flat().ceiling);
  EXPECT_GT(viewpoint.position_m.z(), 0.2);
}

TEST(Viewpoint, NamesATargetWithNoViewpoint) {
  // Inside the ceiling slab: no position in range sees it through free space.
  const InspectionTarget buried{"buried_bolt", {0.05, 0.05, 3.2}, 0.3, 0.35, 10.0};
  try {
    chooseViewpoint(buried, flat().ceiling, paperQuad());
    FAIL() << "expected an error";
  } catch (const ceilplan::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("target 'buried_bolt' at (0.05, 0.05, 3.20): no valid viewpoint"),
              std::string::npos)
        << e.what();
  }
  const InspectionTarget outside{"far_away", {50, 0, 1}, 0.3, 1.5, 10.0};
  try {
    chooseViewpoint(outside, flat().ceiling, paperQuad());
    FAIL() << "expected an error";
  } catch (const ceilplan::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("target 'far_away' at (50.00, 0.00, 1.00) lies outside the map"),
              std::string::npos)
        << e.what();
  }
  InspectionTarget inverted = ceilingTarget();
  std::swap(inverted.standoff_min_m, inverted.standoff_max_m);
  EXPECT_THROW(chooseViewpoint(inverted, flat().ceiling, paperQuad()), ceilplan::InputError);
}

// The shipped bridge and its mission's targets (maps/bridge.yaml).
TEST(Viewpoint, BridgeTargetsGetViewpointsAndDeckBaysAreHugged) {
  const environment::OccupancyMap map =
      environment::OccupancyMap::load(std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/bridge.bt");
  const Environment environment(map, testing::quad());
  const std::vector<InspectionTarget> targets = {
      {"deck_bay_06", {6.0, 0.0, 6.0}, 0.3, 1.5, 20},      {"deck_bay_30", {30.0, 0.0, 6.0}, 0.3, 1.5, 20},
      {"girder_2_at_10", {10.0, -1.4, 5.2}, 0.3, 1.5, 15}, {"cross_frame_08", {8.0, 0.0, 5.4}, 0.3, 1.5, 10},
      {"pier_cap_16", {16.0, 0.0, 4.2}, 0.3, 1.5, 30},     {"girder_1_at_42", {42.0, -4.2, 5.0}, 0.3, 1.5, 15}};
  for (const InspectionTarget& target : targets) {
    const Viewpoint viewpoint = chooseViewpoint(target, environment, paperQuad());
    expectUsable(viewpoint, target, environment);
    EXPECT_LT(viewpoint.position_m.z(), target.point_m.z()) << target.name;
    EXPECT_NEAR(viewpoint.ceiling_gap_m, 0.05, 1e-6) << target.name << ": not hugging";
    EXPECT_LT(viewpoint.dwell_current_a, 8.5) << target.name;
  }
  // Deck bays are hugged right beside the target: the underside is flat and fully covers the rotors.
  const Viewpoint deck = chooseViewpoint(targets[0], environment, paperQuad());
  EXPECT_NEAR(deck.distance_m, 0.3, 0.03);
  EXPECT_NEAR(deck.dwell_current_a, energy::kPaperCeilingCurrentA, 1e-3);

  // Free mode, 1 m from every structure: under a girder's bottom flange, in free air.
  const Viewpoint girder = chooseViewpoint(targets[2], environment, paperQuad(), freeMode());
  expectUsable(girder, targets[2], environment);
  EXPECT_GE(planner::standoffAt(environment, girder.position_m), 1.0 - 1e-3);
  EXPECT_NEAR(girder.distance_m, 1.0 + kAirframeRadiusM, 0.03);
  EXPECT_NEAR(girder.dwell_current_a, energy::kPaperFreeAirCurrentA, 1e-3);
  // A deck bay between girders 2.8 m apart: 1 m from the deck and the girders fits within the
  // target's 1.5 m, below the deck.
  const Viewpoint bay = chooseViewpoint(targets[0], environment, paperQuad(), freeMode());
  expectUsable(bay, targets[0], environment);
  EXPECT_GE(planner::standoffAt(environment, bay.position_m), 1.0 - 1e-3);
  EXPECT_LT(bay.position_m.z(), targets[0].point_m.z() - 1.0);
}

}  // namespace
}  // namespace ceilplan::mission
