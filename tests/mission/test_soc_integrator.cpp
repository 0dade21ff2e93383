// A load profile in steps (stepProfile), what the large-tour split flies home: the same charge
// from any SOC, to within what the integration itself leaves, in a few samples per step.

#include "ceilplan/core/error.hpp"
#include "ceilplan/mission/soc_integrator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace ceilplan::mission {
namespace {

// A way home as the tours score one: a sample every 25 ms (5 cm at 2 m/s) for 500 s, the
// propulsion power wandering between 120 and 180 W with a jump at each of 40 girders.
std::vector<LoadSample> wayHome() {
  std::mt19937_64 random(7);
  std::normal_distribution<double> wander(0.0, 0.5);
  std::vector<LoadSample> profile;
  double power_w = 150.0;
  for (int k = 0; k <= 20000; ++k) {
    power_w = std::clamp(power_w + wander(random), 120.0, 180.0);
    const double girder_w = (k / 500) % 2 == 0 ? 0.0 : -15.0;  // under a girder the ceiling effect helps
    profile.push_back({0.025 * k, power_w + girder_w});
  }
  return profile;
}

// A 4S pack's current for a power: an Rint pack, its open-circuit voltage falling with the SOC.
double packCurrentA(double power_w, double soc) {
  const double open_circuit_v = 13.6 + 3.2 * soc, resistance_ohm = 0.03;
  return (open_circuit_v - std::sqrt(open_circuit_v * open_circuit_v - 4.0 * resistance_ohm * power_w)) /
         (2.0 * resistance_ohm);
}

double chargeFlownAh(const std::vector<LoadSample>& profile, double start_soc, const CurrentAtSoc& current) {
  battery::Pack pack;
  pack.capacity_ah = 5.2;
  SocIntegrator flight(pack, start_soc, current);
  flyProfile(flight, profile, {});
  return flight.chargeAh();
}

TEST(StepProfile, AWayHomeInAHoversStepsDrawsItsChargeFromAnySoc) {
  const std::vector<LoadSample> profile = wayHome();
  const std::vector<LoadSample> steps = stepProfile(profile, kHoverStepS);
  // Two samples per second instead of forty.
  EXPECT_LE(steps.size(), 2u * 500u + 2u);
  EXPECT_GE(steps.size(), 2u * 500u - 2u);
  for (const double start_soc : {0.95, 0.7, 0.45}) {
    const double full_ah = chargeFlownAh(profile, start_soc, packCurrentA);
    const double stepped_ah = chargeFlownAh(steps, start_soc, packCurrentA);
    EXPECT_GT(full_ah, 0.1);
    // Each step's current at its end is the one at the SOC of its start, as in a hover's steps:
    // over 500 s, as the current rises with the falling SOC, that lag leaves about half a step's
    // rise, 6e-5 Ah of 1.2 Ah.
    EXPECT_NEAR(stepped_ah, full_ah, 1e-4 * full_ah) << "from SOC " << start_soc;
    EXPECT_LT(stepped_ah, full_ah) << "the lag draws less, never more";
  }
}

TEST(StepProfile, KeepsTheLoadsIntegralExactlyWhereTheLoadIsTheCurrent) {
  const std::vector<LoadSample> profile = wayHome();
  for (const double step_s : {0.1, 1.0, 7.5, 1000.0}) {
    const std::vector<LoadSample> steps = stepProfile(profile, step_s);
    EXPECT_NEAR(chargeFlownAh(steps, 0.95, {}), chargeFlownAh(profile, 0.95, {}), 1e-12) << step_s;
    EXPECT_EQ(steps.front().t_s, profile.front().t_s);
    EXPECT_EQ(steps.back().t_s, profile.back().t_s);
    for (std::size_t k = 0; k + 1 < steps.size(); k += 2) {
      EXPECT_EQ(steps[k].load, steps[k + 1].load) << "a step draws one load";
      EXPECT_LE(steps[k + 1].t_s - steps[k].t_s, step_s + 1e-9);
      if (k + 2 < steps.size()) {
        EXPECT_EQ(steps[k + 2].t_s, steps[k + 1].t_s) << "steps follow without a gap";
      }
    }
  }
}

TEST(StepProfile, AnIntervalLongerThanAStepIsAStepOfItsOwn) {
  const std::vector<LoadSample> profile{{0.0, 10.0}, {0.5, 20.0}, {5.0, 20.0}, {5.5, 10.0}};
  const std::vector<LoadSample> steps = stepProfile(profile, 1.0);
  ASSERT_EQ(steps.size(), 6u);
  EXPECT_DOUBLE_EQ(steps[0].load, 15.0);  // 0 .. 0.5 s
  EXPECT_DOUBLE_EQ(steps[2].t_s, 0.5);
  EXPECT_DOUBLE_EQ(steps[3].t_s, 5.0);
  EXPECT_DOUBLE_EQ(steps[3].load, 20.0);  // 0.5 .. 5 s, longer than the step
  EXPECT_DOUBLE_EQ(steps[5].load, 15.0);  // 5 .. 5.5 s
}

TEST(StepProfile, ShortProfilesComeBackAsTheyAreAndABadStepIsRefused) {
  const std::vector<LoadSample> two{{0.0, 3.0}, {4.0, 5.0}};
  const std::vector<LoadSample> same = stepProfile(two, 1.0);
  ASSERT_EQ(same.size(), 2u);
  EXPECT_EQ(same[1].t_s, 4.0);
  EXPECT_EQ(same[1].load, 5.0);
  for (const double bad :
       {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    EXPECT_THROW(stepProfile(wayHome(), bad), ceilplan::InputError) << bad;
}

}  // namespace
}  // namespace ceilplan::mission
