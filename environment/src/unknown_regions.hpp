#pragma once
// Applies an unknown-space policy to a grid's column runs: which unknown runs become free air.
// Private to the environment module (MapIndex uses it).

#include "ceilplan/environment/column_index.hpp"
#include "ceilplan/environment/map_index.hpp"
#include "ceilplan/environment/unknown_space.hpp"

#include <cstdint>
#include <vector>

namespace ceilplan::environment::detail {

struct ResolvedRuns {
  // What stays non-free (occupied, and unknown the policy keeps), laid out as ColumnIndex's runs.
  std::vector<std::uint32_t> offsets;
  std::vector<ColumnIndex::Run> runs;
  // The unknown runs the policy assumed free, per column (no unbounded runs).
  std::vector<std::uint32_t> assumed_offsets;
  std::vector<ColumnIndex::Run> assumed_runs;
  UnknownSpaceSummary summary;
};

ResolvedRuns resolveUnknownSpace(const ColumnIndex& raw, const UnknownSpace& unknown);

}  // namespace ceilplan::environment::detail
