// Duty cycles: missions in fixed slots, overnight rest, SOC carried over, capacity fade fed back.

#include "ceilplan/battery/duty_cycle.hpp"
#include "ceilplan/core/error.hpp"

#include <gtest/gtest.h>

namespace ceilplan::battery {
namespace {

DutyCycle paperDuty(double flight_current_a, double charge_max_s) {
  DutyCycle duty;
  duty.mission = flyIdleChargeMission(flight_current_a, 1200.0, 300.0, 10.4, charge_max_s, 0.95);
  return duty;
}

TEST(DutyCycle, MissionsStartInFixedSlotsAndDaysAtMidnight) {
  DutyCycle duty = paperDuty(9.5, 1200.0);
  duty.days = 2;
  const DutyResult run = simulateDuty(Pack{}, duty);
  ASSERT_EQ(run.missions.size(), 30u);
  EXPECT_DOUBLE_EQ(run.missions[1].start_s, 2700.0);  // 20 + 5 + 20 min slots
  EXPECT_DOUBLE_EQ(run.missions[15].start_s, 86400.0);
  EXPECT_EQ(run.missions[15].day, 1);
  EXPECT_EQ(run.missions[15].mission_in_day, 0);
  EXPECT_DOUBLE_EQ(run.final_state.t_s, 2 * 86400.0);
  ASSERT_EQ(run.days.size(), 2u);
  EXPECT_NEAR(run.days[0].fec, run.days[1].fec, 1e-12);
}

TEST(DutyCycle, ChargeCappedInTimeMakesTheSocDriftDown) {
  DutyCycle duty = paperDuty(9.5, 900.0);  // 15 min at 10.4 A puts back less than 20 min at 9.5 A took
  duty.days = 1;
  duty.missions_per_day = 3;
  const DutyResult run = simulateDuty(Pack{}, duty);
  const double lost_per_mission = (9.5 * 1200.0 - 10.4 * 900.0) / 3600.0 / 5.2;
  EXPECT_NEAR(run.missions[0].end_soc, 0.95 - lost_per_mission, 1e-12);
  EXPECT_NEAR(run.missions[2].end_soc, 0.95 - 3 * lost_per_mission, 1e-12);
  EXPECT_LT(run.missions[2].min_soc, run.missions[0].min_soc);
}

TEST(DutyCycle, DepletionNamesTheMissionAndDay) {
  DutyCycle duty = paperDuty(9.5, 900.0);
  duty.missions_per_day = 15;
  try {
    simulateDuty(Pack{}, duty);
    FAIL() << "expected DepletionError";
  } catch (const DepletionError& e) {
    // Each mission ends 0.109 lower; mission 5 starts at 0.514 and flies 0.609 off it.
    EXPECT_NE(std::string(e.what()).find("mission 5 of day 1 (mission 5 of the run)"), std::string::npos) << e.what();
    EXPECT_LT(e.reachedSoc(), 0.0);
  }
}

TEST(DutyCycle, CapacityFadeFedBackMakesLaterMissionsGoDeeper) {
  DutyCycle duty = paperDuty(9.5, 1200.0);
  duty.days = 2;
  DutyOptions options;
  options.on_mission = [](const MissionTally& mission, const std::vector<Sample>& samples) {
    EXPECT_FALSE(samples.empty());
    return mission.index < 15 ? 1.0 : 0.8;  // the pack loses a fifth of its capacity after day 1
  };
  const DutyResult run = simulateDuty(Pack{}, duty, options);
  EXPECT_NEAR(run.missions[14].min_soc, 0.95 - 9.5 / 3.0 / 5.2, 1e-12);
  EXPECT_NEAR(run.missions[16].min_soc, 0.95 - 9.5 / 3.0 / (5.2 * 0.8), 1e-12);
  EXPECT_DOUBLE_EQ(run.missions[16].state_of_health, 0.8);
  EXPECT_DOUBLE_EQ(run.days[1].state_of_health, 0.8);
}

TEST(DutyCycle, RecordsMissionDayAndRunSeriesOnRequest) {
  DutyCycle duty = paperDuty(8.0, 1200.0);
  duty.days = 2;
  DutyOptions options;
  options.step_s = 30.0;
  options.record_run = true;
  const DutyResult run = simulateDuty(Pack{}, duty, options);
  EXPECT_NEAR(run.first_mission.back().t_s, 2700.0, 1e-9);
  EXPECT_NEAR(run.first_day.back().t_s, 15 * 2700.0, 1e-9);
  EXPECT_NEAR(run.run.back().t_s, 2 * 86400.0, 1e-9);
  EXPECT_NEAR(run.run.back().fec_continuous, run.fecTotal(), 1e-9);
}

TEST(DutyCycle, RefusesMissionsThatDoNotFitInADay) {
  DutyCycle duty = paperDuty(9.5, 1200.0);
  duty.missions_per_day = 33;  // 33 x 45 min > 24 h
  EXPECT_THROW(simulateDuty(Pack{}, duty), ceilplan::InputError);
  duty.missions_per_day = 0;
  EXPECT_THROW(simulateDuty(Pack{}, duty), ceilplan::InputError);
}

}  // namespace
}  // namespace ceilplan::battery
