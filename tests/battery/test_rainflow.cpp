// Rainflow counting per ASTM E1049-85, streaming (docs/ageing.md).
#include "ceilplan/battery/rainflow.hpp"
#include "ceilplan/core/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <stdexcept>
#include <vector>

using ceilplan::battery::countRainflowCycles;
using ceilplan::battery::RainflowCounter;
using ceilplan::battery::RainflowCycle;

namespace {

// Total count per range, the form in which ASTM states its example.
std::map<double, double> countsByRange(const std::vector<RainflowCycle>& cycles) {
  std::map<double, double> counts;
  for (const auto& c : cycles) counts[c.range] += c.count;
  return counts;
}

double totalCount(const std::vector<RainflowCycle>& cycles) {
  double total = 0.0;
  for (const auto& c : cycles) total += c.count;
  return total;
}

bool sameCycles(const std::vector<RainflowCycle>& a, const std::vector<RainflowCycle>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].range != b[i].range || a[i].mean != b[i].mean || a[i].count != b[i].count || a[i].start != b[i].start ||
        a[i].end != b[i].end)
      return false;
  }
  return true;
}

const std::vector<double> kAstmExample{-2, 1, -3, 5, -1, 3, -4, 4, -2};

}  // namespace

TEST(Rainflow, ReproducesTheAstmExample) {
  const auto cycles = countRainflowCycles(kAstmExample);
  const std::map<double, double> expected{{3, 0.5}, {4, 1.5}, {6, 0.5}, {8, 1.0}, {9, 0.5}};
  EXPECT_EQ(countsByRange(cycles), expected);
  EXPECT_DOUBLE_EQ(totalCount(cycles), 4.0);
}

TEST(Rainflow, ReportsMeansAndTimeOrderedSampleIndices) {
  const auto cycles = countRainflowCycles(kAstmExample);
  // The first closed range is the half cycle -2 -> 1 (samples 0 and 1).
  ASSERT_FALSE(cycles.empty());
  EXPECT_DOUBLE_EQ(cycles[0].range, 3.0);
  EXPECT_DOUBLE_EQ(cycles[0].mean, -0.5);
  EXPECT_DOUBLE_EQ(cycles[0].count, 0.5);
  EXPECT_EQ(cycles[0].start, 0u);
  EXPECT_EQ(cycles[0].end, 1u);
  // The full cycle of range 4 closed first is -1 -> 3 (samples 4 and 5), mean 1.
  bool found = false;
  for (const auto& c : cycles) {
    if (c.count == 1.0 && c.range == 4.0) {
      EXPECT_EQ(c.start, 4u);
      EXPECT_EQ(c.end, 5u);
      EXPECT_DOUBLE_EQ(c.mean, 1.0);
      found = true;
      break;
    }
  }
  EXPECT_TRUE(found);
  for (const auto& c : cycles) EXPECT_LT(c.start, c.end);
}

TEST(Rainflow, PlateausAndRepeatedSamplesChangeNothingButIndices) {
  const std::vector<double> with_plateaus{-2, -2, 1, 1, 1, -3, 0, 5, 5, -1, 3, 3, -4, 4, 4, -2, -2};
  const auto plain = countRainflowCycles(kAstmExample);
  const auto padded = countRainflowCycles(with_plateaus);
  EXPECT_EQ(countsByRange(padded), countsByRange(plain));
  ASSERT_EQ(padded.size(), plain.size());
  for (std::size_t i = 0; i < plain.size(); ++i) EXPECT_DOUBLE_EQ(padded[i].mean, plain[i].mean);
  // A turning point on a plateau is the plateau's first sample.
  EXPECT_EQ(padded[0].start, 0u);
  EXPECT_EQ(padded[0].end, 2u);
}

TEST(Rainflow, MonotoneStretchesAreNotTurningPoints) {
  // 0 -> 0.5 -> 1 is one rising range; the middle sample is not a turning point.
  const auto cycles = countRainflowCycles({0.0, 0.5, 1.0, 0.25});
  const std::map<double, double> expected{{0.75, 0.5}, {1.0, 0.5}};
  EXPECT_EQ(countsByRange(cycles), expected);
}

