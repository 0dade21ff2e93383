#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/rotary_wing_power.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using ceilplan::energy::RotaryWingPower;

namespace {
// Zeng, Xu, Zhang 2019 (IEEE T-WC 18(4)), the published example (docs/models.md).
RotaryWingPower zengExample() {
  return RotaryWingPower::fromBladeParameters(0.012, 1.225, 0.05, 0.503, 300.0, 0.4, 0.1, 20.0, 0.6);
}
}  // namespace

TEST(RotaryWingPower, ReproducesZengsPublishedHoverPowers) {
  const RotaryWingPower zeng = zengExample();
  EXPECT_NEAR(zeng.hoverProfilePowerW(), 79.86, 0.005);
  EXPECT_NEAR(zeng.hoverInducedPowerW(), 88.63, 0.005);
  EXPECT_NEAR(zeng.powerW(0.0), 168.5, 0.05);
}

TEST(RotaryWingPower, HasZengsMinimumPowerSpeed) {
  const RotaryWingPower zeng = zengExample();
  double best_speed = 0.0, best_power = zeng.powerW(0.0);
  for (double v = 0.0; v <= 30.0; v += 0.01) {
    if (zeng.powerW(v) < best_power) {
      best_power = zeng.powerW(v);
      best_speed = v;
    }
  }
  EXPECT_NEAR(best_speed, 10.2, 0.15);
  EXPECT_NEAR(best_power, 126.0, 0.5);
}

TEST(RotaryWingPower, InducedPowerFallsWithSpeedAndParasiticRisesAsTheCube) {
  const RotaryWingPower zeng = zengExample();
  EXPECT_DOUBLE_EQ(zeng.inducedSpeedFactor(0.0), 1.0);
  EXPECT_LT(zeng.inducedSpeedFactor(10.0), zeng.inducedSpeedFactor(5.0));
  EXPECT_NEAR(zeng.parasiticPowerW(10.0), 8.0 * zeng.parasiticPowerW(5.0), 1e-9);
}

TEST(RotaryWingPower, ScalingRefusesHoverPowerBelowTheMomentumInducedPower) {
  EXPECT_THROW(RotaryWingPower::scaledToHover(10.0, 13.7, 0.2, 0.1, 80.0, 0.03, 1.225), ceilplan::InputError);
  const RotaryWingPower scaled = RotaryWingPower::scaledToHover(110.0, 13.7, 0.2, 0.1, 80.0, 0.03, 1.225);
  EXPECT_NEAR(scaled.powerW(0.0), 110.0, 1e-12);
}
