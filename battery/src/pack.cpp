#include "ceilplan/battery/pack.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace ceilplan::battery {

void Pack::validate() const {
  if (!(capacity_ah >= kMinCapacity_ah && capacity_ah <= kMaxCapacity_ah))
    throw ceilplan::InputError("pack capacity must be " + formatNumber(kMinCapacity_ah) + " to " +
                               formatNumber(kMaxCapacity_ah) + " Ah, got " + formatNumber(capacity_ah));
  if (cell_count < 1)
    throw ceilplan::InputError("pack cell count must be at least 1, got " + std::to_string(cell_count));
  if (!(std::isfinite(charge_current_a) && charge_current_a >= 0.0))
    throw ceilplan::InputError("charge current must be >= 0 A, got " + formatNumber(charge_current_a));
  if (!(soc_min >= 0.0 && soc_min < soc_max && soc_max <= 1.0))
    throw ceilplan::InputError("SOC limits must satisfy 0 <= soc_min < soc_max <= 1, got " + formatNumber(soc_min) +
                               " and " + formatNumber(soc_max));
  if (!(state_of_health > 0.0 && state_of_health <= 1.0))
    throw ceilplan::InputError("state of health must be in (0, 1], got " + formatNumber(state_of_health));
}

}  // namespace ceilplan::battery