TEST(Rainflow, EmptyOneAndTwoPointSeries) {
  EXPECT_TRUE(countRainflowCycles({}).empty());
  EXPECT_TRUE(countRainflowCycles({0.4}).empty());
  EXPECT_TRUE(countRainflowCycles({0.4, 0.4, 0.4}).empty());
  const auto two = countRainflowCycles({0.9, 0.3});
  ASSERT_EQ(two.size(), 1u);
  EXPECT_DOUBLE_EQ(two[0].range, 0.6);
  EXPECT_DOUBLE_EQ(two[0].mean, 0.6);
  EXPECT_DOUBLE_EQ(two[0].count, 0.5);
  EXPECT_EQ(two[0].start, 0u);
  EXPECT_EQ(two[0].end, 1u);
}

TEST(Rainflow, RepeatedIdenticalCyclesCountAsFullCycles) {
  // Charge to 0.95, fly down to 0.35, ten times: nine full cycles of depth 0.6 close, the
  // residue keeps the first and last half ranges.
  std::vector<double> soc{0.95};
  for (int i = 0; i < 10; ++i) {
    soc.push_back(0.35);
    soc.push_back(0.95);
  }
  const auto cycles = countRainflowCycles(soc);
  EXPECT_DOUBLE_EQ(totalCount(cycles), 10.0);
  for (const auto& c : cycles) EXPECT_NEAR(c.range, 0.6, 1e-12);
}

TEST(Rainflow, ResidueLeavesTheCounterUnchanged) {
  RainflowCounter counter;
  std::vector<RainflowCycle> closed;
  counter.add(std::vector<double>{-2, 1, -3, 5}, closed);
  const auto first = counter.residue();
  const auto again = counter.residue();
  EXPECT_TRUE(sameCycles(first, again));
  counter.add(std::vector<double>{-1, 3, -4, 4, -2}, closed);
  auto all = closed;
  const auto rest = counter.residue();
  all.insert(all.end(), rest.begin(), rest.end());
  EXPECT_TRUE(sameCycles(all, countRainflowCycles(kAstmExample)));
}

TEST(Rainflow, LongRandomSeriesCountedInPiecesMatchesCountedAtOnce) {
  const unsigned seed = 20240611;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> soc(0.0, 1.0);
  std::bernoulli_distribution repeat(0.1);
  std::vector<double> series;
  for (int i = 0; i < 200000; ++i) {
    // Rounded values and repeats make ties and plateaus common.
    const double v = std::round(soc(rng) * 64.0) / 64.0;
    series.push_back(v);
    if (repeat(rng)) series.push_back(v);
  }
  const auto at_once = countRainflowCycles(series);

  RainflowCounter counter;
  std::vector<RainflowCycle> in_pieces;
  std::uniform_int_distribution<std::size_t> piece(0, 5000);
  std::size_t done = 0;
  while (done < series.size()) {
    const std::size_t n = std::min(piece(rng), series.size() - done);
    counter.add(series.data() + done, n, in_pieces);
    done += n;
    if (piece(rng) % 7 == 0) (void)counter.residue();  // peeking changes nothing
  }
  const auto rest = counter.residue();
  in_pieces.insert(in_pieces.end(), rest.begin(), rest.end());
  EXPECT_TRUE(sameCycles(in_pieces, at_once)) << "seed " << seed;
  EXPECT_EQ(counter.samplesSeen(), series.size());
}

TEST(Rainflow, RejectsNonFiniteSamplesNamingTheirIndex) {
  RainflowCounter counter;
  std::vector<RainflowCycle> closed;
  counter.add(0.5, closed);
  try {
    counter.add(std::nan(""), closed);
    FAIL() << "NaN accepted";
  } catch (const ceilplan::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sample 1"), std::string::npos) << e.what();
  }
  EXPECT_THROW(counter.add(INFINITY, closed), ceilplan::InputError);
  EXPECT_EQ(counter.samplesSeen(), 1u);
}
