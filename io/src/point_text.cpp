#include "ceilplan/io/point_text.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/environment/map_builder.hpp"

#include <algorithm>
#include <sstream>

namespace ceilplan::io {

Eigen::Vector3d parsePoint(const std::string& text) {
  std::istringstream in(text);
  Eigen::Vector3d point;
  char comma1 = 0, comma2 = 0;
  if (!(in >> point.x() >> comma1 >> point.y() >> comma2 >> point.z()) || comma1 != ',' || comma2 != ',' ||
      !(in >> std::ws).eof() || !point.allFinite() || point.cwiseAbs().maxCoeff() > kMaxPointCoordinate_m)
    throw InputError("'" + printableText(text) +
                     "': expected three finite numbers x,y,z in metres, each within +-1e6 m");
  return point;
}

Eigen::AlignedBox3d parseBox(const std::string& text) {
  std::istringstream in(text);
  double values[6];
  bool read = true;
  for (int i = 0; i < 6 && read; ++i) {
    char comma = ',';
    read = (in >> values[i]) && (i == 5 || (in >> comma && comma == ','));
  }
  const Eigen::Vector3d min(values[0], values[1], values[2]), max(values[3], values[4], values[5]);
  if (!read || !(in >> std::ws).eof() || !min.allFinite() || !max.allFinite() ||
      std::max(min.cwiseAbs().maxCoeff(), max.cwiseAbs().maxCoeff()) > kMaxPointCoordinate_m)
    throw InputError("'" + printableText(text) +
                     "': expected six finite numbers xmin,ymin,zmin,xmax,ymax,zmax in metres, each within +-1e6 m");
  const Eigen::AlignedBox3d box(min, max);
  try {
    environment::validateCrop(box);
  } catch (const InputError& e) {
    throw InputError("'" + printableText(text) + "': " + e.what());
  }
  return box;
}

}  // namespace ceilplan::io
