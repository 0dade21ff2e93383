#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/energy/paper_quad.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <future>
#include <stdexcept>
#include <vector>

using namespace ceilplan::energy;

namespace {

FlightCondition hover(double soc = kPaperReferenceSoc) {
  FlightCondition flight;
  flight.soc = soc;
  return flight;
}

const EnergyModel& paperModel() {
  static const EnergyModel model(paperQuadParameters());
  return model;
}

}  // namespace

TEST(EnergyModel, DrawsThePapersNinePointFiveAmpsHoveringInFreeAir) {
  EXPECT_NEAR(paperModel().currentA(kNoSurface, 1.0, hover()), kPaperFreeAirCurrentA, 1e-9);
}

TEST(EnergyModel, DrawsThePapersEightAmpsFiveCentimetresUnderAFullCeiling) {
  EXPECT_NEAR(paperModel().currentA(0.05, 1.0, hover()), kPaperCeilingCurrentA, 1e-9);
}

TEST(EnergyModel, AHundredMetreGapIsFreeAir) {
  EXPECT_NEAR(paperModel().currentA(100.0, 1.0, hover()), paperModel().currentA(kNoSurface, 1.0, hover()), 1e-9);
}

TEST(EnergyModel, CurrentIsContinuousAndNeverFallsWithGrowingGap) {
  const EnergyModel& model = paperModel();
  const double step_m = 1e-4;
  double previous = model.currentA(0.0, 1.0, hover());
  for (double gap = step_m; gap <= 0.5; gap += step_m) {
    const double current = model.currentA(gap, 1.0, hover());
    EXPECT_GE(current, previous) << "gap " << gap;
    EXPECT_LT(current - previous, 150.0 * step_m) << "jump at gap " << gap;  // steepest near contact: ~110 A/m
    previous = current;
  }
  EXPECT_NEAR(previous, kPaperFreeAirCurrentA, 1e-12);
}

TEST(EnergyModel, LessCoverageGivesLessBenefit) {
  const EnergyModel& model = paperModel();
  EXPECT_LT(model.currentA(0.05, 1.0, hover()), model.currentA(0.05, 0.5, hover()));
  EXPECT_LT(model.currentA(0.05, 0.5, hover()), model.currentA(0.05, 0.0, hover()));
  EXPECT_NEAR(model.currentA(0.05, 0.0, hover()), kPaperFreeAirCurrentA, 1e-12);
}

TEST(EnergyModel, PerRotorGapsAgreeWithTheConvenienceFormWhenAllAlike) {
  const EnergyModel& model = paperModel();
  const RotorCeiling same[4] = {{0.05, 0.7}, {0.05, 0.7}, {0.05, 0.7}, {0.05, 0.7}};
  EXPECT_NEAR(model.currentA(same, 4, hover()), model.currentA(0.05, 0.7, hover()), 1e-12);
}

TEST(EnergyModel, HalfTheRotorsUnderTheCeilingSaveLessThanAll) {
  const EnergyModel& model = paperModel();
  const RotorCeiling half[4] = {{0.05, 1.0}, {0.05, 1.0}, {kNoSurface, 1.0}, {kNoSurface, 1.0}};
  const double current = model.currentA(half, 4, hover());
  EXPECT_GT(current, kPaperCeilingCurrentA);
  EXPECT_LT(current, kPaperFreeAirCurrentA);
  const CurrentBreakdown b = model.breakdown(half, 4, hover());
  EXPECT_NEAR(b.ceiling_factor, (1.0 + model.ceilingEffect().thrustRatio(0.05)) / 2.0, 1e-12);
}

TEST(EnergyModel, GroundEffectLowersCurrentAndAddsToTheCeilings) {
  const EnergyModel& model = paperModel();
  FlightCondition near_ground = hover();
  near_ground.ground_gap_m = 0.127;
  const CurrentBreakdown b = model.breakdown(kNoSurface, 1.0, near_ground);
  EXPECT_NEAR(b.ground_factor, 16.0 / 15.0, 1e-12);
  EXPECT_LT(b.current_a, kPaperFreeAirCurrentA);
  EXPECT_LT(model.currentA(0.05, 1.0, near_ground), kPaperCeilingCurrentA);
}

