#include "ceilplan/core/format.hpp"

#include <cmath>
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
  // Past 1e15 a double holds no fraction: hundreds of digits of fixed notation would say nothing.
  if (std::abs(value) >= 1e15) return formatNumber(value);
  std::ostringstream text;
  text << std::fixed << std::setprecision(decimals) << value;
  return text.str();
}

std::string formatPoint(const Eigen::Vector3d& point, int decimals) {
  return "(" + formatFixed(point.x(), decimals) + ", " + formatFixed(point.y(), decimals) + ", " +
         formatFixed(point.z(), decimals) + ")";
}

}  // namespace ceilplan
