#include "ceilplan/environment/column_index.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/parallel_for.hpp"

#include <algorithm>
#include <limits>

namespace ceilplan::environment {
namespace {

// Bands of whole rows (y) of columns, so each thread reads the grid in memory order (z
// outermost, then its rows) and owns the columns it writes.
struct RowBands {
  RowBands(int rows, int workers) : rows_(rows), count_(std::min<int>(rows, std::max(1, workers) * 16)) {}
  std::size_t count() const { return static_cast<std::size_t>(count_); }
  int begin(std::size_t band) const { return static_cast<int>(band * rows_ / count_); }
  int end(std::size_t band) const { return static_cast<int>((band + 1) * rows_ / count_); }

 private:
  long rows_;
  long count_;
};

}  // namespace

ColumnIndex::ColumnIndex(const VoxelGrid& grid, int workers)
    : frame_(grid.frame()),
      resolution_m_(frame_.resolution_m()),
      inverse_resolution_(1.0 / frame_.resolution_m()),
      origin_z_(frame_.origin()[2]) {
  // Two passes over the grid in memory order: count the runs of each column, then fill them
  // in place; walking each column bottom-up would miss the cache on every voxel.
  const int size_x = frame_.size()[0], size_z = frame_.size()[2];
  const std::size_t columns = static_cast<std::size_t>(size_x) * frame_.size()[1];
  const RowBands bands(frame_.size()[1], workers);
  std::vector<std::uint64_t> cursor(columns, 2);  // first the run counts, with the two unbounded runs
  const auto sweep = [&](std::size_t band, auto&& onVoxel) {
    const std::size_t c0 = static_cast<std::size_t>(bands.begin(band)) * size_x;
    const std::size_t c1 = static_cast<std::size_t>(bands.end(band)) * size_x;
    std::vector<CellState> previous(c1 - c0, CellState::Free);
    for (int k = 0; k < size_z; ++k)
      for (std::size_t c = c0; c < c1; ++c) {
        const CellState state = grid.atLinear(static_cast<std::size_t>(k) * columns + c);
        if (state != CellState::Free) onVoxel(c, k, state, state != previous[c - c0]);
        previous[c - c0] = state;
      }
  };
  parallelFor(bands.count(), workers, [&](std::size_t band) {
    sweep(band, [&](std::size_t c, int, CellState, bool starts) { cursor[c] += starts; });
  });
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
  for (std::size_t c = 0; c < columns; ++c) runs_[cursor[c]++] = {kBelowEverything, 0, CellState::Unknown};
  parallelFor(bands.count(), workers, [&](std::size_t band) {
    sweep(band, [&](std::size_t c, int k, CellState state, bool starts) {
      if (starts) {
        runs_[cursor[c]++] = {k, k + 1, state};
      } else {
        runs_[cursor[c] - 1].hi = k + 1;
      }
    });
  });
  for (std::size_t c = 0; c < columns; ++c) runs_[cursor[c]++] = {size_z, kAboveEverything, CellState::Unknown};
}

ColumnIndex::ColumnIndex(const GridFrame& frame, std::vector<std::uint32_t> offsets, std::vector<Run> runs)
    : frame_(frame),
      resolution_m_(frame.resolution_m()),
      inverse_resolution_(1.0 / frame.resolution_m()),
      origin_z_(frame.origin()[2]),
      offsets_(std::move(offsets)),
      runs_(std::move(runs)) {}

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

ColumnIndex::Boundaries ColumnIndex::around(int i, int j, double z_m) const {
  if (!inside(i, j)) return {{z_m, CellState::Unknown}, {z_m, CellState::Unknown}};
  const double t = voxelHeight(z_m);
  const Run* run = std::partition_point(beginRuns(i, j), endRuns(i, j), [t](const Run& r) { return r.hi <= t; });
  const Boundary up = run->lo <= t ? Boundary{z_m, run->state} : Boundary{face(run->lo), run->state};
  // below()'s run, the last to start below t: this one when it does, else the one before,
  // which exists because the first run starts below everything.
  const Run* under = run->lo < t ? run : run - 1;
  const Boundary down = under->hi >= t ? Boundary{z_m, under->state} : Boundary{face(under->hi), under->state};
  return {up, down};
}

std::optional<ColumnIndex::FreeSpan> ColumnIndex::freeSpan(int i, int j, double z_m) const {
  if (!inside(i, j)) return std::nullopt;
  const double t = voxelHeight(z_m);
  const Run* run = std::partition_point(beginRuns(i, j), endRuns(i, j), [t](const Run& r) { return r.hi <= t; });
  if (run == beginRuns(i, j)) return std::nullopt;  // below the grid, inside its unbounded run
  const Run* under = run - 1;
  if (!(under->hi < t && t < run->lo)) return std::nullopt;
  // around()'s two answers for a height strictly between the runs.
  return FreeSpan{static_cast<double>(under->hi),
                  static_cast<double>(run->lo),
                  {{face(run->lo), run->state}, {face(under->hi), under->state}}};
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
