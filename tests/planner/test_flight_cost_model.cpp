// FlightCostModel: speeds, durations and charge of straight motions.

#include "ceilplan/core/error.hpp"

#include "planner_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace ceilplan::testing {
namespace {

using planner::CostModelOptions;
using planner::FlightCostModel;

struct CorridorModels {
  environment::OccupancyMap map = corridor(flatCeiling);
  environment::Environment environment{map, quad()};
  energy::EnergyModel energy = paperEnergy();
};

// A seeded point anywhere in the environment's map box.
Eigen::Vector3d somewhereIn(const environment::Environment& environment, std::mt19937& random) {
  const Eigen::AlignedBox3d box = environment.grid().frame().bounds();
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double x = unit(random), y = unit(random), z = unit(random);  // in this order, whatever the compiler
  return box.min() + box.sizes().cwiseProduct(Eigen::Vector3d(x, y, z));
}

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

TEST(FlightCostModel, MotionsShareGapLookupsAndGiveEachSampleItsOwnConditions) {
  const environment::OccupancyMap map = beamRoom();
  const environment::Environment environment(map, quad());
  const energy::EnergyModel energy = paperEnergy();
  CostModelOptions options;
  options.standoff_m = 0.3;  // the shortfall is part of each sample's conditions too
  const FlightCostModel model(environment, energy, options);
  std::mt19937 random(26);
  const auto somewhere = [&] { return somewhereIn(environment, random); };
  int near_ceiling = 0;
  for (int m = 0; m < 300; ++m) {
    const Eigen::Vector3d a = somewhere(),
                          b = m % 2 ? somewhere() : Eigen::Vector3d(a + 0.4 * Eigen::Vector3d::UnitX());
    if (!environment.contains(b)) continue;
    const std::vector<planner::PointConditions> along = model.conditionsAlong(a, b);
    const std::vector<planner::PointConditions> exact_along = model.exactConditionsAlong(a, b);
    const int intervals = model.intervalCount(a, b);
    ASSERT_EQ(along.size(), static_cast<std::size_t>(intervals + 1));
    ASSERT_EQ(exact_along.size(), along.size());
    // Bit for bit: EXPECT_EQ on doubles.
    const auto expectSame = [&](const planner::PointConditions& got, const planner::PointConditions& single, int k) {
      EXPECT_EQ(got.nearest_ceiling_gap_m, single.nearest_ceiling_gap_m) << m << " " << k;
      EXPECT_EQ(got.ground_gap_m, single.ground_gap_m) << m << " " << k;
      EXPECT_EQ(got.standoff_shortfall_m, single.standoff_shortfall_m) << m << " " << k;
      ASSERT_EQ(got.rotor_count, single.rotor_count);
      for (int r = 0; r < single.rotor_count; ++r) {
        EXPECT_EQ(got.rotors[r].gap_m, single.rotors[r].gap_m) << m << " " << k << " rotor " << r;
        EXPECT_EQ(got.rotors[r].coverage, single.rotors[r].coverage) << m << " " << k << " rotor " << r;
      }
    };
    for (int k = 0; k <= intervals; ++k) {
      const Eigen::Vector3d p = k == intervals ? b : Eigen::Vector3d(a + (b - a) * (double(k) / intervals));
      const planner::PointConditions single = model.conditionsAt(p);
      expectSame(along[k], single, k);
      expectSame(exact_along[k], model.exactConditionsAt(p), k);
      near_ceiling += model.nearCeiling(single);
    }
    const auto [forth, back] = model.integrateBothWays(a, b);
    const auto [forth_each, back_each] =
        model.integrateBothWays(a, b, [&](const Eigen::Vector3d& p) { return model.conditionsAt(p); });
    EXPECT_EQ(forth.charge_ah, forth_each.charge_ah) << m;
    EXPECT_EQ(back.charge_ah, back_each.charge_ah) << m;
    EXPECT_EQ(forth.duration_s, forth_each.duration_s) << m;
    EXPECT_EQ(forth.shortfall_m2, forth_each.shortfall_m2) << m;
  }
  EXPECT_GT(near_ceiling, 100);  // the motions met the beams and the ceiling, not only free air
}

// integrate() and integrateBothWays() of the motion a -> b cost what its samples do, each looked up
// alone (conditionsAt) and with every gap looked up (exactConditionsAt): bit for bit, EXPECT_EQ
// on doubles.
void expectCostsOfTheSamplesLookedUpOneByOne(const FlightCostModel& model, const Eigen::Vector3d& a,
                                             const Eigen::Vector3d& b, int motion) {
  const auto each = [&](const Eigen::Vector3d& p) { return model.conditionsAt(p); };
  const auto exact = [&](const Eigen::Vector3d& p) { return model.exactConditionsAt(p); };
  const auto expectSame = [&](const planner::MotionTotals& got, const planner::MotionTotals& sampled) {
    EXPECT_EQ(got.charge_ah, sampled.charge_ah) << motion;
    EXPECT_EQ(got.duration_s, sampled.duration_s) << motion;
    EXPECT_EQ(got.shortfall_m2, sampled.shortfall_m2) << motion;
  };
  const planner::MotionTotals once = model.integrate(a, b);
  expectSame(once, model.integrate(a, b, each));
  expectSame(once, model.integrate(a, b, exact));
  const auto [forth, back] = model.integrateBothWays(a, b);
  for (const auto& [forth_sampled, back_sampled] :
       {model.integrateBothWays(a, b, each), model.integrateBothWays(a, b, exact)}) {
    expectSame(forth, forth_sampled);
    expectSame(back, back_sampled);
  }
}

// Whether a sample feels the structure: a rotor's or the ground's gap, the speed rule or the
// standoff.
bool feelsStructure(const FlightCostModel& model, const planner::PointConditions& conditions) {
  bool feels =
      conditions.standoff_shortfall_m > 0.0 || model.nearCeiling(conditions) || std::isfinite(conditions.ground_gap_m);
  for (int r = 0; r < conditions.rotor_count; ++r) feels = feels || conditions.rotors[r].coverage > 0.0;
  return feels;
}

TEST(FlightCostModel, AMotionWhollyInFreeAirCostsWhatItsSamplesLookedUpOneByOneDo) {
  // The corridor's middle is more than a metre from the floor, the ceiling and the walls: motions
  // there are costed from one lookup (FlightCostModel::integrate), motions reaching towards the
  // structure sample by sample, and both must cost what each sample looked up alone does, and
  // what it does with every gap looked up (exactConditionsAt: free air's skipped lookups change
  // nothing the cost sees), with and without the proximity effects, and with a standoff that
  // reaches beyond the rotors' reach.
  CorridorModels scene;
  std::mt19937 random(5);
  std::uniform_real_distribution<double> across(-1.6, 1.6), along(0.5, 5.5), height(0.9, 2.8), reach(0.05, 3.0);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const bool proximity : {true, false})
    for (const double standoff_m : {0.0, 0.5}) {
      CostModelOptions options;
      options.proximity_effects = proximity;
      options.standoff_m = standoff_m;
      const FlightCostModel model(scene.environment, scene.energy, options);
      int in_free_air = 0, near_structure = 0;
      for (int m = 0; m < 400; ++m) {
        const Eigen::Vector3d a(along(random), across(random), height(random));
        const double length_m = m % 2 ? reach(random) : 0.2 * reach(random);
        const Eigen::Vector3d b = a + length_m * Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized();
        if (!scene.environment.contains(b)) continue;
        expectCostsOfTheSamplesLookedUpOneByOne(model, a, b, m);
        // Farther than any rotor's reach (under 0.8 m for this vehicle) and than the standoff.
        in_free_air += scene.environment.clearance_m(0.5 * (a + b)) - 0.5 * (b - a).norm() > 0.8 + standoff_m;
        bool felt = false;
        const int intervals = model.intervalCount(a, b);
        for (int k = 0; k <= intervals && !felt; ++k)
          felt = feelsStructure(model, model.conditionsAt(a + (b - a) * (double(k) / intervals)));
        near_structure += felt;
      }
      EXPECT_GT(in_free_air, standoff_m > 0.0 ? 10 : 100) << proximity << " " << standoff_m;
      EXPECT_GT(near_structure, 50) << proximity << " " << standoff_m;
    }
}

