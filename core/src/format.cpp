#include "ceilplan/core/format.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iomanip>
#include <sstream>

namespace ceilplan {

namespace {

// std::to_chars with a precision writes what printf's "%.*f" (fixed) or "%.*g" (general) writes
// in the C locale, which is what a stream with that precision wrote, without the stream's
// allocations and locale.
void appendToChars(std::string& text, double value, std::chars_format format, int precision) {
  std::array<char, 64> buffer{};
  const std::to_chars_result written =
      std::to_chars(buffer.data(), buffer.data() + buffer.size(), value, format, precision);
  if (written.ec == std::errc()) {
    text.append(buffer.data(), written.ptr);
    return;
  }
  std::ostringstream stream;  // more digits than the buffer holds
  if (format == std::chars_format::fixed) stream << std::fixed;
  stream << std::setprecision(precision) << value;
  text += stream.str();
}

// printf's "%.*f" for the usual case, from integer arithmetic: `value` times 10^decimals is
// rounded to the nearest integer, whose digits are written with the point before the last
// `decimals`. printf rounds the exact product; the double product is within 1.2e-4 of it below
// 1e12, so it rounds the same way unless it lies within 1e-3 of a half, where (as for a
// non-finite value, a large one or many decimals) this declines and returns false.
bool appendFixedFast(std::string& text, double value, int decimals) {
  constexpr double kPowers[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
  if (decimals < 0 || decimals > 9 || !std::isfinite(value)) return false;
  const double scaled = std::abs(value) * kPowers[decimals];
  if (!(scaled < 1e12)) return false;
  const double whole = std::floor(scaled), fraction = scaled - whole;
  if (std::abs(fraction - 0.5) < 1e-3) return false;
  const auto digits = static_cast<std::uint64_t>(whole) + (fraction > 0.5 ? 1 : 0);
  const auto unit = static_cast<std::uint64_t>(kPowers[decimals]);
  std::array<char, 24> buffer{};  // filled from its end: at most 13 digits, a point and a sign
  char* first = buffer.data() + buffer.size();
  // Two digits at a time, the fraction's `decimals` digits first, then the whole part's.
  const auto writeDigits = [&first](std::uint64_t number, int at_least) {
    static constexpr char kPairs[] =
        "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
        "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
        "8081828384858687888990919293949596979899";
    int written = 0;
    for (; number >= 100 || written + 2 <= at_least; written += 2, number /= 100) {
      const std::size_t pair = 2 * (number % 100);
      *--first = kPairs[pair + 1];
      *--first = kPairs[pair];
    }
    for (; number > 0 || written < at_least || written == 0; ++written, number /= 10)
      *--first = static_cast<char>('0' + number % 10);
  };
  if (decimals > 0) {
    writeDigits(digits % unit, decimals);
    *--first = '.';
  }
  writeDigits(digits / unit, 1);
  if (std::signbit(value)) *--first = '-';  // as printf: "-0.00" for -0.001 and -0.0
  text.append(first, buffer.data() + buffer.size());
  return true;
}

}  // namespace

void appendNumber(std::string& text, double value, int significant) {
  appendToChars(text, value, std::chars_format::general, significant);
}

std::string formatNumber(double value, int significant) {
  std::string text;
  appendNumber(text, value, significant);
  return text;
}

void appendFixed(std::string& text, double value, int decimals) {
  if (appendFixedFast(text, value, decimals)) return;
  // Past 1e15 a double holds no fraction: hundreds of digits of fixed notation would say nothing.
  if (std::abs(value) >= 1e15) {
    text += formatNumber(value);
    return;
  }
  appendToChars(text, value, std::chars_format::fixed, decimals);
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
