#pragma once
/// @file
/// A conservative, constant-time "surely valid" test for the vehicle's cylinder near structure,
/// where the distance-field fast path cannot decide. Per column of the grid, as bits over
/// height, the layers holding a blocked voxel (the distance field's) in any column whose centre
/// lies within the cylinder's radius + sqrt(2) voxels: a superset of the columns the cylinder
/// can overlap from a body centre anywhere in the column. A state whose height range meets none
/// of those bits is valid; the others take the exact test. Read from the distance field's
/// horizontal distances, so building them is one pass over the grid whatever the radius.
/// Memory: a bit per voxel of the grid.

#include "ceilplan/environment/distance_field.hpp"
#include "ceilplan/environment/voxel_grid.hpp"

#include <cstdint>
#include <vector>

namespace ceilplan::environment {

/// Per column, a bit per height slice that says whether anything blocking lies within a footprint radius: a fast first
/// test before the exact cylinder test.
class FootprintMasks {
 public:
  /// Builds the masks from `field` for a footprint of `footprint_radius_m`, on `workers` threads.
  FootprintMasks(const DistanceField& field, double footprint_radius_m, int workers = 1);

  /// False only if no blocking voxel overlapping the heights (bottom_m, top_m) lies in the reach
  /// of a cylinder of the footprint radius centred anywhere in column (i, j) (inside the grid).
  bool mayBlock(int i, int j, double bottom_m, double top_m) const;

  /// Memory held, bytes.
  std::size_t memoryBytes() const { return reach_.capacity() * sizeof(std::uint64_t); }

 private:
  GridFrame frame_;
  bool unknown_blocks_;
  int words_;                         ///< 64-bit words per column
  std::vector<std::uint64_t> reach_;  ///< words_ per column, column (i, j) at (j * size_x + i) * words_
};

}  // namespace ceilplan::environment
