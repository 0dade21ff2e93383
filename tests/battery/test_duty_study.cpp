// The duty study (battery::runDutyStudy): the founding paper's month by default (Kocer et al.
// 2019, arXiv 1812.11707), cases compared with the first, ageing projections compared over the
// days every case flew, and bad options refused before any work.

#include "ceilplan/battery/duty_study.hpp"
#include "ceilplan/core/error.hpp"
#include "input_error.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace ceilplan::battery {
namespace {

// A made-up but plausible LiPo cell curve; Schmalstieg only needs some cell voltage.
double linearCellVoltage(double soc) { return 3.5 + 0.7 * soc; }

DutyStudyOptions withoutAgeing() {
  DutyStudyOptions options;
  options.ageing_models.clear();
  return options;
}

std::string errorOf(const DutyStudyOptions& options) {
  return testing::inputErrorOf([&] { options.validate(); });
}

TEST(DutyStudy, DefaultsAreThePapersMonth) {
  const DutyStudyOptions options;
  EXPECT_EQ(options.flight_currents_a, (std::vector<double>{9.5, 8.0}));
  EXPECT_EQ(options.studyDays(), 30);
  EXPECT_EQ(options.step_s, 30.0);
  EXPECT_EQ(options.ageing_models, ageingModelNames());
  const MissionTemplate mission = options.mission(9.5);
  EXPECT_DOUBLE_EQ(mission.periodS(), 45 * 60.0);
  EXPECT_EQ(options.studyMissions(), 450.0);
}

TEST(DutyStudy, ReproducesThePapersTable) {
  const DutyStudyResult result = runDutyStudy(withoutAgeing());
  ASSERT_EQ(result.cases.size(), 2u);
  EXPECT_EQ(result.study_days, 30);
  for (const DutyStudyCase& c : result.cases) {
    const double i = c.flight_current_a;
    EXPECT_NEAR(c.run.minSoc(), 0.95 - i / 3.0 / 5.2, 1e-12);
    EXPECT_NEAR(c.run.fecTotal(), 450 * i / 3.0 / 5.2, 1e-9);  // 274.04 and 230.77
    EXPECT_NEAR(c.run.fecPerDay(), 15 * i / 3.0 / 5.2, 1e-9);
    EXPECT_NEAR(c.max_dod, i / 3.0 / 5.2, 1e-12);  // every mission charges back to 95 %
    EXPECT_TRUE(c.ageing.empty());
  }
  EXPECT_NEAR(result.cases[0].run.missions.back().charge_end_s / 60.0, 43.5, 1e-9);  // 30 s steps
  EXPECT_NEAR(result.cases[1].run.missions.back().charge_end_s / 60.0, 40.5, 1e-9);
  EXPECT_EQ(result.cases[0].fec_reduction_pct, 0.0);
  EXPECT_NEAR(result.cases[1].fec_reduction_pct, 100.0 * (1.0 - 8.0 / 9.5), 1e-9);  // 15.79 %
  EXPECT_TRUE(result.comparison_days.empty());
  EXPECT_TRUE(result.cases[0].run.run.empty());  // the whole run is kept only on request
}

TEST(DutyStudy, EachModelProjectsEveryCaseAndComparesWithTheFirst) {
  DutyStudyOptions options;
  options.ageing_models = {"fec", "xu"};
  options.step_s = 0.0;
  const DutyStudyResult result = runDutyStudy(options);
  ASSERT_EQ(result.comparison_days, (std::vector<int>{30, 30}));
  const DutyStudyCase& ceiling = result.cases[1];
  ASSERT_EQ(ceiling.ageing.size(), 2u);
  const DutyStudyAgeing& fec = ceiling.ageing[0];
  EXPECT_EQ(fec.projection.model, "fec");
  EXPECT_NEAR(fec.projection.cycle_wear, ceiling.run.fecTotal(), 1e-9);  // one FEC
  EXPECT_NEAR(*fec.wear_reduction_pct, 100.0 * (1.0 - 8.0 / 9.5), 1e-9);
  EXPECT_NEAR(*fec.wear_reduction_new_pack_pct, 100.0 * (1.0 - 8.0 / 9.5), 1e-9);
  EXPECT_GT(*fec.fade_reduction_pct, 0.0);
  // Xu et al. 2018's cycle damage, with the pack kept new, falls 18.2 % under the ceiling.
  const DutyStudyAgeing& xu = ceiling.ageing[1];
  EXPECT_EQ(xu.projection.model, "xu");
  EXPECT_NEAR(*xu.wear_reduction_new_pack_pct, 18.2, 0.05);
  EXPECT_FALSE(xu.projection.warnings.empty());  // fitted on LMO cells at 1C
  EXPECT_EQ(*result.cases[0].ageing[1].wear_reduction_pct, 0.0);
}

TEST(DutyStudy, ReductionsCompareOverTheDaysEveryCaseFlew) {
  // The free-flight pack gives out first under the fec model; the cases compare over its days.
  DutyStudyOptions options;
  options.ageing_models = {"fec"};
  options.days = 100;
  options.step_s = 0.0;
  const DutyStudyResult result = runDutyStudy(options);
  const int free_days = result.cases[0].ageing[0].projection.days_flown;
  const int ceiling_days = result.cases[1].ageing[0].projection.days_flown;
  EXPECT_LT(free_days, ceiling_days);
  EXPECT_LT(ceiling_days, 100);
  EXPECT_EQ(result.comparison_days.at(0), free_days);
  EXPECT_NEAR(*result.cases[1].ageing[0].wear_reduction_pct, 100.0 * (1.0 - 8.0 / 9.5), 1e-9);
}

TEST(DutyStudy, SpanTextSaysDaysAndTheYearsTheyCameFrom) {
  DutyStudyOptions options;
  EXPECT_EQ(options.spanText(), "30 days");
  options.days = 1;
  EXPECT_EQ(options.spanText(), "1 day");
  options.years = 5;
  EXPECT_EQ(options.studyDays(), 1825);
  EXPECT_EQ(options.spanText(), "1825 days (5 years)");
  options.years = 1;
  EXPECT_EQ(options.spanText(), "365 days (1 year)");
}

TEST(DutyStudy, ReportsProgressPerRunAndProjection) {
  DutyStudyOptions options;
  options.ageing_models = {"fec"};
  options.days = 2;
  std::vector<std::pair<std::string, double>> stages;  // each stage and its last fraction
  options.progress = [&](const std::string& stage, double fraction) {
    if (stages.empty() || stages.back().first != stage) stages.emplace_back(stage, fraction);
    stages.back().second = fraction;
  };
  runDutyStudy(options);
  const std::vector<std::pair<std::string, double>> expected{
      {"duty 9.50 A", 1.0}, {"ageing (fec, 9.50 A)", 1.0}, {"duty 8.00 A", 1.0}, {"ageing (fec, 8.00 A)", 1.0}};
  EXPECT_EQ(stages, expected);
}

TEST(DutyStudy, RecordsTheWholeRunOnRequestAndCountsItsSamplesBeforehand) {
  for (double step_s : {30.0, 0.0}) {
    DutyStudyOptions options = withoutAgeing();
    options.days = 2;
    options.step_s = step_s;
    options.record_run = true;
    const DutyStudyResult result = runDutyStudy(options);
    // 30 s: 94 samples a mission (charge ending in the slot), 1532 a night of 765 min.
    const double recorded = static_cast<double>(result.cases[0].run.run.size());
    EXPECT_LE(recorded, options.recordedRunSamples()) << step_s;
    EXPECT_GE(recorded, 0.9 * options.recordedRunSamples()) << step_s;
  }
}

TEST(DutyStudy, ADepletedPackIsInfeasibleAndNamesTheCase) {
  DutyStudyOptions options = withoutAgeing();
  options.charge_max_s = 600.0;
  try {
    runDutyStudy(options);
    FAIL() << "the pack runs out in the third mission";
  } catch (const InfeasibleError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("case 9.50 A: mission 3 of day 1", 0), 0u) << message;
    EXPECT_NE(message.find("fly less, charge longer or start fuller"), std::string::npos) << message;
  }
}

