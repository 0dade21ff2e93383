#pragma once
/// @file
/// Turning a thrust ratio kappa = T_near / T_free into the ratio of induced power at equal
/// thrust, and back (docs/models.md, "From thrust ratio to power").

#include "ceilplan/energy/energy_parameters.hpp"

#include <cmath>

namespace ceilplan::energy {

/// Induced power near a surface over free-air induced power, for a thrust ratio kappa under `convention`.
inline double inducedPowerRatio(double thrust_ratio, ThrustToPowerConvention convention) noexcept {
  return convention == ThrustToPowerConvention::kMomentumTheory ? 1.0 / (thrust_ratio * std::sqrt(thrust_ratio))
                                                                : 1.0 / thrust_ratio;
}

/// The inverse: the thrust ratio that gives induced power ratio `power_ratio`.
inline double thrustRatioForInducedPowerRatio(double power_ratio, ThrustToPowerConvention convention) noexcept {
  return convention == ThrustToPowerConvention::kMomentumTheory ? std::pow(power_ratio, -2.0 / 3.0) : 1.0 / power_ratio;
}

}  // namespace ceilplan::energy
