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
  return (policy_option_ != nullptr && policy_option_->count() > 0) || (fill_option_ != nullptr && fill_option_->count() > 0);
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

nlohmann::json unknownSpaceJson(const environment::UnknownSpace& unknown, const environment::UnknownSpaceSummary& summary) {
  const bool fill = unknown.policy == environment::UnknownPolicy::Fill;
  return {{"policy", environment::unknownPolicyName(unknown.policy)},
          {"fill_max_m", fill ? nlohmann::json(unknown.fill_max_m) : nlohmann::json(nullptr)},
          {"unknown_volume_m3", summary.unknown_volume_m3},
          {"assumed_free_volume_m3", summary.assumed_free_volume_m3},
          {"regions", fill ? nlohmann::json(summary.regions) : nlohmann::json(nullptr)},
          {"filled_regions", fill ? nlohmann::json(summary.filled_regions) : nlohmann::json(nullptr)}};
}

std::string unknownSpaceLine(const environment::UnknownSpace& unknown, const environment::UnknownSpaceSummary& summary) {
  std::string line = unknown.describe() + ": " + formatFixed(summary.assumed_free_volume_m3, 2) + " of " +
                     formatFixed(summary.unknown_volume_m3, 2) + " m3 unknown assumed free";
  if (unknown.policy == environment::UnknownPolicy::Fill)
    line += " (" + std::to_string(summary.filled_regions) + " of " + std::to_string(summary.regions) + " regions)";
  return line;
}

}  // namespace ceilplan::app
