// The one number formatter: formatFixed and appendFixed write exactly what a stream's std::fixed
// (printf's "%.*f") writes, and formatNumber and appendNumber what a stream with a precision
// (printf's "%.*g") writes, so that files written through them did not change when they stopped
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

std::string streamNumber(double value, int significant) {
  std::ostringstream text;
  text << std::setprecision(significant) << value;
  return text.str();
}

// `format(value, precision)` equals `stream(value, precision)` for random numbers from 1e-12 up
// to 10^max_exponent, at every precision from 0 to max_precision.
void expectAsStreamOverRandomNumbers(std::string (*format)(double, int), std::string (*stream)(double, int),
                                     int max_exponent, int max_precision) {
  std::mt19937 random(20261127);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-12, max_exponent), precision(0, max_precision);
  for (int n = 0; n < 20000; ++n) {
    const double value = mantissa(random) * std::pow(10.0, exponent(random));
    const int p = precision(random);
    ASSERT_EQ(format(value, p), stream(value, p)) << std::setprecision(17) << value << " to precision " << p;
  }
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
  expectAsStreamOverRandomNumbers(formatFixed, streamFixed, 14, 9);
}

// appendFixed writes the usual numbers from integer arithmetic: the cases where that could round
// otherwise than printf are ties and near-ties, exact halves in binary, negatives rounding to
// zero and the largest numbers it takes.
TEST(FormatFixed, WritesWhatAStreamWritesAtTiesAndEdges) {
  EXPECT_EQ(formatFixed(-0.0004, 3), "-0.000");
  EXPECT_EQ(formatFixed(0.5, 0), "0");
  EXPECT_EQ(formatFixed(1.5, 0), "2");
  EXPECT_EQ(formatFixed(-2.5, 0), "-2");
  EXPECT_EQ(formatFixed(0.0, 6), "0.000000");
  EXPECT_EQ(formatFixed(999.9999996, 6), "1000.000000");
  std::mt19937 random(20261128);
  std::uniform_int_distribution<long> numerator(-4000000, 4000000);
  std::uniform_int_distribution<int> shift(0, 12), decimals(0, 9), exponent(-10, 12);
  std::uniform_real_distribution<double> unit(0.0, 1.0), nudge(-1e-12, 1e-12);
  for (int n = 0; n < 200000; ++n) {
    const int d = decimals(random);
    double value = 0.0;
    switch (n % 4) {
      case 0:  // exact binary fractions: ties at every decimal count that reaches them
        value = std::ldexp(static_cast<double>(numerator(random)), -shift(random));
        break;
      case 1:  // decimal halves, which a double holds only nearly
        value = (static_cast<double>(numerator(random)) + 0.5) / std::pow(10.0, d);
        break;
      case 2:  // the same, nudged
        value = (static_cast<double>(numerator(random)) + 0.5) / std::pow(10.0, d) * (1.0 + nudge(random));
        break;
      default:  // any magnitude up to where the integer arithmetic stops
        value = (unit(random) - 0.5) * std::pow(10.0, exponent(random));
    }
    ASSERT_EQ(formatFixed(value, d), streamFixed(value, d)) << std::setprecision(17) << value << " with " << d;
  }
}

TEST(FormatFixed, AppendFixedAppendsTheSameText) {
  std::string text = "x=";
  appendFixed(text, -1.23456, 3);
  appendFixed(text, 7.0, 1);
  EXPECT_EQ(text, "x=-1.2357.0");
}

TEST(FormatNumber, WritesWhatAStreamWithThatPrecisionWrites) {
  EXPECT_EQ(formatNumber(5.2), "5.2");
  EXPECT_EQ(formatNumber(0.009655), "0.009655");
  EXPECT_EQ(formatNumber(1e-9), "1e-09");
  EXPECT_EQ(formatNumber(123456789.0), "1.23457e+08");
  EXPECT_EQ(formatNumber(-0.0), "-0");
  EXPECT_EQ(formatNumber(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(formatNumber(std::nan("")), streamNumber(std::nan(""), 6));
  EXPECT_EQ(formatNumber(0.1, 60), streamNumber(0.1, 60));  // past the buffer
  expectAsStreamOverRandomNumbers(formatNumber, streamNumber, 20, 17);
}

TEST(FormatNumber, AppendNumberAppendsTheSameText) {
  std::string text = "x=";
  appendNumber(text, -1.23456, 3);
  text += ',';
  appendNumber(text, 0.1 + 0.2, 12);
  EXPECT_EQ(text, "x=-1.23,0.3");
}

}  // namespace
}  // namespace ceilplan
