#include "ceilplan/core/format.hpp"

#include <array>
#include <charconv>
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

void appendFixed(std::string& text, double value, int decimals) {
  // Past 1e15 a double holds no fraction: hundreds of digits of fixed notation would say nothing.
  if (std::abs(value) >= 1e15) {
    text += formatNumber(value);
    return;
  }
  // std::to_chars with a precision writes what printf's "%.*f" writes in the C locale, which
  // is what the stream's std::fixed wrote, without the stream's allocations and locale.
  std::array<char, 64> buffer{};
  const std::to_chars_result written =
      std::to_chars(buffer.data(), buffer.data() + buffer.size(), value, std::chars_format::fixed, decimals);
  if (written.ec == std::errc()) {
    text.append(buffer.data(), written.ptr);
    return;
  }
  std::ostringstream stream;  // more decimals than the buffer holds
  stream << std::fixed << std::setprecision(decimals) << value;
  text += stream.str();
}

std::string formatFixed(double value, int decimals) {
  std::string text;
  appendFixed(text, value, decimals);
  return text;
}

std::string formatPoint(const Eigen::Vector3d& point, int decimals) {
  return "(" + formatFixed(point.x(), decimals) + ", " + formatFixed(point.y(), decimals) + ", " +
         formatFixed(point.z(), decimals) + ")";
}

}  // namespace ceilplan
