#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/ground_effect.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

using namespace ceilplan::energy;

namespace {
const AirframeParameters kQuad{};  // R = 0.127 m, 450 mm X frame
constexpr double kR = 0.127;
}  // namespace

TEST(GroundEffect, CheesemanBennettMatchesReferenceSection3Values) {
  const GroundEffect ground(GroundEffectParameters{}, kQuad);
  EXPECT_NEAR(ground.thrustRatio(0.5 * kR), 4.0 / 3.0, 1e-12);    // 1.333
  EXPECT_NEAR(ground.thrustRatio(1.0 * kR), 16.0 / 15.0, 1e-12);  // 1.067
  EXPECT_NEAR(ground.thrustRatio(2.0 * kR), 64.0 / 63.0, 1e-12);  // 1.016
}

TEST(GroundEffect, ClampsBelowHalfARadius) {
  const GroundEffect ground(GroundEffectParameters{}, kQuad);
  EXPECT_DOUBLE_EQ(ground.thrustRatio(0.0), ground.thrustRatio(0.5 * kR));
  EXPECT_DOUBLE_EQ(ground.thrustRatio(0.2 * kR), ground.thrustRatio(0.5 * kR));
}

TEST(GroundEffect, NoGroundMeansNoEffect) {
  const GroundEffect ground(GroundEffectParameters{}, kQuad);
  EXPECT_EQ(ground.thrustRatio(std::numeric_limits<double>::infinity()), 1.0);
}

TEST(GroundEffect, MultirotorFormAddsTheNeighbouringRotorsToTheSingleRotorTerm) {
  GroundEffectParameters multirotor;
  multirotor.model = GroundEffectModel::kMultirotor;
  const GroundEffect single(GroundEffectParameters{}, kQuad);
  const GroundEffect multi(multirotor, kQuad);
  for (double z : {0.5 * kR, kR, 2.0 * kR, 5.0 * kR}) EXPECT_GT(multi.thrustRatio(z), single.thrustRatio(z));
  // Hand evaluation at z = R of Sanchez-Cuevas et al. 2017's formula, d = 0.318 m, b = 0.45 m, K_b = 2.
  const double z = kR, d = 0.225 * std::sqrt(2.0), b = 0.45, r2 = kR * kR;
  const double expected =
      1.0 / (1.0 - r2 / (16 * z * z) - r2 * z / std::pow(d * d + 4 * z * z, 1.5) -
             0.5 * r2 * z / std::pow(2 * d * d + 4 * z * z, 1.5) - 2 * r2 * 2.0 * z / std::pow(b * b + 4 * z * z, 1.5));
  EXPECT_NEAR(multi.thrustRatio(z), expected, 1e-12);
}

TEST(GroundEffect, MultirotorFormRefusesASingleRotorAndRotorsTooClose) {
  GroundEffectParameters multirotor;
  multirotor.model = GroundEffectModel::kMultirotor;
  AirframeParameters single = kQuad;
  single.rotor_count = 1;
  EXPECT_THROW(GroundEffect(multirotor, single), ceilplan::InputError);
  AirframeParameters crowded = kQuad;
  crowded.adjacent_rotor_spacing_m = 0.01;
  crowded.opposite_rotor_spacing_m = 0.014;
  EXPECT_THROW(GroundEffect(multirotor, crowded), ceilplan::InputError);
}
