#include "ceilplan/energy/ground_effect.hpp"
#include "ceilplan/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ceilplan::energy {

GroundEffect::GroundEffect(const GroundEffectParameters& p, const AirframeParameters& vehicle)
    : model_(p.model),
      min_gap_m_(p.min_gap_radii * vehicle.rotor_radius_m),
      radius_squared_m2_(vehicle.rotor_radius_m * vehicle.rotor_radius_m),
      adjacent_squared_m2_(vehicle.adjacent_rotor_spacing_m * vehicle.adjacent_rotor_spacing_m),
      opposite_squared_m2_(vehicle.opposite_rotor_spacing_m * vehicle.opposite_rotor_spacing_m),
      body_lift_factor_(p.body_lift_factor) {
  if (!(p.min_gap_radii > 0.25) || !std::isfinite(p.min_gap_radii))
    throw ceilplan::InputError("ground min_gap_radii must exceed 0.25, where Cheeseman-Bennett is singular");
  if (model_ != GroundEffectModel::kMultirotor) return;
  if (vehicle.rotor_count < 2 || !(vehicle.adjacent_rotor_spacing_m > 0.0) || !(vehicle.opposite_rotor_spacing_m > 0.0))
    throw ceilplan::InputError(
        "the multirotor ground-effect form needs at least two rotors with positive spacing; use cheeseman-bennett");
  if (!(p.body_lift_factor >= 0.0) || !std::isfinite(p.body_lift_factor))
    throw ceilplan::InputError("ground body_lift_factor must be >= 0");
  // The interaction terms peak at gaps of the order of the rotor spacing: scan up to well past
  // it and refuse a geometry whose denominator comes near zero anywhere.
  const double scan_end_m = 4.0 * std::sqrt(opposite_squared_m2_) + 10.0 * std::sqrt(radius_squared_m2_);
  constexpr int kScanSteps = 400;
  for (int i = 0; i <= kScanSteps; ++i) {
    const double z = min_gap_m_ + (scan_end_m - min_gap_m_) * i / kScanSteps;
    if (denominator(z) < 0.1)
      throw ceilplan::InputError(
          "the multirotor ground-effect form is singular for these rotor spacings (rotors too close "
          "together for their radius); use cheeseman-bennett or check rotor positions");
  }
}

double GroundEffect::denominator(double gap_m) const noexcept {
  const double z = std::max(gap_m, min_gap_m_);
  const double four_z_squared = 4.0 * z * z;
  double d = 1.0 - radius_squared_m2_ / (4.0 * four_z_squared);  // (R/4z)^2 = R^2 / (16 z^2)
  if (model_ == GroundEffectModel::kMultirotor) {
    const auto threeHalvesPower = [](double x) { return x * std::sqrt(x); };  // x^1.5
    d -= radius_squared_m2_ * z / threeHalvesPower(adjacent_squared_m2_ + four_z_squared);
    d -= 0.5 * radius_squared_m2_ * z / threeHalvesPower(2.0 * adjacent_squared_m2_ + four_z_squared);
    d -= 2.0 * radius_squared_m2_ * body_lift_factor_ * z / threeHalvesPower(opposite_squared_m2_ + four_z_squared);
  }
  return d;
}

double GroundEffect::thrustRatio(double gap_m) const noexcept {
  if (std::isinf(gap_m)) return 1.0;
  return 1.0 / denominator(gap_m);
}

}  // namespace ceilplan::energy
