#include "ceilplan/io/map_slice_file.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/environment/map_statistics.hpp"
#include "ceilplan/io/atomic_file.hpp"

#include <cstdint>
#include <vector>

namespace ceilplan::io {
namespace {

const char* stateName(environment::CellState state, bool assumed_free) {
  if (assumed_free) return "assumed_free";
  switch (state) {
    case environment::CellState::Occupied:
      return "occupied";
    case environment::CellState::Free:
      return "free";
    case environment::CellState::Unknown:
      return "unknown";
  }
  return "unknown";
}

}  // namespace

void writeMapSliceCsv(const std::filesystem::path& file, const environment::MapIndex& index, double z_m,
                      const environment::Environment* environment, const std::string& height_name,
                      const Provenance& provenance) {
  const environment::GridFrame& frame = index.grid().frame();
  const int k = frame.indexOf(2, z_m);
  if (k < 0 || k >= frame.size()[2])
    throw InputError(height_name + " " + formatNumber(z_m) + " lies outside the map, whose heights span " +
                     formatNumber(frame.faceOf(2, 0)) + " to " + formatNumber(frame.faceOf(2, frame.size()[2])) + " m");
  const std::vector<std::uint8_t> ceiling = environment::ceilingColumns(index);
  writeTextAtomically(file, [&](std::ostream& out) {
    out << provenance.csvComment() << '\n'
        << "x_m,y_m,state,under_ceiling" << (environment ? ",valid,assumes_free" : "") << '\n';
    for (int j = 0; j < frame.size()[1]; ++j)
      for (int i = 0; i < frame.size()[0]; ++i) {
        const Eigen::Vector3d centre(frame.centreOf(0, i), frame.centreOf(1, j), z_m);
        out << formatNumber(centre.x()) << ',' << formatNumber(centre.y()) << ','
            << stateName(index.grid().at(i, j, k), index.isAssumedFree(centre)) << ','
            << int(ceiling[static_cast<std::size_t>(j) * frame.size()[0] + i] == 2);
        if (environment)
          out << ',' << int(environment->isStateValid(centre)) << ',' << int(environment->assumesFree(centre));
        out << '\n';
      }
  });
}

}  // namespace ceilplan::io
