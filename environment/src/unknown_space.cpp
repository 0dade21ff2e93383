#include "ceilplan/environment/unknown_space.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <cmath>

namespace ceilplan::environment {

void UnknownSpace::validate() const {
  if (!(fill_max_m > 0.0 && fill_max_m <= kMaxFill_m))
    throw ceilplan::InputError("unknown space: the fill size must be a number of metres in (0, " +
                               formatNumber(kMaxFill_m) + "], got " + formatNumber(fill_max_m));
}

std::string UnknownSpace::describe() const {
  if (policy != UnknownPolicy::Fill) return unknownPolicyName(policy);
  return "fill (pockets up to " + formatNumber(fill_max_m) + " m)";
}

UnknownPolicy unknownPolicyFromName(const std::string& name) {
  if (name == "occupied") return UnknownPolicy::Occupied;
  if (name == "free") return UnknownPolicy::Free;
  if (name == "fill") return UnknownPolicy::Fill;
  throw ceilplan::InputError("unknown-space policy '" + name + "' is not one of occupied, free, fill");
}

std::string unknownPolicyName(UnknownPolicy policy) {
  switch (policy) {
    case UnknownPolicy::Occupied:
      return "occupied";
    case UnknownPolicy::Free:
      return "free";
    case UnknownPolicy::Fill:
      return "fill";
  }
  return "occupied";
}

}  // namespace ceilplan::environment