TEST(EnergyModel, BreakdownAddsUpToThePower) {
  FlightCondition flight = hover();
  flight.speed_m_s = 6.0;
  flight.climb_m_s = 0.5;
  const CurrentBreakdown b = paperModel().breakdown(0.1, 0.8, flight);
  EXPECT_NEAR(b.induced_w + b.profile_w + b.parasitic_w + b.climb_w + b.avionics_w, b.power_w, 1e-9);
  EXPECT_NEAR(b.terminal_voltage_v * b.current_a, b.power_w, 1e-9);
}

TEST(EnergyModel, HasAMinimumPowerSpeedBelowTheSpeedLimit) {
  const EnergyModel& model = paperModel();
  FlightCondition flight = hover();
  double best_speed = 0.0, best_current = model.currentA(kNoSurface, 1.0, flight);
  for (double v = 0.0; v <= model.maxSpeedM_s(); v += 0.05) {
    flight.speed_m_s = v;
    const double current = model.currentA(kNoSurface, 1.0, flight);
    if (current < best_current) {
      best_current = current;
      best_speed = v;
    }
  }
  EXPECT_GT(best_speed, 3.0);
  EXPECT_LT(best_speed, model.maxSpeedM_s() - 1.0);
  EXPECT_LT(best_current, 0.9 * kPaperFreeAirCurrentA);
}

TEST(EnergyModel, ClimbCostsMgVOverEfficiencyAndDescentIsFloored) {
  const EnergyModel& model = paperModel();
  const EnergyParameters& p = model.parameters();
  FlightCondition climb = hover();
  climb.climb_m_s = 1.0;
  EXPECT_NEAR(model.breakdown(kNoSurface, 1.0, climb).climb_w,
              p.airframe.mass_kg * kStandardGravityM_s2 / p.rotor.motor_efficiency, 1e-9);
  FlightCondition fast_descent = hover();
  fast_descent.climb_m_s = -p.airframe.max_speed_m_s;  // the fastest descent the vehicle allows
  const CurrentBreakdown b = model.breakdown(kNoSurface, 1.0, fast_descent);
  EXPECT_NEAR(b.induced_w + b.profile_w + b.parasitic_w + b.climb_w,
              p.rotor.descent_power_floor * (b.induced_w + b.profile_w + b.parasitic_w), 1e-9);
  EXPECT_GT(b.current_a, 0.0);
}

TEST(EnergyModel, LowerChargeMeansLowerVoltageAndMoreCurrentForTheSamePower) {
  const EnergyModel& model = paperModel();
  const CurrentBreakdown full = model.breakdown(kNoSurface, 1.0, hover(0.95));
  const CurrentBreakdown low = model.breakdown(kNoSurface, 1.0, hover(0.30));
  EXPECT_NEAR(full.power_w - full.avionics_w, low.power_w - low.avionics_w, 1e-9);
  EXPECT_LT(full.current_a, kPaperFreeAirCurrentA);
  EXPECT_GT(low.current_a, kPaperFreeAirCurrentA);
  // Rint by hand at SOC 0.95: 4 x OCV, minus R I.
  const double ocv_v = 4.0 * (4.085 + (0.95 - 0.9231) / (0.9615 - 0.9231) * (4.112 - 4.085));
  EXPECT_NEAR(full.terminal_voltage_v, ocv_v - 0.020 * full.current_a, 1e-12);
}

