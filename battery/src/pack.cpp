#include "ceilplan/battery/pack.hpp"

#include "format.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace ceilplan::battery {

void Pack::validate() const {
  if (!(std::isfinite(capacity_ah) && capacity_ah > 0.0))
    throw std::invalid_argument("pack capacity must be a positive number of Ah, got " + detail::number(capacity_ah));
  if (cell_count < 1)
    throw std::invalid_argument("pack cell count must be at least 1, got " + std::to_string(cell_count));
  if (!(std::isfinite(charge_current_a) && charge_current_a >= 0.0))
    throw std::invalid_argument("charge current must be >= 0 A, got " + detail::number(charge_current_a));
  if (!(soc_min >= 0.0 && soc_min < soc_max && soc_max <= 1.0))
    throw std::invalid_argument("SOC limits must satisfy 0 <= soc_min < soc_max <= 1, got " +
                                detail::number(soc_min) + " and " + detail::number(soc_max));
  if (!(state_of_health > 0.0 && state_of_health <= 1.0))
    throw std::invalid_argument("state of health must be in (0, 1], got " + detail::number(state_of_health));
}

}  // namespace ceilplan::battery
