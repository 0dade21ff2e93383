#include "map_options.hpp"

#include "cli_checks.hpp"

#include <optional>

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
  std::optional<double> fill_max_m;
  if (fill_option_ != nullptr && fill_option_->count() > 0) fill_max_m = fill_max_m_;
  return environment::parseUnknownSpace(policy_, fill_max_m, {"--unknown", "--unknown-fill-max-m"});
}

}  // namespace ceilplan::app