TEST(FlightCostModel, ALongMotionCostsWhatItsSamplesLookedUpOneByOneDo) {
  // A refined leg's segments run tens of metres, from free air to the structure and back: after
  // one lookup the samples that lie in free air by its bound, less the way flown since, are
  // costed without their own (FlightCostModel::integrate), and must cost what each sample looked
  // up alone does. Under the shipped bridge, in both modes, with and without a standoff.
  const environment::OccupancyMap map = environment::OccupancyMap::load(CEILPLAN_SOURCE_DIR "/maps/bridge.bt");
  const environment::Environment environment(map, quad());
  const energy::EnergyModel energy = paperEnergy();
  std::mt19937 random(31);
  const auto somewhere = [&] { return somewhereIn(environment, random); };
  for (const bool proximity : {true, false})
    for (const double standoff_m : {0.0, 1.0}) {
      CostModelOptions options;
      options.proximity_effects = proximity;
      options.standoff_m = standoff_m;
      const FlightCostModel model(environment, energy, options);
      int motions = 0, felt = 0, in_free_air = 0;
      for (int m = 0; m < 120; ++m) {
        const Eigen::Vector3d a = somewhere(), b = somewhere();
        expectCostsOfTheSamplesLookedUpOneByOne(model, a, b, m);
        ++motions;
        // The motion met both: samples far from everything, and samples that feel the structure.
        bool near = false, far = false;
        const int intervals = model.intervalCount(a, b);
        for (int k = 0; k <= intervals; ++k) {
          const Eigen::Vector3d p = a + (b - a) * (double(k) / intervals);
          near = near || feelsStructure(model, model.conditionsAt(p));
          far = far || environment.clearance_m(p) > 1.5;
        }
        felt += near && far;
        in_free_air += far;
      }
      EXPECT_EQ(motions, 120);
      EXPECT_GT(felt, 80) << proximity << " " << standoff_m;
      EXPECT_GT(in_free_air, 80) << proximity << " " << standoff_m;
    }
}

