#include "ceilplan/mission/battery_spec.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

namespace ceilplan::mission {

void BatterySpec::validate() const {
  pack.validate();
  if (!(start_soc > 0.0 && start_soc <= 1.0))
    throw InputError("start SOC must be in (0, 1], got " + formatNumber(start_soc));
  if (!(start_soc > pack.soc_min && start_soc <= pack.soc_max))
    throw InputError("start SOC " + formatNumber(start_soc) + " must lie above the pack's floor " +
                     formatNumber(pack.soc_min) + " and at most its ceiling " + formatNumber(pack.soc_max));
  if (!(reserve_soc >= 0.0 && reserve_soc <= 1.0))
    throw InputError("reserve SOC must be in [0, 1], got " + formatNumber(reserve_soc));
  if (!(swap_s >= 0.0 && swap_s <= 86400.0))
    throw InputError("pack swap time must be in [0, 86400] s, got " + formatNumber(swap_s));
  if (reserve_confidence && !(*reserve_confidence > 0.0 && *reserve_confidence < 1.0))
    throw InputError("reserve confidence must be in (0, 1), got " + formatNumber(*reserve_confidence));
  if (reserve_soc >= start_soc)
    throw InputError("reserve SOC " + formatNumber(reserve_soc) + " is not below the start SOC " +
                     formatNumber(start_soc) + ": no sortie could fly; lower the reserve or raise the start SOC");
}

}  // namespace ceilplan::mission
