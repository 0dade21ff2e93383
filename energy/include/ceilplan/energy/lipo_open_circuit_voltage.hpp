#pragma once
/// @file
/// Open-circuit voltage of one LiPo cell against state of charge.

#include "ceilplan/core/error.hpp"

#include <array>
#include <functional>

namespace ceilplan::energy {

/// Per-cell OCV table of ArduPilot's battery simulator (libraries/SITL/SIM_Battery.cpp),
/// linearly interpolated. Public so the battery module's ageing models (which need the cell
/// voltage, e.g. Schmalstieg's V and Vrms) share this curve instead of embedding their own.
/// Below the table's lowest point (2 % SOC, 2.977 V) the voltage is held at that value: the
/// table says nothing deeper and a planner must never rely on charge there anyway.
class LipoOpenCircuitVoltage {
 public:
  static constexpr int kPointCount = 27;  ///< points in the table

  LipoOpenCircuitVoltage();

  /// Cell voltage (V) at `soc` in [0, 1]. Throws ceilplan::InputError outside [0, 1] or NaN.
  double cellVoltageV(double soc) const;

  /// The same without the range check, for hot loops that validated `soc` already.
  double cellVoltageUncheckedV(double soc) const noexcept;

  /// The table itself, ascending in SOC (fractions 0..1) with voltages in V.
  const std::array<double, kPointCount>& socPoints() const noexcept { return soc_; }
  /// The table's cell voltages, V, one per socPoints() entry.
  const std::array<double, kPointCount>& voltagePointsV() const noexcept { return voltage_v_; }

 private:
  std::array<double, kPointCount> soc_{};
  std::array<double, kPointCount> voltage_v_{};
  std::array<double, kPointCount> slope_v_per_soc_{};  ///< slope of the segment starting at each point
};

/// The curve as a function of SOC, checked (cellVoltageV), in the form the battery module's ageing
/// models take it (battery::CellVoltageOfSoc, needed by Schmalstieg's model).
std::function<double(double soc)> lipoCellVoltageOfSoc();

}  // namespace ceilplan::energy
