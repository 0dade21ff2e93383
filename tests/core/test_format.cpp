// The one number formatter: formatFixed and appendFixed write exactly what a stream's std::fixed
// (printf's "%.*f") writes, so that files written through them did not change when it stopped
// using a stream.

#include "ceilplan/core/format.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <random>
#include <sstream>

namespace ceilplan {
namespace {

std::string streamFixed(double value, int decimals) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(decimals) << value;
  return text.str();
}

TEST(FormatFixed, WritesWhatAStreamsFixedNotationWrites) {
  EXPECT_EQ(formatFixed(43.5, 2), "43.50");
  EXPECT_EQ(formatFixed(-0.0, 3), "-0.000");
  EXPECT_EQ(formatFixed(0.125, 2), "0.12");  // exactly half: to even, as printf
  EXPECT_EQ(formatFixed(2.5, 0), "2");
  EXPECT_EQ(formatFixed(std::numeric_limits<double>::infinity(), 2), "inf");
  EXPECT_EQ(formatFixed(-std::numeric_limits<double>::infinity(), 2), "-inf");
  EXPECT_EQ(formatFixed(std::nan(""), 2), streamFixed(std::nan(""), 2));
  EXPECT_EQ(formatFixed(1e15, 2), "1e+15");  // no fraction to show: as formatNumber
  EXPECT_EQ(formatFixed(123456789.123456789, 40), streamFixed(123456789.123456789, 40));  // past the buffer
  std::mt19937 random(20261127);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-12, 14), decimals(0, 9);
  for (int n = 0; n < 20000; ++n) {
    const double value = mantissa(random) * std::pow(10.0, exponent(random));
    const int d = decimals(random);
    ASSERT_EQ(formatFixed(value, d), streamFixed(value, d)) << value << " with " << d << " decimals";
  }
}

TEST(FormatFixed, AppendFixedAppendsTheSameText) {
  std::string text = "x=";
  appendFixed(text, -1.23456, 3);
  appendFixed(text, 7.0, 1);
  EXPECT_EQ(text, "x=-1.2357.0");
}

}  // namespace
}  // namespace ceilplan
