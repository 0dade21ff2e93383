// The set cover: on random instances it covers every coverable element, never costs more than
// the greedy it starts from, stays within the greedy guarantee of the optimum found by brute
// force, and is deterministic; hand-made instances check the lazy greedy, the exchanges and the
// start from a flat patch's lawnmower tiling.

#include "ceilplan/mission/view_selection.hpp"

#include <gtest/gtest.h>

#include <random>

namespace ceilplan::mission {
namespace {

CandidateViews sets(const std::vector<std::vector<std::uint32_t>>& elements) {
  CandidateViews views;
  for (const auto& list : elements) views.add(CameraPose{}, elementRuns(list), CoverSummary{});
  return views;
}

double optimum(const CandidateViews& views, const std::vector<double>& cost, std::size_t elements) {
  std::vector<std::uint8_t> coverable(elements, 0);
  for (const ElementRun& run : views.runs)
    for (std::uint32_t e = run.first; e < run.first + run.count; ++e) coverable[e] = 1;
  double best = INFINITY;
  for (std::uint32_t mask = 0; mask < (1u << views.size()); ++mask) {
    std::vector<std::uint8_t> covered(elements, 0);
    double total = 0.0;
    for (std::uint32_t v = 0; v < views.size(); ++v)
      if (mask & (1u << v)) {
        total += cost[v];
        for (ElementIterator s = views.begin(v); s != views.end(v); ++s) covered[*s] = 1;
      }
    if (covered == coverable) best = std::min(best, total);
  }
  return best;
}

// A candidate keeps its covered elements as runs of consecutive indices and gives every index
// back, in order, one run per gap in the list.
TEST(CandidateViews, RunsGiveBackTheAscendingListsTheyWereMadeFrom) {
  std::mt19937 random(3);
  std::vector<std::vector<std::uint32_t>> lists(40);
  for (auto& list : lists)
    for (std::uint32_t e = 0; e < 300; ++e)
      if (random() % 4 != 0) list.push_back(e);
  lists.push_back({7});
  const CandidateViews views = sets(lists);
  ASSERT_EQ(views.size(), lists.size());
  for (std::size_t v = 0; v < lists.size(); ++v) {
    std::vector<std::uint32_t> back;
    for (ElementIterator s = views.begin(v); s != views.end(v); ++s) back.push_back(*s);
    EXPECT_EQ(back, lists[v]) << "candidate " << v;
    std::size_t gaps = 0;
    for (std::size_t k = 1; k < lists[v].size(); ++k) gaps += lists[v][k] != lists[v][k - 1] + 1;
    EXPECT_EQ(views.offsets[v + 1] - views.offsets[v], gaps + 1) << "candidate " << v;
  }
}

TEST(ViewSelection, RandomInstancesAgainstBruteForce) {
  std::mt19937 random(7);
  for (int instance = 0; instance < 60; ++instance) {
    const std::size_t element_count = 6 + random() % 10, view_count = 4 + random() % 10;
    std::vector<std::vector<std::uint32_t>> lists(view_count);
    std::size_t largest = 1;
    for (auto& list : lists) {
      for (std::uint32_t e = 0; e < element_count; ++e)
        if (random() % 3 == 0) list.push_back(e);
      largest = std::max(largest, list.size());
    }
    const CandidateViews views = sets(lists);
    std::vector<double> area(element_count), cost(view_count);
    for (double& a : area) a = 0.5 + (random() % 100) / 100.0;
    for (double& c : cost) c = 1.0 + (random() % 100) / 25.0;
    const SetCoverResult result = chooseViews(views, area, cost);

    std::vector<std::uint8_t> coverable(element_count, 0), covered(element_count, 0);
    for (const ElementRun& run : views.runs)
      for (std::uint32_t e = run.first; e < run.first + run.count; ++e) coverable[e] = 1;
    double total = 0.0;
    for (const std::uint32_t v : result.chosen) {
      total += cost[v];
      for (ElementIterator s = views.begin(v); s != views.end(v); ++s) covered[*s] = 1;
    }
    EXPECT_EQ(covered, coverable) << "instance " << instance;
    EXPECT_NEAR(total, result.cost, 1e-9);
    EXPECT_LE(result.cost, result.greedy_cost + 1e-9);
    double harmonic = 0.0;  // greedy weighted set cover: within H(largest set) of the optimum (Chvatal 1979)
    for (std::size_t k = 1; k <= largest; ++k) harmonic += 1.0 / k;
    const double best = optimum(views, cost, element_count);
    EXPECT_GE(result.cost, best - 1e-9);
    EXPECT_LE(result.cost, harmonic * best + 1e-9) << "instance " << instance;
    EXPECT_EQ(chooseViews(views, area, cost).chosen, result.chosen);  // deterministic
  }
}

TEST(ViewSelection, LazyGreedyTakesTheBestRatioFirst) {
  // View 2 covers everything but costs more than views 0 and 1 together.
  const CandidateViews views = sets({{0, 1}, {2, 3}, {0, 1, 2, 3}});
  const SetCoverResult cheap = chooseViews(views, {1, 1, 1, 1}, {1.0, 1.0, 3.0});
  EXPECT_EQ(cheap.chosen, (std::vector<std::uint32_t>{0, 1}));
  const SetCoverResult one = chooseViews(views, {1, 1, 1, 1}, {1.0, 1.0, 1.9});
  EXPECT_EQ(one.chosen, (std::vector<std::uint32_t>{2}));
}

TEST(ViewSelection, ExchangesReplaceViewsMadeRedundant) {
  // Greedy takes view 0 (1.0 for 3 elements), then view 3 (1.5 for the 2 still open): 2.5.
  // Adding view 4 (0.6) makes view 0 redundant: the optimum {3, 4} costs 2.1.
  const CandidateViews views = sets({{0, 1, 2}, {3}, {4}, {1, 2, 3, 4}, {0}});
  const std::vector<double> cost{1.0, 0.9, 0.9, 1.5, 0.6};
  const SetCoverResult result = chooseViews(views, {1, 1, 1, 1, 1}, cost);
  EXPECT_NEAR(result.greedy_cost, 2.5, 1e-12);
  EXPECT_EQ(result.greedy_views, 2u);
  EXPECT_EQ(result.exchanges, 1u);
  EXPECT_NEAR(result.cost, 2.1, 1e-12);
  EXPECT_EQ(result.chosen, (std::vector<std::uint32_t>{3, 4}));
}

// Six elements in a row, one flat patch: a tiling of two views end to end (0: elements 0-2,
// 1: 3-5), a view centred on the row (2: 1-4, the best ratio) and two edge slivers (3: 0, 4: 5).
CandidateViews rowWithATiling() {
  CandidateViews views = sets({{0, 1, 2}, {3, 4, 5}, {1, 2, 3, 4}, {0}, {5}});
  views.tilings.push_back({0, {0, 1}});
  return views;
}

TEST(ViewSelection, AWholeTilingBeatsTheGreedysSlivers) {
  // Greedy takes the centred view (1.0 for 4 elements), then each sliver (0.6 for 1) rather than
  // a tiling view (1.0 for 1): 2.2, and no exchange helps (a tiling view frees one sliver only).
  const std::vector<double> area(6, 1.0), cost{1.0, 1.0, 1.0, 0.6, 0.6};
  CandidateViews plain = rowWithATiling();
  plain.tilings.clear();
  const SetCoverResult greedy = chooseViews(plain, area, cost);
  EXPECT_EQ(greedy.chosen, (std::vector<std::uint32_t>{2, 3, 4}));
  EXPECT_NEAR(greedy.cost, 2.2, 1e-12);
  EXPECT_EQ(greedy.tiling_views, 0u);
  // Started from the patch's tiling, the cover is the tiling: 2.0.
  const SetCoverResult tiled = chooseViews(rowWithATiling(), area, cost);
  EXPECT_EQ(tiled.chosen, (std::vector<std::uint32_t>{0, 1}));
  EXPECT_NEAR(tiled.cost, 2.0, 1e-12);
  EXPECT_EQ(tiled.tiling_views, 2u);
}

TEST(ViewSelection, ATilingDearerThanTheGreedysCoverIsNotKept) {
  // Slivers at 0.4: the greedy's cover costs 1.8, less than the tiling's 2.0.
  const SetCoverResult result = chooseViews(rowWithATiling(), std::vector<double>(6, 1.0), {1.0, 1.0, 1.0, 0.4, 0.4});
  EXPECT_EQ(result.chosen, (std::vector<std::uint32_t>{2, 3, 4}));
  EXPECT_NEAR(result.cost, 1.8, 1e-12);
  EXPECT_EQ(result.tiling_views, 0u);
}

TEST(ViewSelection, OfAPatchsTilingsTheCheapestPerAreaIsTaken) {
  // A second tiling of the patch, three views (5-7) of 0.7 covering the row: 2.1 against 2.0.
  CandidateViews views = sets({{0, 1, 2}, {3, 4, 5}, {1, 2, 3, 4}, {0}, {5}, {0, 1}, {2, 3}, {4, 5}});
  views.tilings = {{0, {5, 6, 7}}, {0, {0, 1}}};
  const SetCoverResult result =
      chooseViews(views, std::vector<double>(6, 1.0), {1.0, 1.0, 1.0, 0.6, 0.6, 0.7, 0.7, 0.7});
  EXPECT_EQ(result.chosen, (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(result.tiling_views, 2u);
}

TEST(ViewSelection, RefusesBadCosts) {
  const CandidateViews views = sets({{0}});
  EXPECT_THROW(chooseViews(views, {1.0}, {0.0}), ceilplan::InputError);
  EXPECT_THROW(chooseViews(views, {1.0}, {NAN}), ceilplan::InputError);
  EXPECT_THROW(chooseViews(views, {1.0}, {1.0, 2.0}), ceilplan::InputError);
  EXPECT_THROW(chooseViews(sets({{3}}), {1.0}, {1.0}), ceilplan::InputError);
  CandidateViews unknown_tiling = sets({{0}});
  unknown_tiling.tilings.push_back({0, {1}});
  EXPECT_THROW(chooseViews(unknown_tiling, {1.0}, {1.0}), ceilplan::InputError);
}

}  // namespace
}  // namespace ceilplan::mission
