#pragma once
// A summary of a map for `ceilplan mapinfo`: what it holds and how much of it has a ceiling
// close enough to matter.

#include "ceilplan/environment/column_index.hpp"
#include "ceilplan/environment/occupancy_map.hpp"
#include "ceilplan/environment/voxel_grid.hpp"

#include <Eigen/Geometry>

#include <cstddef>

namespace ceilplan::environment {

struct MapStatistics {
  double resolution_m;
  Eigen::AlignedBox3d extent_m;  // bounding box of the known voxels (voxel faces)
  std::size_t occupied_leaves;   // OctoMap leaves (after pruning), as stored
  std::size_t free_leaves;
  double occupied_volume_m3;
  double free_volume_m3;
  double unknown_volume_m3;      // inside the extent
  // Share of the floor area (columns holding free space) where some free voxel has an
  // occupied voxel at most `ceiling_within_m` straight above it.
  double ceiling_within_m;
  double ceiling_area_share;
};

MapStatistics computeStatistics(const OccupancyMap& map, const VoxelGrid& grid, const ColumnIndex& columns,
                                double ceiling_within_m = 2.0);
// Same, indexing the map first.
MapStatistics computeStatistics(const OccupancyMap& map, double ceiling_within_m = 2.0);

}  // namespace ceilplan::environment
