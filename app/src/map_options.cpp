#include "map_options.hpp"

#include "cli_checks.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

namespace ceilplan::app {

void UnknownSpaceFlags::addTo(CLI::App& command) {
  policy_option_ = command
                       .add_option("--unknown", policy_,
                                   "Unknown space: occupied (an obstacle), free (free air), or fill (pockets up to "
                                   "--unknown-fill-max-m inside known free space are free air, the rest an obstacle)")
                       ->check(CLI::IsMember({"occupied", "free", "fill"}))
                       ->capture_default_str();
  fill_option_ = command
                     .add_option("--unknown-fill-max-m", fill_max_m_,
                                 "With --unknown fill: the largest pocket filled, in metres (the longest edge of its "
                                 "bounding box)")
                     ->check(positiveFinite())
                     ->capture_default_str();
}

bool UnknownSpaceFlags::given() const {
  return (policy_option_ != nullptr && policy_option_->count() > 0) ||
         (fill_option_ != nullptr && fill_option_->count() > 0);
}

environment::UnknownSpace UnknownSpaceFlags::value() const {
  environment::UnknownSpace unknown;
  unknown.policy = environment::unknownPolicyFromName(policy_);
  unknown.fill_max_m = fill_max_m_;
  if (unknown.policy != environment::UnknownPolicy::Fill && fill_option_ != nullptr && fill_option_->count() > 0)
    throw ceilplan::InputError("--unknown-fill-max-m applies only to --unknown fill; add --unknown fill or drop it");
  unknown.validate();
  return unknown;
}

}  // namespace ceilplan::app
