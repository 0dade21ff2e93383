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
  double ceiling_gap_m = kNoSurface;
  double coverage = 1.0;
  double ground_gap_m = kNoSurface;
  double speed_m_s = 0.0;
  double climb_m_s = 0.0;
  double soc = 0.65;
  double current_a = 0.0;
};

enum class FreeParameter { kHoverPowerW, kK1, kK2M, kMotorEfficiency, kDragAreaM2, kPackResistanceOhm };

/// The name used in vehicle files and on the command line: hover_power_w, k1, k2_m,
/// motor_efficiency, drag_area_m2, pack_resistance_ohm.
std::string parameterName(FreeParameter parameter);
/// Throws ceilplan::InputError listing the valid names.
FreeParameter parseFreeParameter(const std::string& name);

struct FittedParameter {
  FreeParameter parameter;
  double value;
  double lower;  ///< the range it was allowed
  double upper;
  double start;

  /// The fit ended at (within 1e-6 of) an end of the allowed range: the data would take it further.
  bool atBound() const { return value <= lower * (1 + 1e-6) || value >= upper * (1 - 1e-6); }
};

struct CalibrationResult {
  EnergyParameters parameters;  ///< the start with the fitted values put in
  std::vector<FittedParameter> fitted;
  double rmse_a = 0.0;
  double max_abs_error_a = 0.0;
  int evaluations = 0;
};

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
