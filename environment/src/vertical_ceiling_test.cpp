#include "ceilplan/environment/vertical_ceiling_test.hpp"

#include "disc_columns.hpp"

#include <cmath>
#include <limits>

namespace ceilplan::environment {

VerticalCeilingTest::VerticalCeilingTest(const Environment& environment, const Eigen::Vector3d& body_m)
    : environment_(environment), line_m_(body_m.head<2>()) {
  // A position outside the map, or not finite, gets ceilingGapAtLeast's own error.
  if (!environment.contains(body_m)) environment.ceilingGapAtLeast(body_m, 0.0);
  const VehicleGeometry& vehicle = environment.vehicle();
  const ColumnIndex& columns = environment.columns();
  const double plane_z = body_m.z() + vehicle.rotor_plane_height_m;
  for (const Eigen::Vector2d& offset : vehicle.rotor_positions_m)
    detail::forEachDiscColumn(
        environment.grid().frame(), line_m_ + offset, vehicle.rotor_radius_m, [&](int i, int j, int) {
          const std::optional<ColumnIndex::FreeSpan> span = columns.freeSpan(i, j, plane_z);
          if (!span) return spans_ = false;
          // The boundary above the span, which ColumnIndex::above gives at every height inside it.
          const ColumnIndex::Boundary& above = span->around.above;
          columns_.push_back(
              {span->lo, span->hi, above.face_m, detail::isSurface(above, environment.options().unknown_is_surface)});
          return true;
        });
}

bool VerticalCeilingTest::gapAtLeast(const Eigen::Vector3d& body_m, double gap_m) const {
  if (!spans_ || body_m.x() != line_m_.x() || body_m.y() != line_m_.y() || !environment_.contains(body_m))
    return environment_.ceilingGapAtLeast(body_m, gap_m);
  const double plane_z = body_m.z() + environment_.vehicle().rotor_plane_height_m;
  const double t = environment_.columns().voxelHeight(plane_z);
  for (const Column& column : columns_)
    if (!(column.lo < t && t < column.hi)) return environment_.ceilingGapAtLeast(body_m, gap_m);
  // Every column's boundary above is the span's: its gap as Environment::columnGap gives it,
  // tested in the same order, the first too close answering.
  for (const Column& column : columns_) {
    const double gap = column.surface ? std::abs(column.face_m - plane_z) : std::numeric_limits<double>::infinity();
    if (!(gap >= gap_m)) return false;
  }
  return true;
}

}  // namespace ceilplan::environment
