// Path figures: coulomb counting consistent with battery::Simulator and the FEC definition.

#include "planner_fixtures.hpp"

#include "ceilplan/battery/simulation.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/planner/path_evaluation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace ceilplan::testing {
namespace {

TEST(PathEvaluation, CountsCoulombsLikeTheBatterySimulator) {
  const environment::OccupancyMap map = corridor(flatCeiling);
  const environment::Environment environment(map, quad());
  const energy::EnergyModel energy = paperEnergy();
  const planner::FlightCostModel model(environment, energy, planner::CostModelOptions{});
  battery::Pack pack;
  pack.state_of_health = 0.9;
  const std::vector<Eigen::Vector3d> path{{0.5, 0.0, 2.0}, {5.5, 0.0, 2.0}, {5.5, 1.0, 3.4}, {0.5, 1.0, 3.4}};
  const planner::PathEvaluation e = planner::evaluatePath(model, pack, 0.8, path);

  EXPECT_NEAR(e.length_m, 5.0 + std::hypot(1.0, 1.4) + 5.0, 1e-12);
  EXPECT_NEAR(e.samples.back().soc, 0.8 - e.charge_ah / pack.usableCapacityAh(), 1e-12);
  EXPECT_NEAR(e.min_soc, e.samples.back().soc, 1e-12);
  EXPECT_NEAR(e.mean_current_a, 3600.0 * e.charge_ah / e.duration_s, 1e-12);
  EXPECT_DOUBLE_EQ(e.samples.back().t_s, e.duration_s);
  EXPECT_GT(e.time_under_ceiling_s, 0.5 * 5.0 / 1.8);
  EXPECT_LT(e.min_ceiling_gap_m, 0.1);
  // Mean terminal voltage between the pack's empty and full voltages.
  const double volts = e.energy_wh / e.charge_ah;
  EXPECT_GT(volts, 4 * 3.5);
  EXPECT_LT(volts, 4 * 4.2);

  // FEC: the discharge and the recharge putting it back, over twice the nominal capacity.
  battery::Simulator cycle(pack, 0.8);
  cycle.run(battery::Segment::discharge(e.mean_current_a, e.duration_s));
  cycle.run(battery::Segment::charge(pack.charge_current_a, 3600.0, 0.8));
  cycle.closeModeInterval();
  EXPECT_NEAR(e.fec, cycle.state().fec_continuous, 1e-9);

  // The SOC falls along the path, so the evaluated charge exceeds the planning estimate
  // made at the start SOC only by the voltage sag: a little.
  planner::MotionTotals planned;
  for (std::size_t k = 1; k < path.size(); ++k) planned += model.integrate(path[k - 1], path[k]);
  EXPECT_NEAR(e.duration_s, planned.duration_s, 1e-9);
  EXPECT_GT(e.charge_ah, planned.charge_ah * 0.98);
  EXPECT_LT(e.charge_ah, planned.charge_ah * 1.05);
}

// A camera shooting on the move caps the speed (docs/coverage.md): every sample at or below the
// cap, so the flight takes at least length / cap, and hovering longer draws more charge.
TEST(PathEvaluation, HonoursASpeedCap) {
  const environment::OccupancyMap map = corridor(flatCeiling);
  const environment::Environment environment(map, quad());
  const energy::EnergyModel energy = paperEnergy();
  const planner::FlightCostModel model(environment, energy, planner::CostModelOptions{});
  const battery::Pack pack;
  const std::vector<Eigen::Vector3d> path{{0.5, 0.0, 2.0}, {5.5, 0.0, 2.0}, {5.5, 1.0, 3.4}};
  const planner::PathEvaluation free = planner::evaluatePath(model, pack, 0.9, path);
  const planner::PathEvaluation capped = planner::evaluatePath(model, pack, 0.9, path, 0.4);
  for (const planner::PathSample& s : capped.samples) EXPECT_LE(s.speed_m_s, 0.4 + 1e-12);
  EXPECT_GE(capped.duration_s, capped.length_m / 0.4 - 1e-9);
  EXPECT_GT(capped.charge_ah, free.charge_ah);
  EXPECT_DOUBLE_EQ(capped.length_m, free.length_m);
  // A cap above every speed the model flies changes nothing.
  EXPECT_DOUBLE_EQ(planner::evaluatePath(model, pack, 0.9, path, 100.0).charge_ah, free.charge_ah);
  EXPECT_THROW(planner::evaluatePath(model, pack, 0.9, path, 0.0), ceilplan::InputError);
}

TEST(PathEvaluation, RefusesPathsItCannotScore) {
  const environment::OccupancyMap map = corridor(flatCeiling);
  const environment::Environment environment(map, quad());
  const energy::EnergyModel energy = paperEnergy();
  const planner::FlightCostModel model(environment, energy, planner::CostModelOptions{});
  EXPECT_THROW(planner::evaluatePath(model, battery::Pack{}, 0.95, {{1, 0, 2}}), ceilplan::InputError);
  EXPECT_THROW(planner::evaluatePath(model, battery::Pack{}, 0.95, {{1, 0, 2}, {99, 0, 2}}), ceilplan::InputError);
  battery::Pack almost_empty;
  almost_empty.soc_min = 0.949;
  EXPECT_THROW(planner::evaluatePath(model, almost_empty, 0.95, {{0.5, 0, 2}, {5.5, 0, 2}}), battery::DepletionError);
}

TEST(PathEvaluation, APathThatStaysWhereItStartsIsNoFlight) {
  // A tour's leg between two targets seen from the same place.
  const environment::OccupancyMap map = corridor(flatCeiling);
  const environment::Environment environment(map, quad());
  const energy::EnergyModel energy = paperEnergy();
  const planner::FlightCostModel model(environment, energy, planner::CostModelOptions{});
  const Eigen::Vector3d place(3.0, 0.0, 3.3);
  const planner::PathEvaluation stay = planner::evaluatePath(model, battery::Pack{}, 0.95, {place, place, place});
  ASSERT_EQ(stay.samples.size(), 1u);
  EXPECT_EQ(stay.samples[0].position_m, place);
  EXPECT_EQ(stay.samples[0].t_s, 0.0);
  EXPECT_EQ(stay.samples[0].speed_m_s, 0.0);
  EXPECT_DOUBLE_EQ(stay.samples[0].soc, 0.95);
  EXPECT_NEAR(stay.samples[0].ceiling_gap_m, 3.5 - 3.33, 1e-9);
  // Hovering there, under the ceiling: less than the free-air hover (9.5 A).
  EXPECT_NEAR(stay.samples[0].current_a,
              model.breakdown(model.exactConditionsAt(place), planner::Velocity{}, 0.95).current_a, 1e-12);
  EXPECT_LT(stay.samples[0].current_a, 9.5);
  EXPECT_GT(stay.samples[0].current_a, 0.0);
  EXPECT_EQ(stay.length_m, 0.0);
  EXPECT_EQ(stay.duration_s, 0.0);
  EXPECT_EQ(stay.charge_ah, 0.0);
  EXPECT_EQ(stay.fec, 0.0);
  EXPECT_DOUBLE_EQ(stay.min_soc, 0.95);
  EXPECT_DOUBLE_EQ(stay.min_clearance_m, environment.clearance_m(place));
}

// A search ranks thousands of paths by their totals alone (a large tour's leg estimates):
// evaluatePathTotals must give evaluatePath's totals (and, asked, its samples' times and
// propulsion powers) to the bit, near the ceiling, in free air (where it looks no gap up), in
// wind sheltered under the ceiling, and under a speed cap.
TEST(PathEvaluation, TotalsAloneAreTheFullEvaluationsToTheBit) {
  const environment::OccupancyMap map = corridor(flatCeiling);
  const environment::Environment environment(map, quad());
  const energy::EnergyModel energy = paperEnergy();
  planner::CostModelOptions windy;
  windy.wind.speed_m_s = 3.0;
  windy.wind.from_deg = 250.0;
  windy.wind.sheltered_fraction = 0.5;
  const planner::FlightCostModel calm(environment, energy, planner::CostModelOptions{}),
      wind(environment, energy, windy);
  battery::Pack pack;
  pack.state_of_health = 0.9;
  std::mt19937 random(26);
  std::uniform_real_distribution<double> x(-0.2, 6.2), y(-2.2, 2.2), z(0.8, 3.35);
  int far_samples = 0, near_samples = 0;
  for (int m = 0; m < 200; ++m) {
    const planner::FlightCostModel& model = m % 2 ? wind : calm;
    std::vector<Eigen::Vector3d> path(2 + m % 3);
    for (Eigen::Vector3d& waypoint : path) waypoint = {x(random), y(random), z(random)};
    if (m % 7 == 0) path[1] = path[0];  // a segment of no length
    const double cap = m % 5 == 0 ? 0.6 : std::numeric_limits<double>::infinity();
    const planner::PathEvaluation full = planner::evaluatePath(model, pack, 0.9, path, cap);
    const planner::PathEvaluation totals = planner::evaluatePathTotals(model, pack, 0.9, path, cap);
    // Bit for bit: EXPECT_EQ on doubles.
    EXPECT_EQ(totals.length_m, full.length_m) << m;
    EXPECT_EQ(totals.duration_s, full.duration_s) << m;
    EXPECT_EQ(totals.charge_ah, full.charge_ah) << m;
    EXPECT_EQ(totals.energy_wh, full.energy_wh) << m;
    EXPECT_EQ(totals.fec, full.fec) << m;
    EXPECT_EQ(totals.mean_current_a, full.mean_current_a) << m;
    EXPECT_EQ(totals.min_soc, full.min_soc) << m;
    EXPECT_EQ(totals.time_under_ceiling_s, full.time_under_ceiling_s) << m;
    EXPECT_TRUE(totals.samples.empty());
    EXPECT_TRUE(std::isnan(totals.min_clearance_m) && std::isnan(totals.min_ceiling_gap_m) &&
                std::isnan(totals.assumed_free_m));
    for (const planner::PathSample& sample : full.samples)
      (model.farFromStructure(sample.position_m) ? far_samples : near_samples) += 1;
    // The draws the split flies home: each sample's time and propulsion power, the same totals.
    std::vector<planner::PathDraw> draws;
    const planner::PathEvaluation drawn = planner::evaluatePathTotals(model, pack, 0.9, path, cap, draws);
    EXPECT_EQ(drawn.charge_ah, full.charge_ah) << m;
    ASSERT_EQ(draws.size(), full.samples.size()) << m;
    for (std::size_t k = 0; k < draws.size(); ++k) {
      EXPECT_EQ(draws[k].t_s, full.samples[k].t_s) << m << " " << k;
      EXPECT_EQ(draws[k].propulsion_power_w, full.samples[k].propulsion_power_w) << m << " " << k;
    }
  }
  // Both kinds of sample were met: the free-air shortcut and the gap lookups.
  EXPECT_GT(far_samples, 1000);
  EXPECT_GT(near_samples, 1000);
  // A path that stays where it starts: no flight either way.
  const Eigen::Vector3d place(3.0, 0.0, 3.3);
  const planner::PathEvaluation stay = planner::evaluatePathTotals(calm, pack, 0.9, {place, place});
  EXPECT_EQ(stay.charge_ah, 0.0);
  EXPECT_EQ(stay.duration_s, 0.0);
  EXPECT_EQ(stay.min_soc, 0.9);
  std::vector<planner::PathDraw> hovering;
  planner::evaluatePathTotals(calm, pack, 0.9, {place, place}, std::numeric_limits<double>::infinity(), hovering);
  const planner::PathEvaluation stay_full = planner::evaluatePath(calm, pack, 0.9, {place, place});
  ASSERT_EQ(hovering.size(), 1u);
  ASSERT_EQ(stay_full.samples.size(), 1u);
  EXPECT_EQ(hovering[0].t_s, 0.0);
  EXPECT_EQ(hovering[0].propulsion_power_w, stay_full.samples[0].propulsion_power_w);
  EXPECT_GT(hovering[0].propulsion_power_w, 0.0);
  EXPECT_THROW(planner::evaluatePathTotals(calm, pack, 0.9, {place}), ceilplan::InputError);
}

}  // namespace
}  // namespace ceilplan::testing
