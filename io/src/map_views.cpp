#include "ceilplan/io/map_views.hpp"

#include "ceilplan/core/format.hpp"
#include "ceilplan/io/atomic_file.hpp"

#include <Eigen/Geometry>

#include <initializer_list>
#include <string>

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
  // A row of numbers as a stream writes them (six significant digits), into one string.
  const auto appendRow = [](std::string& text, std::initializer_list<double> values) {
    for (const double value : values) {
      appendNumber(text, value);
      text += ',';
    }
    text.back() = '\n';
  };
  std::string top = provenance.csvComment() + "\nx_m,y_m,ceiling_m\n";
  for (int j = 0; j < frame.size()[1]; ++j)
    for (int i = 0; i < frame.size()[0]; ++i) {
      if (!inBand(0, i) || !inBand(1, j)) continue;
      const environment::ColumnIndex::Boundary above = environment.columns().above(i, j, reference_z);
      if (above.state == environment::CellState::Occupied)
        appendRow(top, {frame.centreOf(0, i), frame.centreOf(1, j), above.face_m});
    }
  writeTextAtomically(dir / "map_top.csv", [&](std::ostream& out) { out << top; });
  std::string side = provenance.csvComment() + "\nx_m,z_m\n";
  for (int k = 0; k < frame.size()[2]; ++k) {
    if (!inBand(2, k)) continue;
    for (int i = 0; i < frame.size()[0]; ++i) {
      if (!inBand(0, i)) continue;
      for (int j = 0; j < frame.size()[1]; ++j)
        if (inBand(1, j) && grid.at(i, j, k) == environment::CellState::Occupied) {
          appendRow(side, {frame.centreOf(0, i), frame.centreOf(2, k)});
          break;
        }
    }
  }
  writeTextAtomically(dir / "map_side.csv", [&](std::ostream& out) { out << side; });
}

}  // namespace ceilplan::io
