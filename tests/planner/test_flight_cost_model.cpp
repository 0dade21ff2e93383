// FlightCostModel: speeds, durations and charge of straight motions.

#include "ceilplan/core/error.hpp"

#include "planner_fixtures.hpp"

#include <gtest/gtest.h>

namespace ceilplan::testing {
namespace {

using planner::CostModelOptions;
using planner::FlightCostModel;

struct CorridorModels {
  environment::OccupancyMap map = corridor(flatCeiling);
  environment::Environment environment{map, quad()};
  energy::EnergyModel energy = paperEnergy();
};

TEST(FlightCostModel, LevelFlightInFreeAirTakesLengthOverCruiseSpeed) {
  CorridorModels scene;
  const FlightCostModel model(scene.environment, scene.energy, CostModelOptions{});
  const Eigen::Vector3d a(1.0, 0.0, 2.0), b(5.0, 0.0, 2.0);
  const planner::MotionTotals totals = model.integrate(a, b);
  EXPECT_DOUBLE_EQ(totals.length_m, 4.0);
  EXPECT_NEAR(totals.duration_s, 4.0 / 2.0, 1e-12);
  energy::FlightCondition cruise;
  cruise.speed_m_s = 2.0;
  cruise.soc = 0.95;
  const double free_air_a = scene.energy.currentA(energy::kNoSurface, 0.0, cruise);
  EXPECT_NEAR(totals.charge_ah, free_air_a * 2.0 / 3600.0, 1e-9);
}

TEST(FlightCostModel, BothWaysAtOnceIsEachWayOnItsOwn) {
  CorridorModels scene;
  const FlightCostModel model(scene.environment, scene.energy, CostModelOptions{});
  // Climbing towards the ceiling: the two directions differ in speed and current.
  const Eigen::Vector3d a(1.0, 0.3, 1.2), b(2.3, -0.4, 3.3);
  const auto [forth, back] =
      model.integrateBothWays(a, b, [&](const Eigen::Vector3d& p) { return model.conditionsAt(p); });
  const planner::MotionTotals up = model.integrate(a, b), down = model.integrate(b, a);
  EXPECT_NE(up.charge_ah, down.charge_ah);
  EXPECT_NEAR(forth.charge_ah, up.charge_ah, 1e-12 * up.charge_ah);
  EXPECT_NEAR(forth.duration_s, up.duration_s, 1e-12 * up.duration_s);
  EXPECT_NEAR(back.charge_ah, down.charge_ah, 1e-12 * down.charge_ah);
  EXPECT_NEAR(back.duration_s, down.duration_s, 1e-12 * down.duration_s);
  EXPECT_DOUBLE_EQ(back.length_m, up.length_m);
}

TEST(FlightCostModel, VerticalMotionsFollowClimbAndDescentRates) {
  CorridorModels scene;
  const FlightCostModel model(scene.environment, scene.energy, CostModelOptions{});
  const Eigen::Vector3d low(3.0, 0.0, 1.5), high(3.0, 0.0, 2.5);
  EXPECT_NEAR(model.integrate(low, high).duration_s, 1.0 / 1.0, 1e-12);
  EXPECT_NEAR(model.integrate(high, low).duration_s, 1.0 / 0.8, 1e-12);
  // Climbing draws more current than descending: the cost is not symmetric.
  EXPECT_GT(model.integrate(low, high).charge_ah / 1.0, model.integrate(high, low).charge_ah / 1.25);
}

TEST(FlightCostModel, UnderTheCeilingCurrentDropsAndTheSpeedRuleApplies) {
  CorridorModels scene;
  CostModelOptions options;
  const FlightCostModel model(scene.environment, scene.energy, options);
  const double z = bodyHeightUnder(3.5);
  const planner::MotionTotals hugging = model.integrate({1.0, 0.0, z}, {5.0, 0.0, z});
  const planner::MotionTotals below = model.integrate({1.0, 0.0, 2.0}, {5.0, 0.0, 2.0});
  EXPECT_NEAR(hugging.duration_s, 4.0 / options.speeds.near_ceiling_m_s, 1e-9);
  EXPECT_LT(hugging.charge_ah / hugging.duration_s, 0.92 * below.charge_ah / below.duration_s);
}

TEST(FlightCostModel, FreeModeIgnoresTheCeilingInTheCurrentButNotInTheSpeedRule) {
  CorridorModels scene;
  CostModelOptions options;
  options.proximity_effects = false;
  const FlightCostModel free_model(scene.environment, scene.energy, options);
  const double z = bodyHeightUnder(3.5);
  const planner::MotionTotals hugging = free_model.integrate({1.0, 0.0, z}, {5.0, 0.0, z});
  energy::FlightCondition slow;
  slow.speed_m_s = options.speeds.near_ceiling_m_s;
  slow.soc = options.planning_soc;
  EXPECT_NEAR(hugging.charge_ah, scene.energy.currentA(energy::kNoSurface, 0.0, slow) * hugging.duration_s / 3600.0,
              1e-9);
}

TEST(FlightCostModel, SkippingFreeAirQueriesGivesTheExactConditions) {
  CorridorModels scene;
  const FlightCostModel model(scene.environment, scene.energy, CostModelOptions{});
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(3.0, 0.0, 2.0), Eigen::Vector3d(3.0, 0.0, 0.5),
                                   Eigen::Vector3d(3.0, 2.0, 2.0), Eigen::Vector3d(3.0, 0.0, 3.3)}) {
    const planner::PointConditions fast = model.conditionsAt(p), exact = model.exactConditionsAt(p);
    EXPECT_EQ(fast.ground_gap_m, exact.ground_gap_m) << p.transpose();
    for (int r = 0; r < 4; ++r) {
      EXPECT_EQ(fast.rotors[r].gap_m, exact.rotors[r].gap_m) << p.transpose();
      EXPECT_EQ(fast.rotors[r].gap_m == energy::kNoSurface ? 0.0 : fast.rotors[r].coverage,
                exact.rotors[r].gap_m == energy::kNoSurface ? 0.0 : exact.rotors[r].coverage);
    }
    EXPECT_EQ(model.nearCeiling(fast), model.nearCeiling(exact));
  }
}

TEST(FlightCostModel, RefusesSpeedsTheEnergyModelCannotFly) {
  CorridorModels scene;
  CostModelOptions options;
  options.speeds.cruise_m_s = 40.0;
  EXPECT_THROW(FlightCostModel(scene.environment, scene.energy, options), ceilplan::InputError);
  options.speeds.cruise_m_s = 2.0;
  options.speeds.climb_m_s = 0.0;
  EXPECT_THROW(FlightCostModel(scene.environment, scene.energy, options), ceilplan::InputError);
  options.speeds.climb_m_s = 1e-300;  // times and charges of a route would overflow
  EXPECT_THROW(FlightCostModel(scene.environment, scene.energy, options), ceilplan::InputError);
  options.speeds.climb_m_s = planner::FlightSpeeds::kMinSpeed_m_s;
  EXPECT_NO_THROW(FlightCostModel(scene.environment, scene.energy, options));
}

}  // namespace
}  // namespace ceilplan::testing
