// A point as command lines give one (io/point_text.hpp): "x,y,z" in metres, or a message that
// quotes the text.

#include "ceilplan/io/point_text.hpp"

#include "input_error.hpp"

#include <gtest/gtest.h>

namespace ceilplan::io {
namespace {

std::string errorOf(const std::string& text) {
  return testing::inputErrorOf([&] { parsePoint(text); });
}

TEST(PointText, ReadsThreeCommaSeparatedNumbers) {
  EXPECT_EQ(parsePoint("1.5,-2,3e-1"), Eigen::Vector3d(1.5, -2.0, 0.3));
  EXPECT_EQ(parsePoint(" 0, 0 ,7 "), Eigen::Vector3d(0.0, 0.0, 7.0));
  EXPECT_EQ(parsePoint("1e6,-1e6,0"), Eigen::Vector3d(1e6, -1e6, 0.0));
}

TEST(PointText, RefusesAnythingElseQuotingItPrintable) {
  const std::string expected = "': expected three finite numbers x,y,z in metres, each within +-1e6 m";
  EXPECT_EQ(errorOf("1,2"), "'1,2" + expected);
  EXPECT_EQ(errorOf("1,2,3,4"), "'1,2,3,4" + expected);
  EXPECT_EQ(errorOf("1;2;3"), "'1;2;3" + expected);
  EXPECT_EQ(errorOf("nan,0,0"), "'nan,0,0" + expected);
  EXPECT_EQ(errorOf("0,inf,0"), "'0,inf,0" + expected);
  EXPECT_EQ(errorOf("0,0,2e6"), "'0,0,2e6" + expected);
  EXPECT_EQ(errorOf(""), "'" + expected);
  EXPECT_EQ(errorOf("1,2,\x1b[3"), "'1,2,\\x1B[3" + expected);
}

}  // namespace
}  // namespace ceilplan::io
