#pragma once

#include "ceilplan/core/error.hpp"
/// @file
/// Shaft power of a rotary-wing vehicle against horizontal speed.

namespace ceilplan::energy {

/// Zeng, Xu, Zhang 2019 (IEEE T-WC 18(4); docs/models.md, "Power against speed"):
///   P(V) = P0 (1 + 3V^2/U_tip^2) + Pi (sqrt(1 + V^4/(4 v0^4)) - V^2/(2 v0^2))^(1/2) + c V^3,
/// c = 0.5 d0 rho s A (= 0.5 rho times the flat-plate drag area).
class RotaryWingPower {
 public:
  /// A rotor power curve from its hover profile and induced powers, tip speed, hover induced velocity and parasitic
  /// coefficient.
  RotaryWingPower(double profile_power_w, double induced_power_w, double tip_speed_m_s,
                  double hover_induced_velocity_m_s, double parasitic_coefficient_kg_m);

  /// Zeng's blade-element parametrisation: P0 = (delta/8) rho s A Omega^3 R^3,
  /// Pi = (1+k) W^1.5 / sqrt(2 rho A), v0 = sqrt(W / (2 rho A)), U_tip = Omega R.
  static RotaryWingPower fromBladeParameters(double profile_drag_coefficient, double air_density_kg_m3,
                                             double rotor_solidity, double disc_area_m2,
                                             double blade_angular_velocity_rad_s, double rotor_radius_m,
                                             double induced_power_correction, double weight_n,
                                             double fuselage_drag_ratio);

  /// The vehicle's form: Pi from momentum theory over the total disc area, P0 whatever of the
  /// measured hover shaft power is left. Throws ceilplan::InputError when that is negative
  /// (hover power too low for the mass and rotor size).
  static RotaryWingPower scaledToHover(double hover_shaft_power_w, double weight_n, double total_disc_area_m2,
                                       double induced_power_correction, double tip_speed_m_s, double drag_area_m2,
                                       double air_density_kg_m3);

  /// Blade profile power at `speed_m_s`, W.
  double profilePowerW(double speed_m_s) const noexcept {
    return profile_power_w_ * (1.0 + 3.0 * speed_m_s * speed_m_s * inverse_tip_speed_squared_);
  }
  /// Induced power relative to hover's: 1 at rest, falling with speed.
  double inducedSpeedFactor(double speed_m_s) const noexcept;
  /// Induced power at `speed_m_s`, W.
  double inducedPowerW(double speed_m_s) const noexcept { return induced_power_w_ * inducedSpeedFactor(speed_m_s); }
  /// Parasitic power at `speed_m_s`, W.
  double parasiticPowerW(double speed_m_s) const noexcept {
    return parasitic_coefficient_kg_m_ * speed_m_s * speed_m_s * speed_m_s;
  }
  /// Total shaft power P(V) at `speed_m_s`, W.
  double powerW(double speed_m_s) const noexcept {
    return profilePowerW(speed_m_s) + inducedPowerW(speed_m_s) + parasiticPowerW(speed_m_s);
  }

  /// Profile power P0 at hover, W.
  double hoverProfilePowerW() const noexcept { return profile_power_w_; }
  /// Induced power Pi at hover, W.
  double hoverInducedPowerW() const noexcept { return induced_power_w_; }

 private:
  double profile_power_w_;
  double induced_power_w_;
  double inverse_tip_speed_squared_;
  double inverse_two_v0_squared_;  ///< 1 / (2 v0^2)
  double parasitic_coefficient_kg_m_;
};

}  // namespace ceilplan::energy
