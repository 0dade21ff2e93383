#pragma once
/// @file
/// Thrust ratio of the vehicle above the ground.

#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/energy_parameters.hpp"

namespace ceilplan::energy {

/// docs/models.md, "Ground effect". Cheeseman-Bennett (1955): 1 / (1 - (R/4z)^2). Multirotor
/// (Sanchez-Cuevas et al. 2017): 1 / [1 - (R/4z)^2 - R^2 z/(d^2+4z^2)^1.5
///   - (R^2/2) z/(2d^2+4z^2)^1.5 - 2 R^2 K_b z/(b^2+4z^2)^1.5], d adjacent and b opposite
/// rotor spacing. Both are singular close to the ground, so z is clamped to >= 0.5 R.
class GroundEffect {
 public:
  /// Throws ceilplan::InputError when the chosen form is singular or not defined for this
  /// geometry (the multirotor form needs at least two rotors).
  GroundEffect(const GroundEffectParameters& parameters, const AirframeParameters& vehicle);

  /// Thrust ratio at `gap_m` >= 0 between rotor plane and ground; +infinity gives 1.
  double thrustRatio(double gap_m) const noexcept;

 private:
  double denominator(double gap_m) const noexcept;

  GroundEffectModel model_;
  double min_gap_m_;
  double radius_squared_m2_;
  double adjacent_squared_m2_;
  double opposite_squared_m2_;
  double body_lift_factor_;
};

}  // namespace ceilplan::energy
