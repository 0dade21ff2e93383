#pragma once
/// @file
/// A summary of a map for `ceilplan mapinfo`: what it holds, what the unknown-space policy
/// assumed, and how much of its floor lies under a ceiling.

#include "ceilplan/environment/map_index.hpp"
#include "ceilplan/environment/occupancy_map.hpp"

#include <Eigen/Geometry>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ceilplan::environment {

/// What counts as a ceiling over a column (docs/environment.md, "Looking at a map"): an
/// occupied surface with at least `min_headroom_m` of free space straight below it (room to
/// fly under), in a 4-connected patch of such columns of at least `min_area_m2`. Table tops
/// (too little room below) and lamps, lintels or shelves (too small) are not ceilings.
struct CeilingCriteria {
  double min_headroom_m = 1.0;  ///< free space needed straight below a ceiling
  double min_area_m2 = 4.0;     ///< smallest patch that counts as a ceiling
};

/// What `ceilplan mapinfo` reports of a map.
struct MapStatistics {
  double resolution_m;                  ///< voxel size
  Eigen::AlignedBox3d extent_m;         ///< bounding box of the known voxels (voxel faces)
  std::size_t occupied_leaves;          ///< OctoMap leaves (after pruning), as stored
  std::size_t free_leaves;              ///< OctoMap free leaves, as stored
  double occupied_volume_m3;            ///< occupied volume
  double free_volume_m3;                ///< free volume
  double unknown_volume_m3;             ///< inside the extent
  UnknownSpace unknown;                 ///< the policy the index applied
  UnknownSpaceSummary unknown_summary;  ///< what the policy did with the unknown voxels
  CeilingCriteria ceiling;              ///< what counted as a ceiling
  /// Share of the floor area (columns holding free space) under a ceiling, in [0, 1].
  double ceiling_area_share;
};

/// The statistics of `map` as indexed by `index`, ceilings by `ceiling`.
MapStatistics computeStatistics(const OccupancyMap& map, const MapIndex& index, const CeilingCriteria& ceiling = {});

/// Per column of the index's grid (j * size_x + i): 0 no free space, 1 free space, 2 free space
/// under a ceiling by `ceiling`. What ceiling_area_share counts.
std::vector<std::uint8_t> ceilingColumns(const MapIndex& index, const CeilingCriteria& ceiling = {});

}  // namespace ceilplan::environment
