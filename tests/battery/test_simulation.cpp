// The simulator's behaviour: coulomb counting (paper eq. 7-8), FEC both ways (eq. 3-6),
// stop conditions in both schemes, and the refusals.

#include "ceilplan/battery/simulation.hpp"
#include "ceilplan/core/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace ceilplan::battery {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(Simulator, DischargeLowersSocByChargeOverUsableCapacity) {
  Pack pack;
  pack.state_of_health = 0.8;  // 4.16 Ah usable
  Simulator simulator(pack, 0.9);
  simulator.run(Segment::discharge(4.16, 1800.0));  // 2.08 Ah = half the usable capacity
  EXPECT_NEAR(simulator.state().soc, 0.4, 1e-12);
  EXPECT_NEAR(simulator.state().discharge_ah, 2.08, 1e-12);
  // FEC counts against nominal capacity: 2.08 / (2 * 5.2).
  EXPECT_NEAR(simulator.state().fec_continuous, 0.2, 1e-12);
}

TEST(Simulator, ExactChargeStopsTheMomentTheTargetIsReached) {
  Simulator simulator(Pack{}, 0.5);
  const double took_s = simulator.run(Segment::charge(10.4, 3600.0, 0.95));
  EXPECT_NEAR(took_s, 0.45 * 5.2 / 10.4 * 3600.0, 1e-9);
  EXPECT_DOUBLE_EQ(simulator.state().soc, 0.95);
  EXPECT_NEAR(simulator.state().charge_ah, 0.45 * 5.2, 1e-12);
}

TEST(Simulator, SteppedChargeEndsWithTheStepButStopsTheSocAtTheTarget) {
  Simulator simulator(Pack{}, 0.5, 30.0);
  const double took_s = simulator.run(Segment::charge(10.4, 3600.0, 0.95));
  EXPECT_DOUBLE_EQ(took_s, 810.0);  // exact 810 s lands on a step: 27 steps
  Simulator off_grid(Pack{}, 0.51, 30.0);
  const double off_grid_s = off_grid.run(Segment::charge(10.4, 3600.0, 0.95));
  EXPECT_DOUBLE_EQ(off_grid_s, 30.0 * std::ceil(0.44 * 5.2 / 10.4 * 3600.0 / 30.0));
  EXPECT_DOUBLE_EQ(off_grid.state().soc, 0.95);
  EXPECT_NEAR(off_grid.state().charge_ah, 0.44 * 5.2, 1e-12);
}

TEST(Simulator, ChargeThatIsAlreadyAtItsTargetTakesNoTime) {
  for (double step_s : {0.0, 30.0}) {
    Simulator simulator(Pack{}, 0.97, step_s);
    EXPECT_EQ(simulator.run(Segment::charge(10.4, 1200.0, 0.95)), 0.0);
    EXPECT_DOUBLE_EQ(simulator.state().soc, 0.97);
  }
}

TEST(Simulator, ChargeNeverPassesTheUpperSocLimit) {
  Pack pack;
  pack.soc_max = 0.9;
  Simulator simulator(pack, 0.5);
  simulator.run(Segment::charge(10.4, 3600.0, 1.0));
  EXPECT_DOUBLE_EQ(simulator.state().soc, 0.9);
}

TEST(Simulator, LastStepOfASegmentIsShortenedToItsDuration) {
  Simulator simulator(Pack{}, 0.9, 30.0);
  EXPECT_DOUBLE_EQ(simulator.run(Segment::discharge(5.2, 45.0)), 45.0);
  EXPECT_NEAR(simulator.state().soc, 0.9 - 45.0 / 3600.0, 1e-12);
}