TEST(EnergyModel, ConstantPowerConventionGivesASmallerBenefitForTheSameThrustRatio) {
  EnergyParameters p = paperQuadParameters();
  p.rotor.convention = ThrustToPowerConvention::kConstantPower;
  const EnergyModel constant_power(p);
  const double kappa = paperModel().ceilingEffect().thrustRatio(0.05);
  EXPECT_NEAR(constant_power.breakdown(0.05, 1.0, hover()).induced_power_factor, 1.0 / kappa, 1e-12);
  EXPECT_NEAR(paperModel().breakdown(0.05, 1.0, hover()).induced_power_factor, std::pow(kappa, -1.5), 1e-12);
  EXPECT_GT(constant_power.currentA(0.05, 1.0, hover()), kPaperCeilingCurrentA);
}

TEST(EnergyModel, RefusesBadFlightInput) {
  const EnergyModel& model = paperModel();
  EXPECT_THROW(model.currentA(-0.01, 1.0, hover()), ceilplan::InputError);
  EXPECT_THROW(model.currentA(std::nan(""), 1.0, hover()), ceilplan::InputError);
  EXPECT_THROW(model.currentA(0.1, 1.5, hover()), ceilplan::InputError);
  EXPECT_THROW(model.currentA(0.1, 1.0, hover(1.2)), ceilplan::InputError);
  FlightCondition too_fast = hover();
  too_fast.speed_m_s = model.maxSpeedM_s() + 0.1;
  EXPECT_THROW(model.currentA(kNoSurface, 1.0, too_fast), ceilplan::InputError);
  FlightCondition bad_ground = hover();
  bad_ground.ground_gap_m = -1.0;
  EXPECT_THROW(model.currentA(kNoSurface, 1.0, bad_ground), ceilplan::InputError);
  const RotorCeiling three[3] = {};
  EXPECT_THROW(model.currentA(three, 3, hover()), ceilplan::InputError);
}

TEST(EnergyModel, RefusesBadVehicles) {
  EnergyParameters no_rotors = paperQuadParameters();
  no_rotors.airframe.rotor_count = 0;
  EXPECT_THROW(EnergyModel{no_rotors}, ceilplan::InputError);
  EnergyParameters negative_mass = paperQuadParameters();
  negative_mass.airframe.mass_kg = -1.4;
  EXPECT_THROW(EnergyModel{negative_mass}, ceilplan::InputError);
  EnergyParameters weak = paperQuadParameters();
  weak.rotor.hover_power_w = 20.0;  // below momentum theory's induced power
  EXPECT_THROW(EnergyModel{weak}, ceilplan::InputError);
}

TEST(PaperQuad, AnchorSolvesForTheMeasuredCurrentUnderEitherConvention) {
  EnergyParameters p = paperQuadParameters();
  p.rotor.convention = ThrustToPowerConvention::kConstantPower;
  p.ceiling = ceilingThroughAnchor(p, 0.05, 8.0, kPaperReferenceSoc, kContactThrustRatio);
  EXPECT_NEAR(EnergyModel(p).currentA(0.05, 1.0, hover()), 8.0, 1e-9);
  EXPECT_THROW(ceilingThroughAnchor(p, 0.05, 9.6, kPaperReferenceSoc, kContactThrustRatio), ceilplan::InputError);
  EXPECT_THROW(ceilingThroughAnchor(p, 0.30, 8.0, kPaperReferenceSoc, kContactThrustRatio), ceilplan::InputError);
}

TEST(EnergyModel, OneModelServesManyThreadsWithIdenticalAnswers) {
  const EnergyModel& model = paperModel();
  auto sweep = [&model] {
    std::vector<double> currents;
    for (int i = 0; i < 2000; ++i) {
      FlightCondition flight = hover(0.3 + 0.0003 * i);
      flight.speed_m_s = (i % 10) * 1.0;
      currents.push_back(model.currentA(0.0002 * i, 1.0, flight));
    }
    return currents;
  };
  const std::vector<double> expected = sweep();
  std::vector<std::future<std::vector<double>>> runs;
  for (int t = 0; t < 4; ++t) runs.push_back(std::async(std::launch::async, sweep));
  for (auto& run : runs) EXPECT_EQ(run.get(), expected);
}
