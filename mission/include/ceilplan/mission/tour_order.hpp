#pragma once
// The order in which a tour visits its targets: a travelling-salesman tour over a cost matrix
// whose index 0 is home (the tour starts and ends there). Costs may be asymmetric (climbing
// costs more than descending), so a reversed stretch of the tour is priced anew.

#include "ceilplan/core/error.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace ceilplan::mission {

// costs(i, j): the cost of flying from i to j; index 0 is home, 1..N the targets.
using CostMatrix = Eigen::MatrixXd;

struct TourOrder {
  std::vector<int> targets;  // matrix indices 1..N in visiting order (home left out)
  double cost = 0.0;         // home -> targets -> home
  std::string method;        // "held-karp" or "nearest-neighbour+2-opt+or-opt"
  std::uint64_t seed = 0;    // the heuristic's seed (0 for Held-Karp, which draws nothing)
};

// Perturbation rounds of the heuristic: 50 targets take about 10 ms (bench_tour_order).
inline constexpr int kDefaultTourRestarts = 200;

struct TourOrderOptions {
  int exact_max_targets = 12;  // Held-Karp up to this many targets, the heuristic beyond
  std::uint64_t seed = 1;      // for the heuristic's random restarts
  int restarts = kDefaultTourRestarts;  // perturbation rounds of the heuristic (iterated local search)
};

// The cost of visiting `targets` in order, from home and back.
double tourCost(const CostMatrix& costs, const std::vector<int>& targets);

// Exact: Held-Karp dynamic programming over subsets, O(2^N N^2) time, O(2^N N) memory.
// Throws ceilplan::InputError for more than kHeldKarpMaxTargets targets or a bad matrix.
inline constexpr int kHeldKarpMaxTargets = 15;
TourOrder heldKarpTour(const CostMatrix& costs);

// Heuristic: nearest neighbour from home, then 2-opt and Or-opt moves (segments of 1 to 3
// targets, either way round) until none improves, then `restarts` rounds of a random
// double-bridge kick followed by the same local search, keeping the best. Deterministic for a seed.
TourOrder heuristicTour(const CostMatrix& costs, std::uint64_t seed, int restarts = kDefaultTourRestarts);

// Held-Karp up to options.exact_max_targets targets, the heuristic beyond.
TourOrder orderTour(const CostMatrix& costs, const TourOrderOptions& options = {});

// Throws ceilplan::InputError unless `costs` is square, at least 1 x 1, with finite,
// non-negative entries.
void validateCostMatrix(const CostMatrix& costs);

}  // namespace ceilplan::mission
