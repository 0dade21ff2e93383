#include "ceilplan/core/format.hpp"

#include <cstdio>
#include <iomanip>
#include <sstream>

namespace ceilplan {

std::string formatNumber(double value, int significant) {
  std::ostringstream text;
  text << std::setprecision(significant) << value;
  return text.str();
}

std::string formatFixed(double value, int decimals) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(decimals) << value;
  return text.str();
}

std::string formatPoint(const Eigen::Vector3d& point, int decimals) {
  return "(" + formatFixed(point.x(), decimals) + ", " + formatFixed(point.y(), decimals) + ", " +
         formatFixed(point.z(), decimals) + ")";
}

}  // namespace ceilplan
