#include "ceilplan/io/unknown_space_report.hpp"

#include "ceilplan/core/format.hpp"

namespace ceilplan::io {

nlohmann::json unknownSpaceJson(const environment::UnknownSpace& unknown,
                                const environment::UnknownSpaceSummary& summary) {
  const bool fill = unknown.policy == environment::UnknownPolicy::Fill;
  return {{"policy", environment::unknownPolicyName(unknown.policy)},
          {"fill_max_m", fill ? nlohmann::json(unknown.fill_max_m) : nlohmann::json(nullptr)},
          {"unknown_volume_m3", summary.unknown_volume_m3},
          {"assumed_free_volume_m3", summary.assumed_free_volume_m3},
          {"regions", fill ? nlohmann::json(summary.regions) : nlohmann::json(nullptr)},
          {"filled_regions", fill ? nlohmann::json(summary.filled_regions) : nlohmann::json(nullptr)}};
}

nlohmann::json unknownSpaceJson(const environment::Environment& environment) {
  return unknownSpaceJson(environment.index()->unknownSpace(), environment.index()->unknownSummary());
}

std::string unknownSpaceLine(const environment::UnknownSpace& unknown,
                             const environment::UnknownSpaceSummary& summary) {
  std::string line = unknown.describe() + ": " + formatFixed(summary.assumed_free_volume_m3, 2) + " of " +
                     formatFixed(summary.unknown_volume_m3, 2) + " m3 unknown assumed free";
  if (unknown.policy == environment::UnknownPolicy::Fill)
    line += " (" + std::to_string(summary.filled_regions) + " of " + std::to_string(summary.regions) + " regions)";
  return line;
}

std::string unknownSpaceLine(const environment::Environment& environment) {
  return unknownSpaceLine(environment.index()->unknownSpace(), environment.index()->unknownSummary());
}

nlohmann::json assumedFreeJson(const environment::AssumedFreeStretches& stretches) {
  nlohmann::json intervals = nlohmann::json::array();
  for (const environment::PathInterval& interval : stretches.intervals)
    intervals.push_back({{"from_m", interval.from_m},
                         {"to_m", interval.to_m},
                         {"from", {interval.from_point_m.x(), interval.from_point_m.y(), interval.from_point_m.z()}},
                         {"to", {interval.to_point_m.x(), interval.to_point_m.y(), interval.to_point_m.z()}}});
  return {{"assumed_free_m", stretches.length_m}, {"assumed_free_intervals", intervals}};
}

}  // namespace ceilplan::io
