#include "ceilplan/energy/lipo_open_circuit_voltage.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ceilplan::energy {
namespace {

// ArduPilot's simulator (libraries/SITL/SIM_Battery.cpp, soc_table), SOC % -> V per cell,
// descending in SOC, down to its 2 % point (docs/models.md, "Pack electrics").
constexpr double kTable[LipoOpenCircuitVoltage::kPointCount][2] = {
    {100, 4.173},   {96.15, 4.112}, {92.31, 4.085}, {88.46, 4.071}, {84.62, 4.039}, {80.77, 3.987}, {76.92, 3.943},
    {73.08, 3.908}, {69.23, 3.887}, {65.38, 3.854}, {61.54, 3.833}, {57.69, 3.801}, {53.85, 3.783}, {50, 3.742},
    {46.15, 3.715}, {42.31, 3.679}, {38.46, 3.636}, {34.62, 3.588}, {30.77, 3.543}, {26.92, 3.503}, {23.08, 3.462},
    {19.23, 3.379}, {15.38, 3.296}, {11.54, 3.218}, {7.69, 3.165},  {3.85, 3.091},  {2.0, 2.977}};

}  // namespace

LipoOpenCircuitVoltage::LipoOpenCircuitVoltage() {
  for (int i = 0; i < kPointCount; ++i) {
    soc_[i] = kTable[kPointCount - 1 - i][0] / 100.0;
    voltage_v_[i] = kTable[kPointCount - 1 - i][1];
  }
  for (int i = 0; i + 1 < kPointCount; ++i)
    slope_v_per_soc_[i] = (voltage_v_[i + 1] - voltage_v_[i]) / (soc_[i + 1] - soc_[i]);
  slope_v_per_soc_[kPointCount - 1] = 0.0;
}

double LipoOpenCircuitVoltage::cellVoltageV(double soc) const {
  if (!(soc >= 0.0 && soc <= 1.0))
    throw ceilplan::InputError("state of charge " + formatNumber(soc) +
                               " is outside [0, 1]: give it as a fraction, e.g. 0.65");
  return cellVoltageUncheckedV(soc);
}

double LipoOpenCircuitVoltage::cellVoltageUncheckedV(double soc) const noexcept {
  if (soc <= soc_[0]) return voltage_v_[0];
  // First point above `soc`; the segment starts one before it.
  const auto above = std::upper_bound(soc_.begin(), soc_.end(), soc);
  const auto i = static_cast<std::size_t>(std::min<std::ptrdiff_t>(above - soc_.begin(), kPointCount - 1) - 1);
  return voltage_v_[i] + slope_v_per_soc_[i] * (soc - soc_[i]);
}

std::function<double(double soc)> lipoCellVoltageOfSoc() {
  const LipoOpenCircuitVoltage curve;
  return [curve](double soc) { return curve.cellVoltageV(soc); };
}

}  // namespace ceilplan::energy
