#include "ceilplan/io/point_text.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/printable_text.hpp"

#include <sstream>

namespace ceilplan::io {

Eigen::Vector3d parsePoint(const std::string& text) {
  std::istringstream in(text);
  Eigen::Vector3d point;
  char comma1 = 0, comma2 = 0;
  if (!(in >> point.x() >> comma1 >> point.y() >> comma2 >> point.z()) || comma1 != ',' || comma2 != ',' ||
      !(in >> std::ws).eof() || !point.allFinite() || point.cwiseAbs().maxCoeff() > kMaxPointCoordinate_m)
    throw InputError("'" + printableText(text) + "': expected three finite numbers x,y,z in metres, each within +-1e6 m");
  return point;
}

}  // namespace ceilplan::io
