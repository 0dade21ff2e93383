#include "ceilplan/environment/map_statistics.hpp"

#include "ceilplan/core/error.hpp"

#include <cmath>
#include <vector>

namespace ceilplan::environment {
namespace {

// Per column: 0 no free space, 1 free space, 2 free space under an occupied surface with the
// headroom asked for.
std::vector<std::uint8_t> classifyColumns(const ColumnIndex& columns, double headroom_voxels) {
  const GridFrame& frame = columns.frame();
  std::vector<std::uint8_t> kind(static_cast<std::size_t>(frame.size()[0]) * frame.size()[1], 0);
  for (int j = 0; j < frame.size()[1]; ++j)
    for (int i = 0; i < frame.size()[0]; ++i) {
      std::uint8_t& column = kind[static_cast<std::size_t>(j) * frame.size()[0] + i];
      // Free space in a column is the gap between consecutive non-free runs.
      for (const ColumnIndex::Run* run = columns.beginRuns(i, j) + 1; run < columns.endRuns(i, j); ++run) {
        const std::int32_t gap = run->lo - (run - 1)->hi;
        if (gap <= 0) continue;
        column = std::max<std::uint8_t>(column, 1);
        if (run->state == CellState::Occupied && gap >= headroom_voxels) column = 2;
      }
    }
  return kind;
}

// Marks as 3 every column of kind 2 in a 4-connected patch of at least `min_columns` of them,
// the others as 1.
void keepLargePatches(std::vector<std::uint8_t>& kind, int size_x, int size_y, double min_columns) {
  std::vector<std::size_t> patch, stack;
  for (std::size_t seed = 0; seed < kind.size(); ++seed) {
    if (kind[seed] != 2) continue;
    patch.clear();
    stack.assign(1, seed);
    kind[seed] = 4;  // visited
    while (!stack.empty()) {
      const std::size_t c = stack.back();
      stack.pop_back();
      patch.push_back(c);
      const int i = static_cast<int>(c % size_x), j = static_cast<int>(c / size_x);
      const auto visit = [&](int ni, int nj) {
        if (ni < 0 || nj < 0 || ni >= size_x || nj >= size_y) return;
        const std::size_t n = static_cast<std::size_t>(nj) * size_x + ni;
        if (kind[n] != 2) return;
        kind[n] = 4;
        stack.push_back(n);
      };
      visit(i - 1, j);
      visit(i + 1, j);
      visit(i, j - 1);
      visit(i, j + 1);
    }
    const std::uint8_t mark = patch.size() >= min_columns ? 3 : 1;
    for (const std::size_t c : patch) kind[c] = mark;
  }
}

}  // namespace

std::vector<std::uint8_t> ceilingColumns(const MapIndex& index, const CeilingCriteria& ceiling) {
  if (!(ceiling.min_headroom_m >= 0.0) || !std::isfinite(ceiling.min_headroom_m) || !(ceiling.min_area_m2 >= 0.0) ||
      !std::isfinite(ceiling.min_area_m2))
    throw ceilplan::InputError("ceiling criteria: headroom and area must be finite and not negative");
  const GridFrame& frame = index.grid().frame();
  const double resolution = frame.resolution_m();
  std::vector<std::uint8_t> kind = classifyColumns(index.columns(), ceiling.min_headroom_m / resolution - 1e-9);
  keepLargePatches(kind, frame.size()[0], frame.size()[1], ceiling.min_area_m2 / (resolution * resolution) - 1e-9);
  for (std::uint8_t& column : kind) column = column == 3 ? 2 : column;
  return kind;
}

MapStatistics computeStatistics(const OccupancyMap& map, const MapIndex& index, const CeilingCriteria& ceiling) {
  const std::vector<std::uint8_t> kind = ceilingColumns(index, ceiling);
  const GridFrame& frame = index.grid().frame();
  MapStatistics stats{};
  stats.resolution_m = frame.resolution_m();
  stats.extent_m = frame.bounds();
  stats.unknown = index.unknownSpace();
  stats.unknown_summary = index.unknownSummary();
  stats.ceiling = ceiling;
  const octomap::OcTree& tree = map.tree();
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
    const double volume = std::pow(it.getSize(), 3);
    if (tree.isNodeOccupied(*it)) {
      ++stats.occupied_leaves;
      stats.occupied_volume_m3 += volume;
    } else {
      ++stats.free_leaves;
      stats.free_volume_m3 += volume;
    }
  }
  stats.unknown_volume_m3 = std::max(0.0, stats.extent_m.volume() - stats.occupied_volume_m3 - stats.free_volume_m3);

  std::size_t floor_columns = 0, ceiling_columns = 0;
  for (const std::uint8_t column : kind) {
    floor_columns += column != 0;
    ceiling_columns += column == 2;
  }
  stats.ceiling_area_share = floor_columns == 0 ? 0.0 : static_cast<double>(ceiling_columns) / floor_columns;
  return stats;
}

}  // namespace ceilplan::environment