TEST(DutyStudy, RefusesBadOptionsBeforeAnyWork) {
  DutyStudyOptions options;
  options.flight_currents_a.clear();
  EXPECT_NE(errorOf(options).find("at least one flight current"), std::string::npos);
  options = DutyStudyOptions{};
  options.flight_currents_a = {9.5, -1.0};
  EXPECT_NE(errorOf(options).find("flight current must be"), std::string::npos);
  options = DutyStudyOptions{};
  options.step_s = 0.1;
  EXPECT_NE(errorOf(options).find("cuts each 45-min mission into 27000 steps"), std::string::npos);
  options = DutyStudyOptions{};
  options.missions_per_day = 40;
  EXPECT_NE(errorOf(options).find("do not fit in a day"), std::string::npos);
  options = DutyStudyOptions{};
  options.missions_per_day = 100;
  options.flight_s = 600.0;
  options.idle_s = options.charge_max_s = 60.0;
  options.years = 100;
  EXPECT_NE(errorOf(options).find("3.65e+06 missions, over the 1e+06"), std::string::npos) << errorOf(options);
  options = DutyStudyOptions{};
  options.days = 7000;
  options.record_run = true;
  EXPECT_NE(errorOf(options).find("2.1e+07 samples per case"), std::string::npos) << errorOf(options);
  options.record_run = false;
  options.cell_voltage_of_soc = linearCellVoltage;
  EXPECT_EQ(errorOf(options), "(no error)");
  options = DutyStudyOptions{};
  options.years = 0.001;  // rounds to no day
  EXPECT_NE(errorOf(options).find("outside 1 to 36500 days"), std::string::npos) << errorOf(options);
  options = DutyStudyOptions{};
  options.ageing_models = {"rainbow"};
  EXPECT_NE(errorOf(options).find("rainbow"), std::string::npos);
  options.ageing_models = {"schmalstieg"};  // needs the cell voltage
  EXPECT_NE(errorOf(options), "(no error)");
  options.cell_voltage_of_soc = linearCellVoltage;
  EXPECT_EQ(errorOf(options), "(no error)");
  options.temperature_c = 298.0;
  EXPECT_NE(errorOf(options).find("kelvin"), std::string::npos);
  options.temperature_c = 25.0;
  options.end_of_life_soh = 1.0;
  EXPECT_NE(errorOf(options).find("end-of-life state of health"), std::string::npos);
  options.ageing_models.clear();  // no projection, no end of life
  EXPECT_EQ(errorOf(options), "(no error)");
  options.pack.capacity_ah = 0.0;
  EXPECT_NE(errorOf(options), "(no error)");
}

}  // namespace
}  // namespace ceilplan::battery
