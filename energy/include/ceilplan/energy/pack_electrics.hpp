#pragma once
/// @file
/// From electrical propulsion power to pack current: a Rint pack with a constant avionics load.

#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/energy_parameters.hpp"
#include "ceilplan/energy/lipo_open_circuit_voltage.hpp"

namespace ceilplan::energy {

/// The pack's current and terminal voltage at one propulsion power.
struct PackOperatingPoint {
  double current_a;           ///< total pack current: propulsion + avionics
  double terminal_voltage_v;  ///< n OCV(SOC) - I R
};

/// Rint (docs/models.md, "Pack electrics"): V = n OCV(SOC) - I R, with I = I_prop + I_avionics and
/// the propulsion drawing P = V I_prop. Solving the quadratic gives
///   I_prop = 2 P / (a + sqrt(a^2 - 4 R P)),  a = n OCV - R I_avionics,
/// which stays exact as R -> 0.
class PackElectrics {
 public:
  explicit PackElectrics(const PackParameters& parameters);  ///< throws ceilplan::InputError

  /// Pack open-circuit voltage at `soc` (n cells x OCV), V.
  double openCircuitVoltageV(double soc) const noexcept { return cell_count_ * ocv_.cellVoltageUncheckedV(soc); }

  /// `soc` must be in [0, 1] (unchecked). Throws ceilplan::Error when the pack cannot deliver
  /// `propulsion_power_w` at all (beyond its maximum power point).
  PackOperatingPoint operatingPoint(double propulsion_power_w, double soc) const;

  /// Inverse: the propulsion power that makes the pack deliver `current_a` in total.
  double propulsionPowerForCurrentW(double current_a, double soc) const noexcept;

  /// The cell voltage curve.
  const LipoOpenCircuitVoltage& openCircuitVoltage() const noexcept { return ocv_; }
  /// The constant avionics current, A.
  double avionicsCurrentA() const noexcept { return avionics_current_a_; }

 private:
  LipoOpenCircuitVoltage ocv_;
  double cell_count_;
  double resistance_ohm_;
  double avionics_current_a_;
};

}  // namespace ceilplan::energy
