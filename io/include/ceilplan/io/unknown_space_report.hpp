#pragma once
/// @file
/// What every output says about the unknown-space policy (docs/environment.md, "Unknown space"):
/// the policy, what it assumed free in the map, and how far a route relies on it.

#include "ceilplan/environment/environment.hpp"
#include "ceilplan/environment/map_index.hpp"
#include "ceilplan/environment/unknown_space.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace ceilplan::io {

/// {"policy", "fill_max_m" (null unless fill), "unknown_volume_m3", "assumed_free_volume_m3",
/// "regions", "filled_regions" (null unless fill)}.
nlohmann::json unknownSpaceJson(const environment::UnknownSpace& unknown,
                                const environment::UnknownSpaceSummary& summary);
/// The same for an environment's index.
nlohmann::json unknownSpaceJson(const environment::Environment& environment);
/// One line for text outputs, e.g. "fill (pockets up to 1 m): 0.42 of 12.3 m3 unknown assumed free (7 of 19 regions)".
std::string unknownSpaceLine(const environment::UnknownSpace& unknown, const environment::UnknownSpaceSummary& summary);
/// The same for an environment's index.
std::string unknownSpaceLine(const environment::Environment& environment);
/// Where a route relies on the policy: {"assumed_free_m", "assumed_free_intervals": [{from_m, to_m, from, to}]}.
nlohmann::json assumedFreeJson(const environment::AssumedFreeStretches& stretches);

}  // namespace ceilplan::io
