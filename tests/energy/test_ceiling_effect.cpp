#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/ceiling_effect.hpp"
#include "ceilplan/energy/paper_quad.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

using namespace ceilplan::energy;

namespace {
constexpr double kRadiusM = 0.127;
CeilingEffect defaultCeiling() { return CeilingEffect(paperQuadParameters().ceiling, kRadiusM); }
}  // namespace

TEST(CeilingEffect, FollowsTheImageMethodShapeBelowTheTaper) {
  const CeilingEffectParameters p{8.0, 0.06, 1.5, 2.5};
  const CeilingEffect ceiling(p, kRadiusM);
  for (double z : {0.0, 0.02, 0.1, 1.5 * kRadiusM}) {
    const double expected = 1.0 / (1.0 - (1.0 / p.k1) * std::pow(kRadiusM / (z + p.k2_m), 2));
    EXPECT_NEAR(ceiling.thrustRatio(z), expected, 1e-12) << "gap " << z;
  }
}

TEST(CeilingEffect, VanishesExactlyFromTheTaperEndOn) {
  const CeilingEffect ceiling = defaultCeiling();
  EXPECT_EQ(ceiling.thrustRatio(2.5 * kRadiusM), 1.0);
  EXPECT_EQ(ceiling.thrustRatio(100.0), 1.0);
  EXPECT_EQ(ceiling.thrustRatio(std::numeric_limits<double>::infinity()), 1.0);
  EXPECT_GT(ceiling.thrustRatio(2.0 * kRadiusM), 1.0);
}

TEST(CeilingEffect, IsContinuousAndStrictlyFallingUpToTheTaperEnd) {
  const CeilingEffect ceiling = defaultCeiling();
  const double step = 1e-5;
  double previous = ceiling.thrustRatio(0.0);
  for (double z = step; z < 2.5 * kRadiusM; z += step) {
    const double current = ceiling.thrustRatio(z);
    EXPECT_LT(current, previous) << "gap " << z;
    EXPECT_LT(previous - current, 1e-3) << "jump at gap " << z;
    previous = current;
  }
}

TEST(CeilingEffect, IsBoundedAtContact) {
  EXPECT_NEAR(defaultCeiling().contactThrustRatio(), kContactThrustRatio, 1e-12);
}

TEST(CeilingEffect, ScalesTheExcessWithCoverage) {
  const CeilingEffect ceiling = defaultCeiling();
  const double full = ceiling.thrustRatio(0.05);
  EXPECT_DOUBLE_EQ(ceiling.thrustRatio(0.05, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(ceiling.thrustRatio(0.05, 1.0), full);
  EXPECT_NEAR(ceiling.thrustRatio(0.05, 0.5), 1.0 + 0.5 * (full - 1.0), 1e-15);
}

TEST(CeilingEffect, RefusesConstantsThatAreSingularAtContact) {
  EXPECT_THROW(CeilingEffect({1.0, 0.1, 1.5, 2.5}, kRadiusM), ceilplan::InputError);  // R^2/(K1 K2^2) > 1
  EXPECT_THROW(CeilingEffect({5.0, 0.0, 1.5, 2.5}, kRadiusM), ceilplan::InputError);
  EXPECT_THROW(CeilingEffect({-5.0, 0.05, 1.5, 2.5}, kRadiusM), ceilplan::InputError);
  EXPECT_THROW(CeilingEffect({5.0, 0.05, 2.5, 1.5}, kRadiusM), ceilplan::InputError);
}
