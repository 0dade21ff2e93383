#include "ceilplan/energy/rotary_wing_power.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace ceilplan::energy {

RotaryWingPower::RotaryWingPower(double profile_power_w, double induced_power_w, double tip_speed_m_s,
                                 double hover_induced_velocity_m_s, double parasitic_coefficient_kg_m)
    : profile_power_w_(profile_power_w),
      induced_power_w_(induced_power_w),
      inverse_tip_speed_squared_(1.0 / (tip_speed_m_s * tip_speed_m_s)),
      inverse_two_v0_squared_(1.0 / (2.0 * hover_induced_velocity_m_s * hover_induced_velocity_m_s)),
      parasitic_coefficient_kg_m_(parasitic_coefficient_kg_m) {
  if (!(tip_speed_m_s > 0.0) || !(hover_induced_velocity_m_s > 0.0) || !(parasitic_coefficient_kg_m >= 0.0) ||
      !(profile_power_w >= 0.0) || !(induced_power_w > 0.0))
    throw ceilplan::InputError(
        "rotary-wing power needs positive tip speed, induced velocity and induced power, and non-negative "
        "profile power and drag");
}

RotaryWingPower RotaryWingPower::fromBladeParameters(double delta, double rho, double solidity, double area_m2,
                                                     double omega_rad_s, double radius_m, double k, double weight_n,
                                                     double d0) {
  const double profile = delta / 8.0 * rho * solidity * area_m2 * std::pow(omega_rad_s * radius_m, 3);
  const double induced = (1.0 + k) * std::pow(weight_n, 1.5) / std::sqrt(2.0 * rho * area_m2);
  const double v0 = std::sqrt(weight_n / (2.0 * rho * area_m2));
  return RotaryWingPower(profile, induced, omega_rad_s * radius_m, v0, 0.5 * d0 * rho * solidity * area_m2);
}

RotaryWingPower RotaryWingPower::scaledToHover(double hover_shaft_power_w, double weight_n, double area_m2, double k,
                                               double tip_speed_m_s, double drag_area_m2, double rho) {
  const double induced = (1.0 + k) * std::pow(weight_n, 1.5) / std::sqrt(2.0 * rho * area_m2);
  const double profile = hover_shaft_power_w - induced;
  if (profile < 0.0)
    throw ceilplan::InputError("hover shaft power " + formatNumber(hover_shaft_power_w) +
                               " W is below the momentum-theory induced power " + formatNumber(induced) +
                               " W for this mass and rotor disc: raise hover_power_w or motor_efficiency");
  const double v0 = std::sqrt(weight_n / (2.0 * rho * area_m2));
  return RotaryWingPower(profile, induced, tip_speed_m_s, v0, 0.5 * rho * drag_area_m2);
}

double RotaryWingPower::inducedSpeedFactor(double speed_m_s) const noexcept {
  const double x = speed_m_s * speed_m_s * inverse_two_v0_squared_;  // V^2 / (2 v0^2)
  // sqrt(1 + x^2) - x, written without the cancellation at high speed (V^4/(4 v0^4) = x^2).
  return std::sqrt(1.0 / (std::sqrt(1.0 + x * x) + x));
}

}  // namespace ceilplan::energy
