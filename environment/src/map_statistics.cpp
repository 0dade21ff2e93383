#include "ceilplan/environment/map_statistics.hpp"

#include <cmath>

namespace ceilplan::environment {

MapStatistics computeStatistics(const OccupancyMap& map, const VoxelGrid& grid, const ColumnIndex& columns,
                                double ceiling_within_m) {
  const GridFrame& frame = grid.frame();
  MapStatistics stats{};
  stats.resolution_m = frame.resolution_m();
  stats.extent_m = frame.bounds();
  stats.ceiling_within_m = ceiling_within_m;
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

  // Free space in a column is the gap between consecutive non-free runs.
  const double within_voxels = ceiling_within_m / frame.resolution_m() + 1e-9;
  std::size_t floor_columns = 0, ceiling_columns = 0;
  for (int j = 0; j < frame.size()[1]; ++j)
    for (int i = 0; i < frame.size()[0]; ++i) {
      bool has_free = false, has_ceiling = false;
      for (const ColumnIndex::Run* run = columns.beginRuns(i, j) + 1; run < columns.endRuns(i, j); ++run) {
        const std::int32_t free_top = run->lo;  // free voxels end below this run
        if (free_top <= (run - 1)->hi) continue;
        has_free = true;
        for (const ColumnIndex::Run* above = run; above < columns.endRuns(i, j) && above->lo - free_top <= within_voxels; ++above)
          if (above->state == CellState::Occupied) {
            has_ceiling = true;
            break;
          }
      }
      floor_columns += has_free;
      ceiling_columns += has_ceiling;
    }
  stats.ceiling_area_share = floor_columns == 0 ? 0.0 : static_cast<double>(ceiling_columns) / floor_columns;
  return stats;
}

MapStatistics computeStatistics(const OccupancyMap& map, double ceiling_within_m) {
  const VoxelGrid grid = VoxelGrid::fromTree(map.tree());
  return computeStatistics(map, grid, ColumnIndex(grid), ceiling_within_m);
}

}  // namespace ceilplan::environment
