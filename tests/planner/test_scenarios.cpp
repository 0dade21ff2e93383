// Ceiling mode against free mode on analytic scenes, both scored with the full model: it hugs
// a ceiling where that lowers the charge, agrees with free mode where there is no ceiling, and
// is never worse. Every returned path passes the dense re-check.

#include "planner_fixtures.hpp"

#include "ceilplan/battery/pack.hpp"
#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/path_evaluation.hpp"

#include <gtest/gtest.h>

namespace ceilplan::testing {
namespace {

struct ModeOutcome {
  planner::PlanResult plan;
  planner::PathEvaluation evaluation;  // full model
};

struct Comparison {
  ModeOutcome ceiling;
  ModeOutcome free;
};

Comparison planBothModes(const environment::OccupancyMap& map, const Eigen::Vector3d& start,
                         const Eigen::Vector3d& goal, const std::string& planner_name, double time_limit_s = 30.0,
                         const planner::FlightSpeeds& speeds = {}) {
  planner::seedOmpl(1);
  const environment::Environment environment(map, quad());
  const energy::EnergyModel energy = paperEnergy();
  planner::CostModelOptions full_options;
  full_options.speeds = speeds;
  const planner::FlightCostModel full(environment, energy, full_options);
  planner::CostModelOptions free_options = full_options;
  free_options.proximity_effects = false;
  free_options.standoff_m = 1.0;
  const planner::FlightCostModel free_model(environment, energy, free_options);
  const planner::SafetyRules rules(environment, 0.05);  // the same in both modes

  planner::PlanRequest request;
  request.start_m = start;
  request.goal_m = goal;
  request.planner = planner_name;
  request.time_limit_s = time_limit_s;
  Comparison result;
  const auto run = [&](const planner::SafetyRules& mode_rules, const planner::FlightCostModel& model) {
    const planner::FlightPlanner flight_planner(mode_rules, model, planner::ObjectiveChoice{});
    ModeOutcome outcome;
    outcome.plan = flight_planner.plan(request);
    EXPECT_FALSE(rules.checkPathDensely(outcome.plan.waypoints));
    outcome.evaluation = planner::evaluatePath(full, battery::Pack{}, 0.95, outcome.plan.waypoints);
    return outcome;
  };
  result.free = run(rules, free_model);
  request.candidates = {result.free.plan.waypoints};  // as `ceilplan compare` does
  result.ceiling = run(rules, full);
  return result;
}

double underCeilingShare(const planner::PathEvaluation& evaluation) {
  return evaluation.time_under_ceiling_s / evaluation.duration_s;
}

TEST(Scenarios, FlatCeilingCorridorHugsAndBeatsFreeFlight) {
  const double z = bodyHeightUnder(3.5);
  const Comparison c = planBothModes(corridor(flatCeiling), {0.5, 0.0, z}, {5.5, 0.0, z}, "lattice");
  EXPECT_GT(underCeilingShare(c.ceiling.evaluation), 0.9);
  EXPECT_LT(underCeilingShare(c.free.evaluation), 0.3);
  EXPECT_LT(c.ceiling.evaluation.charge_ah, 0.97 * c.free.evaluation.charge_ah);
}

double slope(double x, double) { return 3.0 + 0.1 * std::round(x * 10.0) / 10.0; }

// The ceiling is lowest over the back of the vehicle's footprint (0.46 m).
const Eigen::Vector3d kSlopeStart(0.5, 0.0, bodyHeightUnder(slope(0.0, 0))),
    kSlopeGoal(5.5, 0.0, bodyHeightUnder(slope(5.0, 0)));

TEST(Scenarios, SlopedCeilingIsHuggedWhenTheSlowZoneIsNotSlower) {
  planner::FlightSpeeds speeds;
  speeds.near_ceiling_m_s = speeds.cruise_m_s;
  const Comparison c = planBothModes(corridor(slope), kSlopeStart, kSlopeGoal, "lattice", 30.0, speeds);
  EXPECT_GT(underCeilingShare(c.ceiling.evaluation), 0.7);
  EXPECT_LT(c.ceiling.evaluation.charge_ah, c.free.evaluation.charge_ah);
}

TEST(Scenarios, SlopedCeilingIsLeftWhenHuggingDoesNotPay) {
  // At the default 1.8 m/s in the slow zone, the weaker effect of a sloped ceiling (the front
  // rotors sit further from it) no longer pays for the slower flight: the plan must then beat
  // the hugging route, not imitate it.
  const environment::OccupancyMap map = corridor(slope);
  const Comparison c = planBothModes(map, kSlopeStart, kSlopeGoal, "lattice");
  const environment::Environment environment(map, quad());
  const energy::EnergyModel energy = paperEnergy();
  const planner::FlightCostModel full(environment, energy, planner::CostModelOptions{});
  std::vector<Eigen::Vector3d> hugging{kSlopeStart};
  for (double x = 1.0; x < 5.45; x += 0.5) {  // level, then up: a staircase under the voxel steps
    hugging.push_back({x, 0.0, hugging.back().z()});
    hugging.push_back({x, 0.0, bodyHeightUnder(slope(x - 0.5, 0))});
  }
  hugging.push_back(kSlopeGoal);
  const planner::SafetyRules rules(environment, 0.05);
  ASSERT_FALSE(rules.checkPathDensely(hugging));
  const double hugging_ah = planner::evaluatePath(full, battery::Pack{}, 0.95, hugging).charge_ah;
  EXPECT_LE(c.ceiling.evaluation.charge_ah, hugging_ah);
  EXPECT_LE(c.ceiling.evaluation.charge_ah, c.free.evaluation.charge_ah);
}

TEST(Scenarios, CeilingWithBeamsIsNeverWorseThanFreeFlight) {
  const auto beams = [](double x, double) { return std::fmod(x + 10.0, 2.0) < 0.3 ? 3.0 : 3.5; };
  const double z = bodyHeightUnder(3.5);
  const Comparison c = planBothModes(corridor(beams), {0.9, 0.0, z}, {5.1, 0.0, z}, "lattice");
  EXPECT_LE(c.ceiling.evaluation.charge_ah, c.free.evaluation.charge_ah);
  EXPECT_GT(c.ceiling.evaluation.time_under_ceiling_s, 0.0);
}

TEST(Scenarios, WithoutACeilingBothModesAgree) {
  const auto none = [](double, double) { return std::numeric_limits<double>::infinity(); };
  const Comparison c = planBothModes(corridor(none), {0.5, 0.0, 2.0}, {5.5, 0.0, 2.0}, "lattice");
  EXPECT_NEAR(c.ceiling.evaluation.charge_ah, c.free.evaluation.charge_ah, 0.02 * c.free.evaluation.charge_ah);
  EXPECT_LE(c.ceiling.evaluation.charge_ah, c.free.evaluation.charge_ah * 1.001);
  EXPECT_EQ(c.ceiling.evaluation.time_under_ceiling_s, 0.0);
}

TEST(Scenarios, SampledPlannerHugsTheFlatCeilingToo) {
  const double z = bodyHeightUnder(3.5);
  const Comparison c = planBothModes(corridor(flatCeiling), {0.5, 0.0, z}, {5.5, 0.0, z}, "BITstar", 1.5);
  EXPECT_LT(c.ceiling.evaluation.charge_ah, 0.97 * c.free.evaluation.charge_ah);
  EXPECT_GT(underCeilingShare(c.ceiling.evaluation), 0.7);
}

}  // namespace
}  // namespace ceilplan::testing
