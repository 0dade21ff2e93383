#include "ceilplan/environment/column_index.hpp"
#include "ceilplan/core/error.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace ceilplan::environment {
namespace {

constexpr std::int32_t kBelowEverything = std::numeric_limits<std::int32_t>::min() / 2;
constexpr std::int32_t kAboveEverything = std::numeric_limits<std::int32_t>::max() / 2;

}  // namespace

ColumnIndex::ColumnIndex(const VoxelGrid& grid)
    : resolution_m_(grid.frame().resolution_m()),
      inverse_resolution_(1.0 / grid.frame().resolution_m()),
      origin_z_(grid.frame().origin()[2]),
      size_x_(grid.frame().size()[0]),
      size_y_(grid.frame().size()[1]) {
  // Two passes over the grid in memory order (z outermost): count the runs of each column,
  // then fill them in place; walking each column bottom-up would miss the cache on every voxel.
  const int size_z = grid.frame().size()[2];
  const std::size_t columns = static_cast<std::size_t>(size_x_) * size_y_;
  std::vector<CellState> previous(columns, CellState::Free);
  std::vector<std::uint64_t> cursor(columns, 2);  // first the run counts, with the two unbounded runs
  for (int k = 0; k < size_z; ++k)
    for (std::size_t c = 0; c < columns; ++c) {
      const CellState state = grid.atLinear(static_cast<std::size_t>(k) * columns + c);
      if (state != CellState::Free && state != previous[c]) ++cursor[c];
      previous[c] = state;
    }
  offsets_.resize(columns + 1);
  std::uint64_t total = 0;
  for (std::size_t c = 0; c < columns; ++c) {
    offsets_[c] = static_cast<std::uint32_t>(total);
    total += cursor[c];
    if (total > std::numeric_limits<std::uint32_t>::max())
      throw ceilplan::InputError("the map has too many voxel runs to index; crop it or coarsen its resolution");
    cursor[c] = offsets_[c];
  }
  offsets_[columns] = static_cast<std::uint32_t>(total);
  runs_.resize(total);
  std::fill(previous.begin(), previous.end(), CellState::Free);
  for (std::size_t c = 0; c < columns; ++c) runs_[cursor[c]++] = {kBelowEverything, 0, CellState::Unknown};
  for (int k = 0; k < size_z; ++k)
    for (std::size_t c = 0; c < columns; ++c) {
      const CellState state = grid.atLinear(static_cast<std::size_t>(k) * columns + c);
      if (state != CellState::Free) {
        if (state == previous[c]) {
          runs_[cursor[c] - 1].hi = k + 1;
        } else {
          runs_[cursor[c]++] = {k, k + 1, state};
        }
      }
      previous[c] = state;
    }
  for (std::size_t c = 0; c < columns; ++c) runs_[cursor[c]++] = {size_z, kAboveEverything, CellState::Unknown};
}

ColumnIndex::Boundary ColumnIndex::above(int i, int j, double z_m) const {
  if (!inside(i, j)) return {z_m, CellState::Unknown};
  const double t = z_m * inverse_resolution_ - origin_z_;  // height in voxel units
  const Run* run = std::partition_point(beginRuns(i, j), endRuns(i, j), [t](const Run& r) { return r.hi <= t; });
  // The last run is unbounded above, so `run` always exists.
  if (run->lo <= t) return {z_m, run->state};
  return {face(run->lo), run->state};
}

ColumnIndex::Boundary ColumnIndex::below(int i, int j, double z_m) const {
  if (!inside(i, j)) return {z_m, CellState::Unknown};
  const double t = z_m * inverse_resolution_ - origin_z_;
  const Run* run = std::partition_point(beginRuns(i, j), endRuns(i, j), [t](const Run& r) { return r.lo < t; }) - 1;
  // The first run is unbounded below, so `run` always exists.
  if (run->hi >= t) return {z_m, run->state};
  return {face(run->hi), run->state};
}

std::optional<CellState> ColumnIndex::firstBlocking(int i, int j, double bottom_m, double top_m,
                                                  bool unknown_blocks) const {
  if (!(bottom_m < top_m)) return std::nullopt;
  if (!inside(i, j)) return unknown_blocks ? std::optional<CellState>(CellState::Unknown) : std::nullopt;
  for (const Run* run = beginRuns(i, j); run != endRuns(i, j); ++run) {
    if (face(run->lo) >= top_m) break;  // this run and every later one lie above
    if (face(run->hi) <= bottom_m) continue;
    if (run->state == CellState::Occupied || unknown_blocks) return run->state;
  }
  return std::nullopt;
}

}  // namespace ceilplan::environment