TEST(Simulator, DiscreteFecIsBookedOnlyAtModeChanges) {
  std::vector<Sample> record;
  Simulator simulator(Pack{}, 0.95, 30.0);
  simulator.run(Segment::discharge(9.5, 1200.0), &record);
  for (const Sample& s : record) EXPECT_EQ(s.fec, 0.0);
  EXPECT_GT(record.back().fec_continuous, 0.0);
  simulator.run(Segment::idle(300.0), &record);
  EXPECT_NEAR(record.back().fec, 9.5 / 3.0 / 10.4, 1e-12);  // booked when idling began
  simulator.closeModeInterval();
  EXPECT_NEAR(simulator.state().fec, simulator.state().fec_continuous, 1e-15);
}

TEST(Simulator, RecordsSegmentStartAndEndWithTheSegmentsSignedCurrent) {
  std::vector<Sample> record;
  Simulator simulator(Pack{}, 0.5);
  simulator.run(Segment::discharge(9.5, 600.0), &record);
  simulator.run(Segment::charge(10.4, 600.0, 0.95), &record);
  ASSERT_EQ(record.size(), 4u);
  EXPECT_EQ(record[0].current_a, 9.5);
  EXPECT_EQ(record[1].t_s, 600.0);
  EXPECT_EQ(record[2].current_a, -10.4);
  EXPECT_EQ(record[3].mode, Mode::Charge);
}

TEST(Simulator, RefusesToDischargeBelowTheFloorAndSaysByHowMuch) {
  Simulator simulator(Pack{}, 0.3);
  try {
    simulator.run(Segment::discharge(5.2, 1440.0));  // 0.4 of the pack
    FAIL() << "expected DepletionError";
  } catch (const DepletionError& e) {
    EXPECT_NEAR(e.reachedSoc(), -0.1, 1e-12);
    EXPECT_NE(std::string(e.what()).find("-10 % SOC, 10 points below its 0 % floor"), std::string::npos) << e.what();
  }
  EXPECT_DOUBLE_EQ(simulator.state().soc, 0.3);  // unchanged
}

TEST(Simulator, RefusesInvalidSegments) {
  Simulator simulator(Pack{}, 0.5);
  EXPECT_THROW(simulator.run(Segment::discharge(-1.0, 10.0)), ceilplan::InputError);
  EXPECT_THROW(simulator.run(Segment::discharge(kNaN, 10.0)), ceilplan::InputError);
  EXPECT_THROW(simulator.run(Segment::discharge(1.0, kNaN)), ceilplan::InputError);
  EXPECT_THROW(simulator.run(Segment::idle(-5.0)), ceilplan::InputError);
  EXPECT_THROW(simulator.run(Segment::charge(0.0, 600.0, 0.95)), ceilplan::InputError);
  EXPECT_THROW(simulator.run(Segment::charge(10.4, 600.0, 1.2)), ceilplan::InputError);
  EXPECT_THROW(simulator.run(Segment::charge(10.4, 600.0, 0.0)), ceilplan::InputError);
}

TEST(Simulator, RefusesInvalidPacksAndStartStates) {
  Pack no_capacity;
  no_capacity.capacity_ah = 0.0;
  EXPECT_THROW(Simulator(no_capacity, 0.5), ceilplan::InputError);
  Pack negative;
  negative.capacity_ah = -5.2;
  EXPECT_THROW(Simulator(negative, 0.5), ceilplan::InputError);
  Pack nan_capacity;
  nan_capacity.capacity_ah = kNaN;
  EXPECT_THROW(Simulator(nan_capacity, 0.5), ceilplan::InputError);
  EXPECT_THROW(Simulator(Pack{}, 0.0), ceilplan::InputError);
  EXPECT_THROW(Simulator(Pack{}, 1.01), ceilplan::InputError);
  EXPECT_THROW(Simulator(Pack{}, kNaN), ceilplan::InputError);
  EXPECT_THROW(Simulator(Pack{}, 0.5, -30.0), ceilplan::InputError);
  Simulator simulator(Pack{}, 0.5);
  EXPECT_THROW(simulator.setStateOfHealth(0.0), ceilplan::InputError);
}

}  // namespace
}  // namespace ceilplan::battery
