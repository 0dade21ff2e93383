#pragma once
/// @file
/// Environment::ceilingGapAtLeast for body positions on one vertical line, the columns under the
/// rotor discs and their free spans found once: the same answers, for a search that asks it at
/// many heights (the viewpoint search's bisection upwards to the highest admissible point).

#include "ceilplan/environment/environment.hpp"

#include <Eigen/Core>

#include <vector>

namespace ceilplan::environment {

/// ceilingGapAtLeast on the vertical line through one body position.
class VerticalCeilingTest {
 public:
  /// The line through `body_m`, a position inside the map (else ceilplan::InputError, as
  /// ceilingGapAtLeast).
  VerticalCeilingTest(const Environment& environment, const Eigen::Vector3d& body_m);

  /// environment.ceilingGapAtLeast(body_m, gap_m), to the bit. A position off the line, or a
  /// height outside a column's free span at the line's first height, is asked of the
  /// environment itself.
  bool gapAtLeast(const Eigen::Vector3d& body_m, double gap_m) const;

 private:
  struct Column {
    double lo, hi;  ///< the free span holding the first height (ColumnIndex::voxelHeight units)
    double face_m;  ///< the boundary above it
    bool surface;   ///< whether that boundary counts as a surface (occupied, or unknown by policy)
  };
  const Environment& environment_;
  Eigen::Vector2d line_m_;
  std::vector<Column> columns_;  ///< every rotor's disc columns, in ceilingGapAtLeast's order
  bool spans_ = true;            ///< every column had a free span at the first height
};

}  // namespace ceilplan::environment
