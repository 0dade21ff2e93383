#include "ceilplan/io/map_views.hpp"

#include "ceilplan/core/format.hpp"
#include "ceilplan/io/atomic_file.hpp"

#include <Eigen/Geometry>

#include <array>
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
  // The indices along each axis whose centres lie in the band: one run, as centres increase.
  std::array<std::array<int, 2>, 3> in_band{};
  for (int axis = 0; axis < 3; ++axis) {
    int index = 0;
    while (index < frame.size()[axis] && !inBand(axis, index)) ++index;
    in_band[axis][0] = index;
    while (index < frame.size()[axis] && inBand(axis, index)) ++index;
    in_band[axis][1] = index - 1;
  }
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
  for (int j = in_band[1][0]; j <= in_band[1][1]; ++j)
    for (int i = in_band[0][0]; i <= in_band[0][1]; ++i) {
      const environment::ColumnIndex::Boundary above = environment.columns().above(i, j, reference_z);
      if (above.state == environment::CellState::Occupied)
        appendRow(top, {frame.centreOf(0, i), frame.centreOf(1, j), above.face_m});
    }
  writeTextAtomically(dir / "map_top.csv", [&](std::ostream& out) { out << top; });
  std::string side = provenance.csvComment() + "\nx_m,z_m\n";
  for (int k = in_band[2][0]; k <= in_band[2][1]; ++k) {
    for (int i = in_band[0][0]; i <= in_band[0][1]; ++i) {
      for (int j = in_band[1][0]; j <= in_band[1][1]; ++j)
        if (grid.at(i, j, k) == environment::CellState::Occupied) {
          appendRow(side, {frame.centreOf(0, i), frame.centreOf(2, k)});
          break;
        }
    }
  }
  writeTextAtomically(dir / "map_side.csv", [&](std::ostream& out) { out << side; });
}

}  // namespace ceilplan::io
