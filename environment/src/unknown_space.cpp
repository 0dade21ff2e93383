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

UnknownSpace parseUnknownSpace(const std::string& policy, std::optional<double> fill_max_m,
                               const UnknownSpaceKeys& keys) {
  UnknownSpace unknown;
  try {
    unknown.policy = unknownPolicyFromName(policy);
  } catch (const ceilplan::InputError& e) {
    throw ceilplan::InputError(keys.policy + ": " + e.what());
  }
  if (fill_max_m) {
    if (unknown.policy != UnknownPolicy::Fill)
      throw ceilplan::InputError(keys.fill_max + " applies only to " + keys.policy + " fill; add " + keys.policy +
                                 " fill or drop " + keys.fill_max);
    unknown.fill_max_m = *fill_max_m;
  }
  unknown.validate();
  return unknown;
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
