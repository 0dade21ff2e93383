// Tour ordering: Held-Karp is exact (checked against brute force), the heuristic stays within
// 2 % of it, and both price asymmetric costs (a reversed stretch costs what it costs).

#include "ceilplan/core/error.hpp"
#include "ceilplan/mission/tour_order.hpp"
#include "test_tour_random_costs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>

namespace ceilplan::mission {
namespace {

CostMatrix randomCosts(int targets, std::uint64_t seed, double climb_penalty) {
  return testing::randomTourCosts(targets, seed, climb_penalty);
}

double bruteForceCost(const CostMatrix& costs) {
  std::vector<int> order(costs.rows() - 1);
  std::iota(order.begin(), order.end(), 1);
  double best = tourCost(costs, order);
  while (std::next_permutation(order.begin(), order.end())) best = std::min(best, tourCost(costs, order));
  return best;
}

void expectPermutationOfTargets(const TourOrder& tour, int targets) {
  std::vector<int> sorted = tour.targets;
  std::sort(sorted.begin(), sorted.end());
  std::vector<int> expected(targets);
  std::iota(expected.begin(), expected.end(), 1);
  EXPECT_EQ(sorted, expected);
}

TEST(TourOrder, HeldKarpMatchesBruteForceOnSmallInstances) {
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const int targets = 1 + static_cast<int>(seed % 7);
    const CostMatrix costs = randomCosts(targets, seed, seed % 2 ? 3.0 : 0.0);
    const TourOrder tour = heldKarpTour(costs);
    expectPermutationOfTargets(tour, targets);
    EXPECT_NEAR(tour.cost, bruteForceCost(costs), 1e-9) << "seed " << seed;
    EXPECT_NEAR(tour.cost, tourCost(costs, tour.targets), 1e-9);
    EXPECT_EQ(tour.method, "held-karp");
  }
}

TEST(TourOrder, HeuristicAgreesWithHeldKarpWithinTwoPercentOnTenTargets) {
  std::vector<double> gaps;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const CostMatrix costs = randomCosts(10, 1000 + seed, seed % 2 ? 2.0 : 0.0);
    const TourOrder exact = heldKarpTour(costs);
    const TourOrder heuristic = heuristicTour(costs, seed);
    expectPermutationOfTargets(heuristic, 10);
    EXPECT_NEAR(heuristic.cost, tourCost(costs, heuristic.targets), 1e-9);
    EXPECT_GE(heuristic.cost, exact.cost - 1e-9);
    gaps.push_back(heuristic.cost / exact.cost - 1.0);
  }
  std::sort(gaps.begin(), gaps.end());
  std::printf("heuristic vs Held-Karp on 200 ten-target instances: median gap %.4f %%, worst %.4f %%\n",
              100 * gaps[gaps.size() / 2], 100 * gaps.back());
  EXPECT_LE(gaps.back(), 0.02);
}

TEST(TourOrder, AsymmetricCostsPickTheCheapDirection) {
  // Three targets on a line; going out along it is cheap, coming back along it is dear. The best
  // tour must go out through 1, 2, 3 and jump home, never the reverse.
  CostMatrix costs(4, 4);
  costs << 0, 1, 2, 3, 10, 0, 1, 2, 10, 10, 0, 1, 1, 10, 10, 0;
  const std::vector<int> out = {1, 2, 3};
  EXPECT_DOUBLE_EQ(heldKarpTour(costs).cost, 4.0);
  EXPECT_EQ(heldKarpTour(costs).targets, out);
  EXPECT_EQ(heuristicTour(costs, 7).targets, out);
  EXPECT_DOUBLE_EQ(tourCost(costs, {3, 2, 1}), 3 + 10 + 10 + 10);
}

TEST(TourOrder, LocalSearchStopsAtATrueLocalOptimumOfAsymmetricCosts) {
  // Priced with the real tour cost, no reversal of a stretch and no move of one target may
  // improve the heuristic's result: a delta that assumed symmetric costs would stop early or
  // accept a worse tour.
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const CostMatrix costs = randomCosts(14, 50 + seed, 5.0);
    const TourOrder tour = heuristicTour(costs, seed, 0);
    const int n = static_cast<int>(tour.targets.size());
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        std::vector<int> reversed = tour.targets;
        std::reverse(reversed.begin() + i, reversed.begin() + j + 1);
        EXPECT_GE(tourCost(costs, reversed), tour.cost - 1e-9) << "seed " << seed << " reversing " << i << ".." << j;
      }
    for (int i = 0; i < n; ++i)
      for (int to = 0; to < n; ++to) {
        std::vector<int> moved = tour.targets;
        const int target = moved[i];
        moved.erase(moved.begin() + i);
        moved.insert(moved.begin() + to, target);
        EXPECT_GE(tourCost(costs, moved), tour.cost - 1e-9) << "seed " << seed << " moving " << i << " to " << to;
      }
  }
}

TEST(TourOrder, HeuristicIsDeterministicForASeedAndReportsIt) {
  const CostMatrix costs = randomCosts(40, 3, 1.0);
  const TourOrder a = heuristicTour(costs, 42);
  const TourOrder b = heuristicTour(costs, 42);
  EXPECT_EQ(a.targets, b.targets);
  EXPECT_EQ(a.seed, 42u);
  expectPermutationOfTargets(a, 40);
  EXPECT_LE(a.cost, tourCost(costs, [] {
              std::vector<int> identity(40);
              std::iota(identity.begin(), identity.end(), 1);
              return identity;
            }()));
}

TEST(TourOrder, OrderTourSwitchesToTheHeuristicAboveTheExactLimit) {
  EXPECT_EQ(orderTour(randomCosts(12, 1, 0.0)).method, "held-karp");
  const TourOrder large = orderTour(randomCosts(13, 1, 0.0), {12, 9, 30});
  EXPECT_EQ(large.method, "nearest-neighbour+2-opt+or-opt");
  EXPECT_EQ(large.seed, 9u);
}

TEST(TourOrder, TrivialTours) {
  EXPECT_TRUE(heldKarpTour(CostMatrix::Zero(1, 1)).targets.empty());
  EXPECT_TRUE(heuristicTour(CostMatrix::Zero(1, 1), 1).targets.empty());
  CostMatrix one(2, 2);
  one << 0, 2, 3, 0;
  EXPECT_DOUBLE_EQ(heldKarpTour(one).cost, 5.0);
  EXPECT_DOUBLE_EQ(heuristicTour(one, 1).cost, 5.0);
}

TEST(TourOrder, RefusesBadInput) {
  EXPECT_THROW(heldKarpTour(randomCosts(16, 1, 0.0)), ceilplan::InputError);
  try {
    heldKarpTour(randomCosts(16, 1, 0.0));
  } catch (const ceilplan::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("at most 15 targets, got 16"), std::string::npos) << e.what();
  }
  CostMatrix nan = randomCosts(3, 1, 0.0);
  nan(1, 2) = std::nan("");
  EXPECT_THROW(orderTour(nan), ceilplan::InputError);
  CostMatrix negative = randomCosts(3, 1, 0.0);
  negative(2, 1) = -1;
  EXPECT_THROW(heuristicTour(negative, 1), ceilplan::InputError);
  EXPECT_THROW(orderTour(CostMatrix::Zero(2, 3)), ceilplan::InputError);
  EXPECT_THROW(orderTour(randomCosts(3, 1, 0.0), {16, 1, 30}), ceilplan::InputError);
}

}  // namespace
}  // namespace ceilplan::mission
