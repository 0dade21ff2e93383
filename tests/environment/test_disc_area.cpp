#include "ceilplan/environment/disc_area.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ceilplan::environment {
namespace {

constexpr double kR = 0.127;
const double kDisc = M_PI * kR * kR;

TEST(DiscArea, ARectangleHoldingTheDiscGetsItAll) {
  EXPECT_NEAR(discRectangleOverlap_m2({0.3, -0.2}, kR, {0, -1}, {1, 1}), kDisc, 1e-15);
}

TEST(DiscArea, HalfAndQuarterPlanesThroughTheCentre) {
  EXPECT_NEAR(discRectangleOverlap_m2({0, 0}, kR, {0, -1}, {1, 1}), kDisc / 2, 1e-15);
  EXPECT_NEAR(discRectangleOverlap_m2({0, 0}, kR, {0, 0}, {1, 1}), kDisc / 4, 1e-15);
  EXPECT_NEAR(discRectangleOverlap_m2({0, 0}, kR, {-1, -1}, {0, 0}), kDisc / 4, 1e-15);
}

TEST(DiscArea, DisjointRectanglesGetNothing) {
  EXPECT_EQ(discRectangleOverlap_m2({0, 0}, kR, {0.2, 0}, {1, 1}), 0.0);
  EXPECT_EQ(discRectangleOverlap_m2({0, 0}, kR, {0.1, 0.1}, {1, 1}), 0.0);  // past the rim diagonally
}

TEST(DiscArea, AGridOfCellsPartitionsTheDisc) {
  for (const double resolution : {0.05, 0.08, 0.1, 0.2}) {
    double total = 0.0;
    const Eigen::Vector2d centre(0.0123, -0.0456);
    for (int i = -10; i < 10; ++i)
      for (int j = -10; j < 10; ++j)
        total += discRectangleOverlap_m2(centre, kR, {i * resolution, j * resolution},
                                         {(i + 1) * resolution, (j + 1) * resolution});
    EXPECT_NEAR(total, kDisc, 1e-14) << resolution;
  }
}

TEST(DiscArea, AThinStripMatchesTheCircularSegmentFormula) {
  const double d = 0.05;  // strip x >= d
  const double segment = kR * kR * std::acos(d / kR) - d * std::sqrt(kR * kR - d * d);
  EXPECT_NEAR(discRectangleOverlap_m2({0, 0}, kR, {d, -1}, {1, 1}), segment, 1e-15);
}

}  // namespace
}  // namespace ceilplan::environment
