#pragma once
/// @file
/// The one battery type of a mission: the pack, the state of charge each sortie takes off at,
/// and the reserve it must land with.

#include "ceilplan/battery/pack.hpp"

#include <optional>
#include <string>

namespace ceilplan::mission {

/// What happens between two sorties: the pack is charged back to the start SOC at its charge
/// current, or swapped for a charged one (and charged off the aircraft, wearing the same).
enum class Turnaround {
  Recharge,  ///< charged back on the aircraft at its charge current
  Swap       ///< swapped for a charged pack (swap_s)
};

/// The battery a mission flies (a battery file, docs/planner.md "Battery file"): the pack, its SOC limits and what
/// happens between sorties.
struct BatterySpec {
  battery::Pack pack;                                 ///< capacity (usable = nominal x SOH), charge current, SOC limits
  double start_soc = 0.95;                            ///< every sortie takes off at this SOC (the paper's missions)
  double reserve_soc = 0.25;                          ///< and lands with at least this much
  Turnaround between_sorties = Turnaround::Recharge;  ///< recharge or swap between sorties
  double swap_s = 120.0;                              ///< landing to take-off with a swapped pack
  /// With it, every sortie must land above reserve_soc with this probability, in (0, 1), under
  /// the calibrated vehicle's uncertainty (mission key battery.reserve_confidence, docs/tours.md).
  std::optional<double> reserve_confidence;
  std::string description =
      "built-in: the founding paper's 4S 5.2 Ah pack at 95 %";  ///< for reports: where it came from

  /// Throws ceilplan::InputError for a bad pack, an SOC outside [0, 1], a start SOC at or below
  /// the pack's floor, a reserve at or above the start SOC, or a reserve confidence outside (0, 1).
  void validate() const;
};

}  // namespace ceilplan::mission
