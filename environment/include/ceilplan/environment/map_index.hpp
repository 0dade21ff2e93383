#pragma once
/// @file
/// Everything about a map that depends only on the map and the unknown-space policy, built once
/// and shared, immutable, by every Environment on that map (one per vehicle geometry and
/// margins: ceiling mode, free mode's standoff): the voxel grid, the column index and the
/// distance field. Building it is linear in the voxels of the map's box and runs on `workers`
/// threads; queries are const and safe from many threads (docs/environment.md).

#include "ceilplan/environment/column_index.hpp"
#include "ceilplan/environment/distance_field.hpp"
#include "ceilplan/environment/occupancy_map.hpp"
#include "ceilplan/environment/unknown_space.hpp"
#include "ceilplan/environment/visibility.hpp"
#include "ceilplan/environment/voxel_grid.hpp"

#include <Eigen/Core>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace ceilplan::environment {

/// How a MapIndex is built: the unknown-space policy and its threads.
struct MapIndexOptions {
  UnknownSpace unknown;  ///< occupied by default
  int workers = 2;       ///< threads building the index
};

/// What the unknown-space policy did with the map's unknown voxels (inside the box of its known ones).
struct UnknownSpaceSummary {
  double unknown_volume_m3 = 0.0;       ///< unknown volume inside the box of the known voxels
  double assumed_free_volume_m3 = 0.0;  ///< of that, what the policy counts as free air
  std::size_t regions = 0;              ///< fill: connected unknown regions
  std::size_t filled_regions = 0;       ///< fill: of those, the pockets counted as free air
};

/// A map's voxels, column runs and distance field under one unknown-space policy, built once and shared by every
/// vehicle's Environment.
class MapIndex {
 public:
  /// Indexes `map` under `options.unknown` (validated here, ceilplan::InputError); `progress`
  /// receives fractions in [0, 1]. About 7 bytes per voxel of the box of the map's known voxels.
  MapIndex(const OccupancyMap& map, const MapIndexOptions& options = {},
           const std::function<void(double)>& progress = {});
  /// The same, shared: what Environment takes.
  static std::shared_ptr<const MapIndex> build(const OccupancyMap& map, const MapIndexOptions& options = {},
                                               const std::function<void(double)>& progress = {});

  /// The map's name (its file) for messages.
  const std::string& mapName() const { return map_name_; }
  /// The policy applied.
  const UnknownSpace& unknownSpace() const { return unknown_; }
  /// What the policy did with the unknown voxels.
  const UnknownSpaceSummary& unknownSummary() const { return summary_; }
  /// Whether the unknown space the policy leaves blocks the vehicle: under occupied and fill.
  /// Under free only what lies outside the map's box is still unknown, and it does not block.
  bool unknownBlocks() const { return unknown_.policy != UnknownPolicy::Free; }

  /// The map's own voxel states: unknown stays unknown whatever the policy.
  const VoxelGrid& grid() const { return grid_; }
  /// Runs of what the policy leaves non-free: occupied voxels and the unknown ones it keeps.
  const ColumnIndex& columns() const { return *columns_; }
  /// Distances to what blocks under the policy.
  const DistanceField& distance() const { return *distance_; }
  /// The grid's all-free blocks, for fast lines of sight (visibility.hpp). Built on first use,
  /// from any thread: commands that cast no line of sight never pay for them.
  const FreeBlocks& freeBlocks() const;

  /// Whether `point_m` lies in the box of the map's known voxels.
  bool contains(const Eigen::Vector3d& point_m) const { return grid_.frame().contains(point_m); }
  /// Whether the voxel holding `point_m` is unknown space that the policy assumed free.
  bool isAssumedFree(const Eigen::Vector3d& point_m) const;
  /// Whether column (i, j) holds assumed-free voxels overlapping the open height interval
  /// (bottom_m, top_m); touching faces do not count.
  bool assumedFreeOverlaps(int i, int j, double bottom_m, double top_m) const;

  /// Memory held, bytes (the free blocks once built).
  std::size_t memoryBytes() const;

 private:
  std::string map_name_;
  UnknownSpace unknown_;
  int workers_;  ///< for the free blocks, built on first use
  VoxelGrid grid_;
  std::unique_ptr<const ColumnIndex> columns_;
  std::unique_ptr<const DistanceField> distance_;
  mutable std::once_flag free_blocks_built_;
  mutable std::unique_ptr<const FreeBlocks> free_blocks_;
  mutable std::atomic<bool> free_blocks_ready_{false};  ///< for memoryBytes() while another thread builds them
  /// The assumed-free runs of each column: assumed_runs_[assumed_offsets_[c], assumed_offsets_[c + 1]).
  std::vector<std::uint32_t> assumed_offsets_;
  std::vector<ColumnIndex::Run> assumed_runs_;
  UnknownSpaceSummary summary_;
};

}  // namespace ceilplan::environment
