// Lifetime projection: capacity fade fed back into the pack, end of life per model, and the
// founding paper's scenario seen through each ageing model.

#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/battery/lifetime.hpp"
#include "ceilplan/core/error.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ceilplan::battery {
namespace {

DutyCycle paperDuty(double flight_current_a) {
  DutyCycle duty;
  duty.mission = flyIdleChargeMission(flight_current_a, 1200.0, 300.0, 10.4, 1200.0, 0.95);
  return duty;
}

// A made-up but plausible LiPo cell curve; Schmalstieg only needs some cell voltage.
double linearCellVoltage(double soc) { return 3.5 + 0.7 * soc; }

LifetimeResult project(const std::string& model_name, double flight_current_a, int study_days = 30,
                       bool feed_back_fade = true) {
  AgeingModelOptions model_options;
  model_options.conditions.chemistry = "LiPo";
  model_options.cell_voltage_of_soc = linearCellVoltage;
  auto model = makeAgeingModel(model_name, model_options);
  LifetimeOptions options;
  options.study_days = study_days;
  options.feed_back_fade = feed_back_fade;
  return projectLifetime(Pack{}, paperDuty(flight_current_a), *model, model_options.conditions, options);
}

TEST(Lifetime, FecModelReachesEndOfLifeSoonerBecauseFadeDeepensEveryMission) {
  const LifetimeResult r = project("fec", 9.5);
  ASSERT_TRUE(r.missions_to_end_of_life);
  // Loss per SOC-FEC is 0.2 / 300, and a faded pack swings its SOC by 1 / SOH more:
  // dL/dn = (0.2 f / N100) / (1 - L) with f = 0.60897, so L - L^2 / 2 = 0.2 f n / N100;
  // L = 0.2 at n = 0.18 * 300 / (0.2 * 0.60897) = 443.4. Without feedback: 492.6.
  EXPECT_NEAR(static_cast<double>(*r.missions_to_end_of_life), 443.4, 1.5);
  EXPECT_NEAR(*r.days_to_end_of_life, (*r.missions_to_end_of_life - 1) / 15 + 1.0, 1.0);
  EXPECT_TRUE(r.stopped_because.empty()) << r.stopped_because;
}

TEST(Lifetime, StateOfHealthFallsDayByDayAndLateMissionsGoDeeper) {
  const LifetimeResult r = project("fec", 9.5);
  ASSERT_GE(r.soh_by_day.size(), 30u);
  for (size_t d = 1; d < r.soh_by_day.size(); ++d) EXPECT_LT(r.soh_by_day[d], r.soh_by_day[d - 1]);
  EXPECT_LE(r.soh_by_day.back(), 0.8);
  EXPECT_LT(r.min_soc, 0.95 - 9.5 / 3.0 / 5.2);  // deeper than the new pack's 34.1 %
}

TEST(Lifetime, StudyFiguresAreTakenAtTheEndOfTheStudyPeriod) {
  const LifetimeResult r = project("fec", 8.0, 10);
  EXPECT_NEAR(r.fec, 150 * 8.0 / 3.0 / 5.2, 1e-9);  // nominal FEC: the same current every mission
  EXPECT_GT(r.cycle_wear, r.fec);                   // SOC-based FEC grows as the pack fades
  EXPECT_NEAR(r.capacity_loss, 0.2 * r.cycle_wear / 300.0, 1e-9);
}

double cycleWearReduction(const std::string& model, bool feed_back_fade) {
  return 1.0 - project(model, 8.0, 30, feed_back_fade).cycle_wear / project(model, 9.5, 30, feed_back_fade).cycle_wear;
}

TEST(Lifetime, XuCycleDamageFallsMoreThanFecUnderTheCeiling) {
  // Reference-models.md section 5: for the paper's scenario (SOH held at 1), Xu's cycle damage
  // falls 18.2 % against 15.8 % for FEC, because S_d is convex.
  EXPECT_NEAR(100 * cycleWearReduction("fec", false), 100 * (1 - 8.0 / 9.5), 1e-6);
  EXPECT_NEAR(100 * cycleWearReduction("xu", false), 18.2, 0.05);
}

TEST(Lifetime, FeedingTheFadeBackWidensTheGap) {
  // The free-flight pack fades faster, so its missions deepen faster: every model's reduction
  // grows once the fade is fed back.
  for (const std::string& name : ageingModelNames())
    EXPECT_GT(cycleWearReduction(name, true), cycleWearReduction(name, false)) << name;
}

TEST(Lifetime, EveryModelProjectsALongerLifeUnderTheCeiling) {
  for (const std::string& name : ageingModelNames()) {
    const LifetimeResult free_flight = project(name, 9.5);
    const LifetimeResult ceiling = project(name, 8.0);
    EXPECT_LT(ceiling.capacity_loss, free_flight.capacity_loss) << name;
    if (free_flight.days_to_end_of_life && ceiling.days_to_end_of_life) {
      EXPECT_GT(*ceiling.days_to_end_of_life, *free_flight.days_to_end_of_life) << name;
    }
  }
}

TEST(Lifetime, StopsWithAReasonWhenTheFadedPackCanNoLongerFly) {
  auto model = makeAgeingModel("fec", {});
  LifetimeOptions options;
  options.end_of_life_soh = 0.3;  // far past where 20 min at 9.5 A still fits in the pack
  const LifetimeResult r = projectLifetime(Pack{}, paperDuty(9.5), *model, {}, options);
  EXPECT_FALSE(r.missions_to_end_of_life);
  EXPECT_NE(r.stopped_because.find("can no longer fly"), std::string::npos) << r.stopped_because;
}

TEST(Lifetime, WarnsWhenTheStudyLeavesAModelsValidityRange) {
  EXPECT_FALSE(project("xu", 9.5).warnings.empty());  // fitted on another chemistry, 2C charge
  EXPECT_TRUE(project("fec", 9.5).warnings.empty());
}

TEST(Lifetime, RefusesNonsenseOptions) {
  auto model = makeAgeingModel("fec", {});
  LifetimeOptions options;
  options.end_of_life_soh = 1.0;
  EXPECT_THROW(projectLifetime(Pack{}, paperDuty(9.5), *model, {}, options), ceilplan::InputError);
  options = {};
  options.study_days = 0;
  EXPECT_THROW(projectLifetime(Pack{}, paperDuty(9.5), *model, {}, options), ceilplan::InputError);
}

}  // namespace
}  // namespace ceilplan::battery
