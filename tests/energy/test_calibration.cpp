#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/calibration.hpp"
#include "ceilplan/energy/paper_quad.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

using namespace ceilplan::energy;

namespace {

// The constants the synthetic measurements are made with: not the defaults the fit starts from.
EnergyParameters truth(bool motion_constants_too) {
  EnergyParameters p = paperQuadParameters();
  p.rotor.hover_power_w = 150.0;
  p.ceiling.k1 = 6.0;
  p.ceiling.k2_m = 0.06;
  if (motion_constants_too) {
    p.rotor.motor_efficiency = 0.72;
    p.rotor.drag_area_m2 = 0.05;
  }
  return p;
}

std::vector<CalibrationSample> synthetic(const EnergyParameters& p, bool vary_motion) {
  const EnergyModel model(p);
  std::vector<CalibrationSample> samples;
  const double gaps[] = {kNoSurface, 0.005, 0.01, 0.02, 0.04, 0.07, 0.1, 0.15, 0.2, 0.4};
  const double climbs[] = {0.0, 1.0, -0.5};
  const double speeds[] = {0.0, 4.0, 9.0};
  const double socs[] = {0.9, 0.6};
  for (double gap : gaps)
    for (double climb :
         vary_motion ? std::vector<double>(std::begin(climbs), std::end(climbs)) : std::vector<double>{0.0})
      for (double speed :
           vary_motion ? std::vector<double>(std::begin(speeds), std::end(speeds)) : std::vector<double>{0.0})
        for (double soc : socs) {
          CalibrationSample s;
          s.ceiling_gap_m = gap;
          s.climb_m_s = climb;
          s.speed_m_s = speed;
          s.soc = soc;
          FlightCondition flight;
          flight.climb_m_s = climb;
          flight.speed_m_s = speed;
          flight.soc = soc;
          s.current_a = model.currentA(gap, 1.0, flight);
          samples.push_back(s);
        }
  return samples;
}

void expectRecovered(const CalibrationResult& result, FreeParameter parameter, double expected) {
  for (const FittedParameter& fitted : result.fitted)
    if (fitted.parameter == parameter) {
      EXPECT_NEAR(fitted.value, expected, 1e-3 * expected) << parameterName(parameter);
      return;
    }
  ADD_FAILURE() << parameterName(parameter) << " was not fitted";
}

}  // namespace

TEST(Calibration, RecoversCeilingConstantsAndHoverPowerFromSyntheticHoverData) {
  const auto samples = synthetic(truth(false), false);
  const auto free = identifiableParameters(paperQuadParameters(), samples);
  ASSERT_EQ(free, (std::vector<FreeParameter>{FreeParameter::kHoverPowerW, FreeParameter::kK1, FreeParameter::kK2M}));
  const CalibrationResult result = calibrate(paperQuadParameters(), samples, free);
  expectRecovered(result, FreeParameter::kHoverPowerW, 150.0);
  expectRecovered(result, FreeParameter::kK1, 6.0);
  expectRecovered(result, FreeParameter::kK2M, 0.06);
  EXPECT_LT(result.rmse_a, 1e-5);
}

TEST(Calibration, RecoversEfficiencyAndDragWhenClimbAndSpeedVary) {
  const auto samples = synthetic(truth(true), true);
  const auto free = identifiableParameters(paperQuadParameters(), samples);
  ASSERT_EQ(free.size(), 5u);
  const CalibrationResult result = calibrate(paperQuadParameters(), samples, free);
  expectRecovered(result, FreeParameter::kHoverPowerW, 150.0);
  expectRecovered(result, FreeParameter::kK1, 6.0);
  expectRecovered(result, FreeParameter::kK2M, 0.06);
  expectRecovered(result, FreeParameter::kMotorEfficiency, 0.72);
  expectRecovered(result, FreeParameter::kDragAreaM2, 0.05);
}

TEST(Calibration, ReportsEachFittedValueWithItsAllowedRange) {
  const CalibrationResult result =
      calibrate(paperQuadParameters(), synthetic(truth(false), false), {FreeParameter::kHoverPowerW});
  ASSERT_EQ(result.fitted.size(), 1u);
  const FittedParameter& hover = result.fitted.front();
  EXPECT_LE(hover.lower, hover.value);
  EXPECT_LE(hover.value, hover.upper);
  EXPECT_GT(result.rmse_a, 0.0);  // K1, K2 left wrong on purpose
  EXPECT_GE(result.max_abs_error_a, result.rmse_a);
  EXPECT_FALSE(hover.atBound());
}

