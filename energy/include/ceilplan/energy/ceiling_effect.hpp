#pragma once
/// @file
/// Thrust ratio of one rotor under a ceiling.

#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/energy_parameters.hpp"

namespace ceilplan::energy {

/// The image-method shape of Sanchez-Cuevas et al. (ICUAS 2017; docs/models.md, "Ceiling effect"),
///   kappa_im(z) = 1 / (1 - (1/K1) (R / (z + K2))^2),  z = rotor plane to ceiling,
/// faded out with a C2 "smootherstep" weight w(z) between taper_start and taper_end (in R):
///   kappa(z) = 1 + w(z) (kappa_im(z) - 1),  w = 1 below the start, 0 from the end on.
/// kappa_im - 1 is positive and decreasing and w is non-increasing, so kappa falls
/// monotonically to exactly 1; K2 > 0 keeps it finite at contact (z = 0). Partial coverage c of
/// the rotor disc scales the excess: 1 + c (kappa - 1) (Reach, J. Aircraft 2023: a ceiling as
/// wide as the propeller acts as an infinite one, a narrow strip hardly at all).
class CeilingEffect {
 public:
  /// Throws ceilplan::InputError when K1 <= 0, K2 <= 0, the taper is empty, or the curve
  /// would be singular at contact (R^2 / (K1 K2^2) >= 1).
  CeilingEffect(const CeilingEffectParameters& parameters, double rotor_radius_m);

  /// Full-coverage thrust ratio at `gap_m` >= 0 (not checked here); +infinity gives 1.
  double thrustRatio(double gap_m) const noexcept;
  /// Thrust ratio at `gap_m` with a `coverage` share (0..1) of the rotor disc under the ceiling.
  double thrustRatio(double gap_m, double coverage) const noexcept {
    return 1.0 + coverage * (thrustRatio(gap_m) - 1.0);
  }

  /// Thrust ratio with the rotor touching the ceiling (gap 0).
  double contactThrustRatio() const noexcept { return thrustRatio(0.0); }
  /// Gap from which the effect is faded out entirely, m.
  double taperEndM() const noexcept { return taper_end_m_; }

 private:
  double strength_m2_;  ///< R^2 / K1
  double k2_m_;
  double taper_start_m_;
  double taper_end_m_;
  double inverse_taper_width_;
};

}  // namespace ceilplan::energy
