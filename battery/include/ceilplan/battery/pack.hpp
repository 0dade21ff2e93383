#pragma once

#include "ceilplan/core/error.hpp"

namespace ceilplan::battery {

/// A battery pack as the simulation sees it. Defaults: the founding paper's 4S 5.2 Ah LiPo,
/// charged at 2C = 10.4 A (Kocer et al. 2019, arXiv 1812.11707).
struct Pack {
  /// The capacities a pack may have: from a 10 mAh micro cell to 1000 Ah. Outside them the
  /// simulation's SOC and FEC figures are meaningless (1e-300 Ah gives SOCs of -1e297 %).
  static constexpr double kMinCapacity_ah = 0.01;
  static constexpr double kMaxCapacity_ah = 1000.0;  ///< largest capacity accepted, Ah

  double capacity_ah = 5.2;        ///< nominal capacity C_nom
  int cell_count = 4;              ///< series cells
  double charge_current_a = 10.4;  ///< charger current (2C)
  double soc_min = 0.0;            ///< a run that would go below this is refused
  double soc_max = 1.0;            ///< charging never goes above this
  double state_of_health = 1.0;    ///< usable capacity / nominal (paper eq. 7; 1 in the paper)

  /// Usable capacity: C_nom * SOH.
  double usableCapacityAh() const { return capacity_ah * state_of_health; }

  /// Throws ceilplan::InputError naming the first field that is out of range.
  void validate() const;
};

}  // namespace ceilplan::battery