TEST(Calibration, AFitAtAnEndOfItsRangeSaysSo) {
  FittedParameter fitted{FreeParameter::kK1, 2.0, 1.0, 4.0, 2.0};
  EXPECT_FALSE(fitted.atBound());
  fitted.value = 1.0 + 1e-7;  // within 1e-6 of the lower end
  EXPECT_TRUE(fitted.atBound());
  fitted.value = 4.0;
  EXPECT_TRUE(fitted.atBound());
  fitted.value = 4.0 * (1 - 1e-5);
  EXPECT_FALSE(fitted.atBound());
}

namespace {
std::string refusal(const std::vector<CalibrationSample>& samples, const std::vector<FreeParameter>& free) {
  try {
    calibrate(paperQuadParameters(), samples, free);
  } catch (const ceilplan::InputError& e) {
    return e.what();
  }
  return "(accepted)";
}
}  // namespace

TEST(Calibration, RefusesAParameterWhoseColumnIsNotVaried) {
  const auto hover_only = synthetic(truth(false), false);
  EXPECT_NE(refusal(hover_only, {FreeParameter::kHoverPowerW, FreeParameter::kMotorEfficiency})
                .find("cannot identify motor_efficiency"),
            std::string::npos);
  EXPECT_NE(refusal(hover_only, {FreeParameter::kDragAreaM2}).find("cannot identify drag_area_m2"), std::string::npos);
  std::vector<CalibrationSample> free_air(4);
  for (auto& s : free_air) s.current_a = 9.5;
  EXPECT_NE(refusal(free_air, {FreeParameter::kK1}).find("cannot identify k1"), std::string::npos);
}

TEST(Calibration, RefusesAFlatDirectionNamingTheParameter) {
  // One ceiling gap only: K1 and K2 trade against each other along a whole curve.
  std::vector<CalibrationSample> two_gaps(4);
  for (std::size_t i = 0; i < two_gaps.size(); ++i) {
    two_gaps[i].ceiling_gap_m = i % 2 ? 0.05 : kNoSurface;
    two_gaps[i].current_a = i % 2 ? 8.0 : 9.5;
  }
  const std::string message = refusal(two_gaps, {FreeParameter::kHoverPowerW, FreeParameter::kK1, FreeParameter::kK2M});
  EXPECT_TRUE(message.find("cannot identify k1") != std::string::npos ||
              message.find("cannot identify k2_m") != std::string::npos)
      << message;
}

TEST(Calibration, RefusesTooFewSamplesAndBadSamples) {
  std::vector<CalibrationSample> one(1);
  one[0].current_a = 9.5;
  EXPECT_THROW(calibrate(paperQuadParameters(), one, {FreeParameter::kHoverPowerW}), ceilplan::InputError);
  std::vector<CalibrationSample> negative_gap(3);
  for (auto& s : negative_gap) s.current_a = 9.5;
  negative_gap[1].ceiling_gap_m = -0.1;
  EXPECT_THROW(calibrate(paperQuadParameters(), negative_gap, {FreeParameter::kHoverPowerW}), ceilplan::InputError);
  EXPECT_THROW(parseFreeParameter("k3"), ceilplan::InputError);
  EXPECT_EQ(parseFreeParameter("k2_m"), FreeParameter::kK2M);
}

TEST(Calibration, AFailedFitSaysWhatFailedAndWhatToDo) {
  // NLopt reports a failed L-BFGS run only as "nlopt failure". One current of 1e200 A (an
  // outlier) makes the squared errors overflow: the message says that, names the column and
  // the value, and what to do.
  auto samples = synthetic(truth(false), false);
  samples[3].current_a = 1e200;
  try {
    calibrate(paperQuadParameters(), samples, {FreeParameter::kHoverPowerW, FreeParameter::kK1, FreeParameter::kK2M});
    FAIL() << "a fit to a 1e200 A current succeeded";
  } catch (const ceilplan::Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("NLopt's L-BFGS gave up"), std::string::npos) << message;
    EXPECT_NE(message.find("squared errors overflow: current_a reaches 1e+200 A"), std::string::npos) << message;
    EXPECT_NE(message.find("give every current in amperes"), std::string::npos) << message;
  }
}

TEST(Calibration, MessagesPrintNumbersThroughTheOneFormatter) {
  std::vector<CalibrationSample> free_air(4);
  for (auto& s : free_air) s.current_a = 9.5;
  EXPECT_NE(refusal(free_air, {FreeParameter::kK1}).find("within 2.5 rotor radii"), std::string::npos)
      << refusal(free_air, {FreeParameter::kK1});  // std::to_string said "2.500000"
}

