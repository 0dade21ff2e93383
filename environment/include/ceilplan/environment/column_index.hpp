#pragma once
/// @file
/// Per (x, y) column of a VoxelGrid, the sorted runs of non-free voxels (occupied or unknown),
/// built once, so "what is the first surface above/below this point" is an array lookup and a
/// binary search: no ray casting.

#include "ceilplan/environment/voxel_grid.hpp"

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace ceilplan::environment {

/// The grid's columns as runs of non-free voxels: what gap and cylinder queries walk instead of single voxels.
class ColumnIndex {
 public:
  /// Runs of non-free voxels in a column, bottom to top, in voxel indices [lo, hi).
  struct Run {
    std::int32_t lo;  ///< lowest voxel index of the run
    std::int32_t hi;  ///< one past its highest voxel index
    CellState state;  ///< occupied or unknown
  };
  /// Each column begins and ends with an unbounded unknown run: everything below and above the grid.
  static constexpr std::int32_t kBelowEverything = std::numeric_limits<std::int32_t>::min() / 2;
  /// the upper end of every column's top unknown run
  static constexpr std::int32_t kAboveEverything = std::numeric_limits<std::int32_t>::max() / 2;

  /// Reads the grid on `workers` threads.
  explicit ColumnIndex(const VoxelGrid& grid, int workers = 1);
  /// Runs already laid out: column c = j * size_x + i holds runs[offsets[c], offsets[c + 1]),
  /// sorted, disjoint, starting and ending with the unbounded unknown runs.
  ColumnIndex(const GridFrame& frame, std::vector<std::uint32_t> offsets, std::vector<Run> runs);

  /// Where the voxels lie.
  const GridFrame& frame() const { return frame_; }

  /// The first non-free voxel met going up (down) from height z_m in column (i, j): the height
  /// of its lower (upper) face and its state. A point inside a non-free voxel meets it at z_m.
  /// Above and below the grid, and in columns outside it, every voxel is unknown.
  struct Boundary {
    double face_m;    ///< height of the face met, m
    CellState state;  ///< state of the voxel met
  };
  /// Going up from z_m (see Boundary).
  Boundary above(int i, int j, double z_m) const;
  /// Going down from z_m (see Boundary).
  Boundary below(int i, int j, double z_m) const;
  /// Both, from one search of the column: the same as above() and below().
  struct Boundaries {
    Boundary above;  ///< as above()
    Boundary below;  ///< as below()
  };
  /// The boundaries above and below z_m in column (i, j).
  Boundaries around(int i, int j, double z_m) const;

  /// The free stretch of a column between two runs: around() gives the same boundaries at every
  /// height strictly inside it, so heights near each other (a motion's samples) need one search.
  struct FreeSpan {
    double lo;          ///< its lower end, in voxelHeight() units: the upper end of the run below
    double hi;          ///< its upper end, likewise: the lower end of the run above
    Boundaries around;  ///< around() at any height z_m with lo < voxelHeight(z_m) < hi
  };
  /// The free span of column (i, j) holding height z_m, if z_m lies strictly inside one: none
  /// inside a run, on its face, or outside the grid.
  std::optional<FreeSpan> freeSpan(int i, int j, double z_m) const;
  /// Height z_m in the units of a FreeSpan's ends.
  double voxelHeight(double z_m) const { return z_m * inverse_resolution_ - origin_z_; }

  /// The state of the lowest voxel of column (i, j) that overlaps the open height interval
  /// (bottom_m, top_m) (touching faces do not count) and blocks: occupied, or unknown when
  /// `unknown_blocks`. None if no such voxel. The cylinder test's inner loop: a few runs per
  /// column instead of one strided grid read per voxel.
  std::optional<CellState> firstBlocking(int i, int j, double bottom_m, double top_m, bool unknown_blocks) const;

  /// First run of column (i, j).
  const Run* beginRuns(int i, int j) const { return runs_.data() + offsets_[column(i, j)]; }
  /// One past the last run of column (i, j).
  const Run* endRuns(int i, int j) const { return runs_.data() + offsets_[column(i, j) + 1]; }
  /// Runs over all columns.
  std::size_t runCount() const { return runs_.size(); }
  /// Where each column's runs begin in runs() (one more entry than columns).
  const std::vector<std::uint32_t>& offsets() const { return offsets_; }
  /// Every column's runs, column after column.
  const std::vector<Run>& runs() const { return runs_; }
  /// Memory held, bytes.
  std::size_t memoryBytes() const {
    return offsets_.capacity() * sizeof(std::uint32_t) + runs_.capacity() * sizeof(Run);
  }

 private:
  std::size_t column(int i, int j) const { return static_cast<std::size_t>(j) * frame_.size()[0] + i; }
  bool inside(int i, int j) const { return i >= 0 && j >= 0 && i < frame_.size()[0] && j < frame_.size()[1]; }
  double face(std::int32_t index) const { return (origin_z_ + static_cast<double>(index)) * resolution_m_; }

  GridFrame frame_;
  double resolution_m_;
  double inverse_resolution_;
  int origin_z_;
  std::vector<std::uint32_t> offsets_;  ///< column c's runs are runs_[offsets_[c], offsets_[c + 1])
  std::vector<Run> runs_;
};

}  // namespace ceilplan::environment