TEST(FlightCostModel, WithoutProximityEffectsOnlyTheSpeedRulesCeilingIsLookedUp) {
  // Free mode's rotors see free air: only a ceiling closer than the speed rule's gap over a disc
  // matters, so the model skips the lookups farther from structure than that. Beside the beam a
  // rotor's disc reaches under its edge while the body is well clear of it: those samples must
  // still slow down, as every gap looked up says.
  const environment::OccupancyMap map = beamRoom();
  const environment::Environment environment(map, quad());
  const energy::EnergyModel energy = paperEnergy();
  CostModelOptions options;
  options.proximity_effects = false;
  const FlightCostModel model(environment, energy, options);
  std::mt19937 random(27);
  std::uniform_real_distribution<double> x(-0.8, 1.1), y(-0.6, 0.6), z(1.2, 1.7), unit(-1.0, 1.0), reach(0.05, 1.0);
  int slowed_beside = 0;
  for (int m = 0; m < 400; ++m) {
    const Eigen::Vector3d a(x(random), y(random), z(random));
    const Eigen::Vector3d b =
        a + reach(random) * Eigen::Vector3d(unit(random), unit(random), 0.2 * unit(random)).normalized();
    if (!environment.contains(b) || !environment.isStateValid(a)) continue;
    const auto exact = [&](const Eigen::Vector3d& p) { return model.exactConditionsAt(p); };
    const planner::MotionTotals once = model.integrate(a, b), looked_up = model.integrate(a, b, exact);
    EXPECT_EQ(once.charge_ah, looked_up.charge_ah) << m;
    EXPECT_EQ(once.duration_s, looked_up.duration_s) << m;
    const int intervals = model.intervalCount(a, b);
    for (int k = 0; k <= intervals; ++k) {
      const Eigen::Vector3d p = a + (b - a) * (double(k) / intervals);
      slowed_beside += model.nearCeiling(model.exactConditionsAt(p)) && environment.clearance_m(p) > 0.3;
    }
  }
  EXPECT_GT(slowed_beside, 20);
  // Bodies approaching the beam below its underside (1.6 m), a disc's rim reaching under its edge:
  // each slows down exactly where every gap looked up says so.
  int slowed = 0;
  for (double x = -0.7; x < -0.05; x += 0.01)
    for (double plane_gap_m = 0.02; plane_gap_m < 0.5; plane_gap_m += 0.03) {
      const Eigen::Vector3d p(x, 0.013, 1.6 - plane_gap_m - quad().rotor_plane_height_m);
      const bool near = model.nearCeiling(model.exactConditionsAt(p));
      EXPECT_EQ(model.nearCeiling(model.conditionsAt(p)), near) << p.transpose();
      slowed += near;
    }
  EXPECT_GT(slowed, 50);
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