namespace {

// The hover data set with Gaussian noise of `sigma_a` on every current, drawn with `seed`.
std::vector<CalibrationSample> noisy(const std::vector<CalibrationSample>& clean, double sigma_a, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> noise(0.0, sigma_a);
  std::vector<CalibrationSample> samples = clean;
  for (CalibrationSample& s : samples) s.current_a += noise(random);
  return samples;
}

}  // namespace

// Gauss-Newton's covariance is a specification of how far a fit's estimates scatter: over
// repeated fits of independently noisy data (same conditions, seeds 1..kFits), the spread of each
// estimate equals its reported standard error. With kFits = 60 the sample standard deviation of a
// normal variable is within +-20 % of the truth with > 99 % probability (its relative standard
// error is 1 / sqrt(2 (kFits - 1)) = 9.2 %, so 20 % is 2.2 of them); a 25 % tolerance also covers
// the linearisation.
TEST(CalibrationUncertainty, StandardErrorsMatchTheSpreadOfRepeatedFits) {
  constexpr int kFits = 60;
  constexpr double kSigmaA = 0.05;
  // Three copies of each condition: 120 samples, 3 parameters.
  std::vector<CalibrationSample> clean;
  for (int copy = 0; copy < 3; ++copy) {
    const auto once = synthetic(truth(false), false);
    clean.insert(clean.end(), once.begin(), once.end());
  }
  const std::vector<FreeParameter> free{FreeParameter::kHoverPowerW, FreeParameter::kK1, FreeParameter::kK2M};
  std::vector<std::vector<double>> estimates(free.size());
  std::vector<double> reported(free.size(), 0.0);
  double residual_std_sum_a = 0.0;
  for (int fit = 0; fit < kFits; ++fit) {
    const CalibrationResult result =
        calibrate(paperQuadParameters(), noisy(clean, kSigmaA, static_cast<unsigned>(fit + 1)), free);
    ASSERT_TRUE(result.uncertainty.hasCovariance()) << result.uncertainty.unavailable;
    ASSERT_EQ(result.uncertainty.parameters, free);
    for (std::size_t k = 0; k < free.size(); ++k) {
      estimates[k].push_back(result.fitted[k].value);
      reported[k] += result.uncertainty.standard_errors[k] / kFits;
      EXPECT_DOUBLE_EQ(result.uncertainty.standard_errors[k] * result.uncertainty.standard_errors[k],
                       result.uncertainty.covariance[k][k]);
    }
    residual_std_sum_a += result.uncertainty.residual_std_a;
  }
  for (std::size_t k = 0; k < free.size(); ++k) {
    double mean = 0.0;
    for (double v : estimates[k]) mean += v / kFits;
    double variance = 0.0;
    for (double v : estimates[k]) variance += (v - mean) * (v - mean) / (kFits - 1);
    EXPECT_NEAR(std::sqrt(variance) / reported[k], 1.0, 0.25) << parameterName(free[k]);
  }
  // s = sqrt(RSS / (n - p)) estimates the noise's sigma: its mean over the fits within 3 %.
  EXPECT_NEAR(residual_std_sum_a / kFits, kSigmaA, 0.03 * kSigmaA);
}

TEST(CalibrationUncertainty, AParameterAtItsBoundGetsAReasonNotNaN) {
  // Currents no hover power within the range reaches: hover_power_w ends at its upper bound.
  auto samples = synthetic(truth(false), false);
  for (CalibrationSample& s : samples) s.current_a *= 20.0;
  const CalibrationResult result = calibrate(paperQuadParameters(), samples, {FreeParameter::kHoverPowerW});
  ASSERT_TRUE(result.fitted[0].atBound());
  EXPECT_FALSE(result.uncertainty.hasCovariance());
  EXPECT_NE(result.uncertainty.unavailable.find("hover_power_w ended at the upper end of its range"), std::string::npos)
      << result.uncertainty.unavailable;
  EXPECT_TRUE(std::isfinite(result.uncertainty.residual_std_a));
}

TEST(CalibrationUncertainty, AnExactFitHasZeroSpreadAndFiniteCovariance) {
  const auto samples = synthetic(truth(false), false);
  const CalibrationResult result =
      calibrate(paperQuadParameters(), samples, identifiableParameters(paperQuadParameters(), samples));
  ASSERT_TRUE(result.uncertainty.hasCovariance());
  EXPECT_LT(result.uncertainty.residual_std_a, 1e-5);
  for (double se : result.uncertainty.standard_errors) EXPECT_TRUE(std::isfinite(se));
}
