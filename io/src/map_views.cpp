#include "ceilplan/io/map_views.hpp"

#include "ceilplan/io/atomic_file.hpp"

#include <Eigen/Geometry>

namespace ceilplan::io {

void writeMapViews(const std::filesystem::path& dir, const environment::Environment& environment,
                   const std::vector<Eigen::Vector3d>& route_m, const Provenance& provenance) {
  Eigen::AlignedBox3d band;
  for (const Eigen::Vector3d& p : route_m) band.extend(p);
  band.min().array() -= 1.0;
  band.max().array() += 1.0;
  const environment::VoxelGrid& grid = environment.grid();
  const environment::GridFrame& frame = grid.frame();
  const auto inBand = [&](int axis, int index) {
    const double c = frame.centreOf(axis, index);
    return c >= band.min()[axis] && c <= band.max()[axis];
  };
  // Top: the height of the first structure above the lowest route point, per column.
  const double reference_z = band.min().z() + 1.0;
  writeTextAtomically(dir / "map_top.csv", [&](std::ostream& out) {
    out << provenance.csvComment() << '\n';
    out << "x_m,y_m,ceiling_m\n";
    for (int j = 0; j < frame.size()[1]; ++j)
      for (int i = 0; i < frame.size()[0]; ++i) {
        if (!inBand(0, i) || !inBand(1, j)) continue;
        const environment::ColumnIndex::Boundary above = environment.columns().above(i, j, reference_z);
        if (above.state == environment::CellState::Occupied)
          out << frame.centreOf(0, i) << ',' << frame.centreOf(1, j) << ',' << above.face_m << '\n';
      }
  });
  writeTextAtomically(dir / "map_side.csv", [&](std::ostream& out) {
    out << provenance.csvComment() << '\n';
    out << "x_m,z_m\n";
    for (int k = 0; k < frame.size()[2]; ++k)
      for (int i = 0; i < frame.size()[0]; ++i)
        for (int j = 0; j < frame.size()[1]; ++j)
          if (inBand(0, i) && inBand(1, j) && inBand(2, k) && grid.at(i, j, k) == environment::CellState::Occupied) {
            out << frame.centreOf(0, i) << ',' << frame.centreOf(2, k) << '\n';
            break;
          }
  });
}

}  // namespace ceilplan::io
