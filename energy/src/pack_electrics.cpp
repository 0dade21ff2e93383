#include "ceilplan/energy/pack_electrics.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace ceilplan::energy {

PackElectrics::PackElectrics(const PackParameters& p)
    : cell_count_(p.cell_count), resistance_ohm_(p.resistance_ohm), avionics_current_a_(p.avionics_current_a) {
  if (p.cell_count < 1 || p.cell_count > 24)
    throw ceilplan::InputError("pack cell_count must be between 1 and 24 (got " + std::to_string(p.cell_count) + ")");
  if (!(p.resistance_ohm >= 0.0) || !std::isfinite(p.resistance_ohm))
    throw ceilplan::InputError("pack resistance_ohm must be >= 0 and finite");
  if (!(p.avionics_current_a >= 0.0) || !std::isfinite(p.avionics_current_a))
    throw ceilplan::InputError("avionics_current_a must be >= 0 and finite");
}

PackOperatingPoint PackElectrics::operatingPoint(double propulsion_power_w, double soc) const {
  const double open_circuit_v = openCircuitVoltageV(soc);
  const double a = open_circuit_v - resistance_ohm_ * avionics_current_a_;
  const double discriminant = a * a - 4.0 * resistance_ohm_ * propulsion_power_w;
  if (!(discriminant >= 0.0) || !(a > 0.0))
    throw ceilplan::Error("the pack cannot deliver " + formatNumber(propulsion_power_w) + " W at SOC " +
                          formatNumber(soc) + " (beyond its maximum power): lower the demand or check the pack");
  const double propulsion_current_a = 2.0 * propulsion_power_w / (a + std::sqrt(discriminant));
  const double current_a = propulsion_current_a + avionics_current_a_;
  return {current_a, open_circuit_v - resistance_ohm_ * current_a};
}

double PackElectrics::propulsionPowerForCurrentW(double current_a, double soc) const noexcept {
  const double terminal_v = openCircuitVoltageV(soc) - resistance_ohm_ * current_a;
  return terminal_v * (current_a - avionics_current_a_);
}

}  // namespace ceilplan::energy
