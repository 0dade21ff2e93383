#include "ceilplan/energy/ceiling_effect.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace ceilplan::energy {

CeilingEffect::CeilingEffect(const CeilingEffectParameters& p, double rotor_radius_m) {
  if (!(p.k1 > 0.0) || !std::isfinite(p.k1))
    throw ceilplan::InputError("ceiling k1 must be positive and finite (got " + formatNumber(p.k1) + ")");
  if (!(p.k2_m > 0.0) || !std::isfinite(p.k2_m))
    throw ceilplan::InputError("ceiling k2_m must be positive and finite (got " + formatNumber(p.k2_m) +
                               "): it keeps the thrust ratio finite at contact");
  if (!(p.taper_start_radii > 0.0 && p.taper_end_radii > p.taper_start_radii && std::isfinite(p.taper_end_radii)))
    throw ceilplan::InputError("ceiling taper must satisfy 0 < taper_start_radii < taper_end_radii");
  strength_m2_ = rotor_radius_m * rotor_radius_m / p.k1;
  k2_m_ = p.k2_m;
  if (strength_m2_ / (k2_m_ * k2_m_) >= 1.0)
    throw ceilplan::InputError("ceiling constants k1 = " + formatNumber(p.k1) + ", k2_m = " + formatNumber(p.k2_m) +
                               " make the thrust ratio infinite at contact: need R^2 / (k1 k2^2) < 1");
  taper_start_m_ = p.taper_start_radii * rotor_radius_m;
  taper_end_m_ = p.taper_end_radii * rotor_radius_m;
  inverse_taper_width_ = 1.0 / (taper_end_m_ - taper_start_m_);
}

double CeilingEffect::thrustRatio(double gap_m) const noexcept {
  if (gap_m >= taper_end_m_) return 1.0;
  const double shifted = gap_m + k2_m_;
  const double excess = 1.0 / (1.0 - strength_m2_ / (shifted * shifted)) - 1.0;
  if (gap_m <= taper_start_m_) return 1.0 + excess;
  const double t = (gap_m - taper_start_m_) * inverse_taper_width_;
  const double smootherstep = t * t * t * (t * (6.0 * t - 15.0) + 10.0);
  return 1.0 + excess * (1.0 - smootherstep);
}

}  // namespace ceilplan::energy
