#pragma once
/// @file
/// The order in which a tour visits its targets: a travelling-salesman tour over a cost matrix
/// whose index 0 is home (the tour starts and ends there). Costs may be asymmetric (climbing
/// costs more than descending), so a reversed stretch of the tour is priced anew.

#include "ceilplan/core/error.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace ceilplan::mission {

/// costs(i, j): the cost of flying from i to j; index 0 is home, 1..N the targets.
using CostMatrix = Eigen::MatrixXd;

/// A visiting order of a tour's targets and its cost.
struct TourOrder {
  std::vector<int> targets;  ///< matrix indices 1..N in visiting order (home left out)
  double cost = 0.0;         ///< home -> targets -> home
  std::string method;        ///< "held-karp" or "nearest-neighbour+2-opt+or-opt"
  std::uint64_t seed = 0;    ///< the heuristic's seed (0 for Held-Karp, which draws nothing)
};

/// Perturbation rounds of the heuristic: 50 targets take about 10 ms (bench_tour_order).
inline constexpr int kDefaultTourRestarts = 200;

/// How orderTour chooses between the exact and the heuristic order.
struct TourOrderOptions {
  int exact_max_targets = 12;           ///< Held-Karp up to this many targets, the heuristic beyond
  std::uint64_t seed = 1;               ///< for the heuristic's random restarts
  int restarts = kDefaultTourRestarts;  ///< perturbation rounds of the heuristic (iterated local search)
};

/// The cost of visiting `targets` in order, from home and back.
double tourCost(const CostMatrix& costs, const std::vector<int>& targets);

/// Exact: Held-Karp dynamic programming over subsets, O(2^N N^2) time, O(2^N N) memory.
/// Throws ceilplan::InputError for more than kHeldKarpMaxTargets targets or a bad matrix.
inline constexpr int kHeldKarpMaxTargets = 15;
/// The exact cheapest order (Held-Karp) of the targets of `costs`.
TourOrder heldKarpTour(const CostMatrix& costs);

/// Heuristic: nearest neighbour from home, then 2-opt and Or-opt moves (segments of 1 to 3
/// targets, either way round) until none improves, then `restarts` rounds of a random
/// double-bridge kick followed by the same local search, keeping the best. Deterministic for a seed.
TourOrder heuristicTour(const CostMatrix& costs, std::uint64_t seed, int restarts = kDefaultTourRestarts);

/// Held-Karp up to options.exact_max_targets targets, the heuristic beyond.
TourOrder orderTour(const CostMatrix& costs, const TourOrderOptions& options = {});

/// A tour of many places (docs/tours.md, "Large tours"), where a full cost matrix is out of
/// reach: `cost(i, j)` is asked only for the pairs the search examines (from this thread; it may
/// route a leg on first use, so it should cache), and moves only join a place to one of its
/// `neighbours` (indexed 0..N like the places, each list nearest first; home may appear). A move
/// is first priced with `bound(i, j)`, a cheap lower bound on cost(i, j) (the cost itself where it
/// is known), and priced exactly only if that might gain. From each of `starts` (orders of the
/// targets 1..N), 2-opt and Or-opt moves (stretches of 1 to 3 targets, either way round,
/// asymmetric costs priced as in heuristicTour) are applied in sweeps over the tour until a sweep
/// finds none; the cheapest result wins (the first on a tie). Then `kicks` rounds of a double
/// bridge within a window of 3 x `kick_window` positions (chosen at random from `seed`), each
/// followed by the same local search, keeping the result when it is cheaper (iterated local
/// search). Deterministic for a seed. Throws ceilplan::InputError for bad starts or lists.
using PairCost = std::function<double(int from, int to)>;
/// The order of a large tour by neighbour lists, as described above.
TourOrder neighbourListTour(int target_count, const PairCost& cost, const PairCost& bound,
                            const std::vector<std::vector<int>>& neighbours,
                            const std::vector<std::vector<int>>& starts, int kicks = 0, std::uint64_t seed = 1,
                            int kick_window = 10);

/// The `k` nearest other places of each place by straight-line distance (ties by index), nearest
/// first: every leg is at least that long, so its charge is at least the distance times the least
/// charge per metre the vehicle can fly (FlightCostModel::minCostPerMetre), and ranking by
/// distance ranks by that bound. Scans outwards in x order, near-linear for spread-out places.
std::vector<std::vector<int>> nearestPlaces(const std::vector<Eigen::Vector3d>& places_m, int k);

/// A nearest-neighbour order of the targets 1..N from home, moving to the nearest unvisited of the
/// current place's `neighbours`, else the nearest unvisited of all (straight-line distance).
std::vector<int> nearestNeighbourOrder(const std::vector<Eigen::Vector3d>& places_m,
                                       const std::vector<std::vector<int>>& neighbours);

/// Throws ceilplan::InputError unless `costs` is square, at least 1 x 1, with finite,
/// non-negative entries.
void validateCostMatrix(const CostMatrix& costs);

}  // namespace ceilplan::mission
