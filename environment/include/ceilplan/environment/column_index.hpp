#pragma once
// Per (x, y) column of a VoxelGrid, the sorted runs of non-free voxels (occupied or unknown),
// built once, so "what is the first surface above/below this point" is an array lookup and a
// binary search: no ray casting.

#include "ceilplan/environment/voxel_grid.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace ceilplan::environment {

class ColumnIndex {
 public:
  explicit ColumnIndex(const VoxelGrid& grid);

  // The first non-free voxel met going up (down) from height z_m in column (i, j): the height
  // of its lower (upper) face and its state. A point inside a non-free voxel meets it at z_m.
  // Above and below the grid, and in columns outside it, every voxel is unknown.
  struct Boundary {
    double face_m;
    CellState state;
  };
  Boundary above(int i, int j, double z_m) const;
  Boundary below(int i, int j, double z_m) const;

  // The state of the lowest voxel of column (i, j) that overlaps the open height interval
  // (bottom_m, top_m) (touching faces do not count) and blocks: occupied, or unknown when
  // `unknown_blocks`. None if no such voxel. The cylinder test's inner loop: a few runs per
  // column instead of one strided grid read per voxel.
  std::optional<CellState> firstBlocking(int i, int j, double bottom_m, double top_m, bool unknown_blocks) const;

  // Runs of non-free voxels in column (i, j), bottom to top, in voxel indices [lo, hi).
  struct Run {
    std::int32_t lo;
    std::int32_t hi;
    CellState state;
  };
  const Run* beginRuns(int i, int j) const { return runs_.data() + offsets_[column(i, j)]; }
  const Run* endRuns(int i, int j) const { return runs_.data() + offsets_[column(i, j) + 1]; }
  std::size_t runCount() const { return runs_.size(); }

 private:
  std::size_t column(int i, int j) const { return static_cast<std::size_t>(j) * size_x_ + i; }
  bool inside(int i, int j) const { return i >= 0 && j >= 0 && i < size_x_ && j < size_y_; }
  double face(std::int32_t index) const { return (origin_z_ + static_cast<double>(index)) * resolution_m_; }

  double resolution_m_;
  double inverse_resolution_;
  int origin_z_;
  int size_x_;
  int size_y_;
  std::vector<std::uint32_t> offsets_;  // column c's runs are runs_[offsets_[c], offsets_[c + 1])
  std::vector<Run> runs_;               // each column begins and ends with an unbounded unknown run
};

}  // namespace ceilplan::environment
