// The ageing objective: each battery ageing model linearised into wear per Ah and per second.

#include "planner_fixtures.hpp"

#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/lipo_open_circuit_voltage.hpp"
#include "ceilplan/planner/ageing_objective.hpp"
#include "ceilplan/planner/flight_planner.hpp"

#include <gtest/gtest.h>

namespace ceilplan::testing {
namespace {

battery::AgeingModelOptions modelOptions() {
  battery::AgeingModelOptions options;
  const energy::LipoOpenCircuitVoltage ocv;
  options.cell_voltage_of_soc = [ocv](double soc) { return ocv.cellVoltageV(soc); };
  return options;
}

TEST(AgeingRates, EveryModelGivesAFiniteNonNegativeLinearisation) {
  for (const std::string& name : battery::ageingModelNames()) {
    const planner::AgeingRates rates =
        planner::measureAgeingRates(name, modelOptions(), battery::Pack{}, 0.95, 0.3, 9.0);
    EXPECT_TRUE(std::isfinite(rates.loss_per_ah) && rates.loss_per_ah >= 0.0) << name;
    EXPECT_TRUE(std::isfinite(rates.loss_per_s) && rates.loss_per_s >= 0.0) << name;
    EXPECT_GT(rates.loss_per_ah, 0.0) << name << ": cycling must wear the pack";
  }
}

TEST(AgeingRates, DeeperCyclesWearMorePerAmpereHourUnderWoehler) {
  // Woehler: cycles to failure ~ DoD^-k with k > 1, so wear per Ah grows with depth.
  const auto per_ah = [](double dod) {
    return planner::measureAgeingRates("woehler", modelOptions(), battery::Pack{}, 0.95, dod, 9.0).loss_per_ah;
  };
  EXPECT_LT(per_ah(0.1), per_ah(0.6));
}

TEST(AgeingRates, RefusesADepthThePackCannotGive) {
  EXPECT_THROW(planner::measureAgeingRates("xu", modelOptions(), battery::Pack{}, 0.95, 0.0, 9.0),
               ceilplan::InputError);
  EXPECT_THROW(planner::measureAgeingRates("xu", modelOptions(), battery::Pack{}, 0.95, 0.97, 9.0),
               ceilplan::InputError);
}

TEST(AgeingObjective, CostIsTheLinearisedWearOfTheMotionsCharge) {
  const environment::OccupancyMap map = corridor(flatCeiling);
  const environment::Environment environment(map, quad());
  const energy::EnergyModel energy = paperEnergy();
  const planner::SafetyRules rules(environment, 0.05);
  const planner::FlightCostModel model(environment, energy, planner::CostModelOptions{});
  planner::ObjectiveChoice choice;
  choice.name = "ageing";
  choice.ageing = planner::measureAgeingRates("schmalstieg", modelOptions(), battery::Pack{}, 0.95, 0.2, 9.0);
  const planner::FlightPlanner planner(rules, model, choice);
  const Eigen::Vector3d a(1, 0, 2), b(5, 1, 3);
  const planner::MotionTotals totals = model.integrate(a, b);
  EXPECT_NEAR(planner.objective().motionCost(a, b),
              choice.ageing.loss_per_ah * totals.charge_ah + choice.ageing.loss_per_s * totals.duration_s, 1e-18);
  planner::PlanRequest request;
  request.start_m = {0.5, 0, 3.4};
  request.goal_m = {5.5, 0, 3.4};
  request.planner = "lattice";
  const planner::PlanResult plan = planner.plan(request);
  EXPECT_GT(plan.cost, 0.0);
  EXPECT_FALSE(rules.checkPathDensely(plan.waypoints));
}

}  // namespace
}  // namespace ceilplan::testing
