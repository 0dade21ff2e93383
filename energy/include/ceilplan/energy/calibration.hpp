#pragma once
/// @file
/// Fitting the model's free constants to measured currents (bounded least squares, NLopt).

#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/energy/energy_parameters.hpp"

#include <string>
#include <vector>

namespace ceilplan::energy {

/// One measurement. A column the data set does not have keeps its default ("not varied").
struct CalibrationSample {
  double ceiling_gap_m = kNoSurface;  ///< rotor plane to ceiling, m; kNoSurface: none
  double coverage = 1.0;              ///< fraction of each rotor disc under the ceiling, 0..1
  double ground_gap_m = kNoSurface;   ///< rotor plane to ground, m; kNoSurface: none
  double speed_m_s = 0.0;             ///< horizontal speed
  double climb_m_s = 0.0;             ///< vertical speed, positive up
  double soc = 0.65;                  ///< state of charge, 0..1
  double current_a = 0.0;             ///< the measured pack current
};

/// An energy-model parameter calibration may fit (parameterName gives its file name).
enum class FreeParameter {
  kHoverPowerW,       ///< free-air hover power, W (hover_power_w)
  kK1,                ///< the ceiling effect's K1 (k1)
  kK2M,               ///< the ceiling effect's K2, m (k2_m)
  kMotorEfficiency,   ///< motor and ESC efficiency (motor_efficiency)
  kDragAreaM2,        ///< fuselage flat-plate drag area, m^2 (drag_area_m2)
  kPackResistanceOhm  ///< pack internal resistance, ohm (pack_resistance_ohm)
};

/// The name used in vehicle files and on the command line: hover_power_w, k1, k2_m,
/// motor_efficiency, drag_area_m2, pack_resistance_ohm.
std::string parameterName(FreeParameter parameter);
/// Throws ceilplan::InputError listing the valid names.
FreeParameter parseFreeParameter(const std::string& name);

/// One fitted parameter: its value, the range it was allowed and where the fit started.
struct FittedParameter {
  FreeParameter parameter;  ///< which parameter
  double value;             ///< the fitted value, in the parameter's unit
  double lower;             ///< the range it was allowed
  double upper;             ///< upper end of the allowed range
  double start;             ///< the value the fit started from

  /// The fit ended at (within 1e-6 of) an end of the allowed range: the data would take it further.
  bool atBound() const { return value <= lower * (1 + 1e-6) || value >= upper * (1 - 1e-6); }
};

/// How well the data pin the fitted parameters down (Gauss-Newton at the optimum, docs/models.md
/// "Calibration uncertainty"): cov = s^2 (J^T J)^-1 with s^2 = RSS / (n - p) and J the residuals'
/// Jacobian in the parameters' own units (central differences, relative step
/// kCovarianceRelativeStep). Empty `parameters` when it could not be computed: `unavailable` says why.
struct FitUncertainty {
  std::vector<FreeParameter> parameters;        ///< in the order of the rows of `covariance`
  std::vector<double> standard_errors;          ///< sqrt of the covariance's diagonal, in each parameter's unit
  std::vector<std::vector<double>> covariance;  ///< p x p, in the parameters' units
  double residual_rms_a = 0.0;                  ///< root-mean-square residual current
  double residual_std_a = 0.0;                  ///< s = sqrt(RSS / (n - p)), the residual current's standard deviation
  int samples = 0;                              ///< n, the samples fitted
  std::string unavailable;  ///< why there is no covariance (a parameter at its bound); empty when there is

  /// True when the covariance is there.
  bool hasCovariance() const { return !parameters.empty(); }
};

/// Relative step of the central differences the covariance's Jacobian is taken with: a
/// parameter's value times this (small enough for the model's curvature, large enough against
/// the residuals' rounding).
constexpr double kCovarianceRelativeStep = 1e-5;

/// What calibrate returns: the fitted parameters and how well they fit the samples.
struct CalibrationResult {
  EnergyParameters parameters;          ///< the start with the fitted values put in
  std::vector<FittedParameter> fitted;  ///< one per parameter fitted
  double rmse_a = 0.0;                  ///< root-mean-square current error over the samples
  double max_abs_error_a = 0.0;         ///< largest current error over the samples
  int evaluations = 0;                  ///< model evaluations the fit took
  FitUncertainty uncertainty;           ///< the fitted parameters' covariance and the residual spread
};

/// A copy of `parameters` with the calibration parameter `parameter` set to `value`.
EnergyParameters withParameter(const EnergyParameters& parameters, FreeParameter parameter, double value);
/// The value of the calibration parameter `parameter` in `parameters`.
double parameterValue(const EnergyParameters& parameters, FreeParameter parameter);

/// The parameters the data can speak to: hover_power_w always; k1 and k2_m when some sample
/// has a ceiling within the taper end; motor_efficiency when climb_m_s varies; drag_area_m2
/// when speed_m_s varies.
std::vector<FreeParameter> identifiableParameters(const EnergyParameters& start,
                                                  const std::vector<CalibrationSample>& samples);

/// Minimises the sum of squared current errors over `free` within fixed ranges (log-scaled;
/// the contact thrust ratio stays within 1.0001..20 and profile power non-negative) with NLopt's
/// bounded L-BFGS. Throws ceilplan::InputError naming the parameter when the data cannot
/// identify it: its column is not varied, or the fitted Jacobian has a (near) flat direction
/// along it. Deterministic: no random start.
CalibrationResult calibrate(const EnergyParameters& start, const std::vector<CalibrationSample>& samples,
                            const std::vector<FreeParameter>& free);

}  // namespace ceilplan::energy
