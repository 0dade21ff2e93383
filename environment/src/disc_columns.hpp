#pragma once
// The columns a rotor disc covers, and what counts as a surface in them, for every query that
// weighs or tests them (environment.cpp) and for the vertical ceiling test, which must visit the
// same columns and see the same surfaces.

#include "ceilplan/environment/column_index.hpp"
#include "ceilplan/environment/voxel_grid.hpp"

#include <Eigen/Core>

#include <algorithm>

namespace ceilplan::environment::detail {

// Calls `visit(i, j, n)` for every column the disc of `radius_m` around `centre_m` overlaps with
// positive area, n counting them, until one returns false; returns whether none did.
template <class Visit>
bool forEachDiscColumn(const GridFrame& frame, const Eigen::Vector2d& centre_m, double radius_m, Visit&& visit) {
  const int i_begin = frame.indexOf(0, centre_m.x() - radius_m), i_end = frame.indexOf(0, centre_m.x() + radius_m);
  const int j_begin = frame.indexOf(1, centre_m.y() - radius_m), j_end = frame.indexOf(1, centre_m.y() + radius_m);
  int n = 0;
  for (int j = j_begin; j <= j_end; ++j) {
    const double dy = std::max({frame.faceOf(1, j) - centre_m.y(), 0.0, centre_m.y() - frame.faceOf(1, j + 1)});
    for (int i = i_begin; i <= i_end; ++i) {
      const double dx = std::max({frame.faceOf(0, i) - centre_m.x(), 0.0, centre_m.x() - frame.faceOf(0, i + 1)});
      if (dx * dx + dy * dy < radius_m * radius_m && !visit(i, j, n++)) return false;
    }
  }
  return true;
}

// Whether a column's boundary is a surface the gaps measure to: occupied, or unknown where the
// policy takes unknown space as a surface.
inline bool isSurface(const ColumnIndex::Boundary& boundary, bool unknown_is_surface) {
  return boundary.state == CellState::Occupied || (boundary.state == CellState::Unknown && unknown_is_surface);
}

}  // namespace ceilplan::environment::detail
