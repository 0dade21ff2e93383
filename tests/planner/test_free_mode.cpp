// Free mode as a conventional planner flies it: the same clearance rules as ceiling mode, no
// proximity model, and the conventional standoff kept where it fits, the largest standoff that
// fits where it does not. The output says where the path had to narrow.

#include "planner_fixtures.hpp"

#include "ceilplan/planner/planner_factory.hpp"
#include "ceilplan/planner/standoff.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace ceilplan::testing {
namespace {

// A straight corridor along x at 0.1 m: 1.6 m wide (|y| < 0.8), floor top at 0.2 m, ceiling at
// 2.4 m. Its widest point-to-wall clearance is 0.8 m on the centre line, so the airframe
// (bounding sphere 0.38 m) keeps at most 0.42 m there: a 1 m standoff does not fit anywhere.
environment::OccupancyMap narrowCorridor() {
  return analyticMap({-0.5, -1.0, 0.0}, {8.5, 1.0, 2.6}, 0.1, [](const Eigen::Vector3d& c) {
    if (c.z() < 0.2 || c.z() > 2.4 || std::abs(c.y()) > 0.8 || c.x() < -0.3 || c.x() > 8.3) return CellState::Occupied;
    return CellState::Free;
  });
}

// Free mode's cost: no proximity effects, a 1 m standoff preferred.
planner::CostModelOptions freeModeCost() {
  planner::CostModelOptions options;
  options.proximity_effects = false;
  options.standoff_m = 1.0;
  return options;
}

struct FreeModeScene : PlannerScene {
  explicit FreeModeScene(environment::OccupancyMap scene_map) : PlannerScene(std::move(scene_map), freeModeCost()) {}

  planner::PlanResult plan(const Eigen::Vector3d& start, const Eigen::Vector3d& goal) const {
    planner::PlanRequest request;
    request.start_m = start;
    request.goal_m = goal;
    request.planner = planner::referencePlannerName();
    request.time_limit_s = 120.0;
    return planner.plan(request);
  }
};

// The least standoff over the samples of a path whose x lies in [x_lo, x_hi].
double leastStandoff(const environment::Environment& environment, const std::vector<Eigen::Vector3d>& path, double x_lo,
                     double x_hi) {
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t k = 1; k < path.size(); ++k)
    for (int step = 0; step <= 50; ++step) {
      const Eigen::Vector3d p = path[k - 1] + (path[k] - path[k - 1]) * (step / 50.0);
      if (p.x() >= x_lo && p.x() <= x_hi) least = std::min(least, planner::standoffAt(environment, p));
    }
  return least;
}

TEST(FreeMode, MeasuresTheStandoffFromTheAirframesBoundingSphere) {
  const environment::VehicleGeometry vehicle = quad();
  EXPECT_NEAR(planner::airframeRadius_m(vehicle), std::hypot(0.36, 0.12), 1e-12);
  const FreeModeScene scene(narrowCorridor());
  // On the centre line, 0.8 m from both walls.
  EXPECT_NEAR(planner::standoffAt(scene.environment, {4.05, 0.0, 1.3}), 0.8 - std::hypot(0.36, 0.12), 1e-6);
}

TEST(FreeMode, KeepsTheConventionalStandoffWhereItFits) {
  // Start and goal hug the ceiling of a 5 m wide, 3.3 m high corridor, 5 m apart: in between
  // the route backs off to 1 m from every structure, as a conventional planner flies.
  const FreeModeScene scene(corridor(flatCeiling));
  const double z = bodyHeightUnder(3.5);
  const planner::PlanResult plan = scene.plan({0.5, 0.0, z}, {5.5, 0.0, z});
  EXPECT_FALSE(scene.rules.checkPathDensely(plan.waypoints));
  EXPECT_GT(leastStandoff(scene.environment, plan.waypoints, 2.7, 3.3), 1.0 - 0.02);
  const planner::StandoffReport report = planner::standoffReport(scene.environment, plan.waypoints, 1.0);
  // It narrows only to leave the start and to reach the goal.
  EXPECT_GT(report.narrowed_m, 0.0);
  EXPECT_LT(report.narrowed_m, 0.6 * report.length_m);
  for (const planner::NarrowedSpan& span : report.spans)
    EXPECT_TRUE(span.to_m < 0.4 * report.length_m || span.from_m > 0.6 * report.length_m)
        << span.from_m << " - " << span.to_m << " of " << report.length_m;
}

TEST(FreeMode, TakesTheLargestStandoffThatFitsWhereTheConventionalOneDoesNot) {
  // From low near one wall to high near the other: the straight line would graze both walls;
  // the route flies the middle of the corridor, where the airframe keeps the most it can.
  const FreeModeScene scene(narrowCorridor());
  const Eigen::Vector3d start(0.5, -0.3, 0.8), goal(7.5, 0.3, 1.8);
  const planner::PlanResult plan = scene.plan(start, goal);
  EXPECT_FALSE(scene.rules.checkPathDensely(plan.waypoints));
  const double most_m = planner::standoffAt(scene.environment, {4.05, 0.0, 1.3});  // 0.42 m
  EXPECT_GT(leastStandoff(scene.environment, plan.waypoints, 2.5, 5.5), most_m - 0.05);
  // The straight line keeps less: the preference pulled the route to the middle.
  EXPECT_LT(leastStandoff(scene.environment, {start, goal}, 2.5, 5.5), most_m - 0.1);
  // And the output says the whole way was narrowed, and how far.
  const planner::StandoffReport report = planner::standoffReport(scene.environment, plan.waypoints, 1.0);
  EXPECT_NEAR(report.narrowed_m, report.length_m, 1e-9);
  ASSERT_EQ(report.spans.size(), 1u);
  EXPECT_LT(report.min_standoff_m, most_m);
}

TEST(FreeMode, PlansUnderTheSameRulesAsCeilingMode) {
  // Ceiling mode's rules accept the free-mode route, and a viewpoint hugging the ceiling is a
  // valid start in both modes: the standoff is a preference, not a rule.
  const FreeModeScene scene(corridor(flatCeiling));
  const CeilingScene ceiling(corridor(flatCeiling));
  const Eigen::Vector3d hugging(0.5, 0.0, bodyHeightUnder(3.5));
  EXPECT_TRUE(scene.rules.isStateValid(hugging));
  EXPECT_TRUE(ceiling.rules.isStateValid(hugging));
  const planner::PlanResult plan = scene.plan(hugging, {5.5, 0.0, 1.0});
  EXPECT_FALSE(ceiling.rules.checkPathDensely(plan.waypoints));
}

TEST(FreeMode, TheStandoffPreferenceIsRefusedWhenNotAPositiveNumber) {
  const CeilingScene scene(beamRoom());
  planner::CostModelOptions options;
  options.standoff_m = -1.0;
  EXPECT_THROW(planner::FlightCostModel(scene.environment, scene.energy, options), ceilplan::InputError);
  options.standoff_m = 1.0;
  options.standoff_weight = 0.0;
  EXPECT_THROW(planner::FlightCostModel(scene.environment, scene.energy, options), ceilplan::InputError);
}

}  // namespace
}  // namespace ceilplan::testing
