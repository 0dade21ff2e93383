// Tour ordering: exact Held-Karp at 12 targets, the heuristic at 20 and 50.

#include "ceilplan/planner/tour_order.hpp"
#include "test_tour_random_costs.hpp"

#include <benchmark/benchmark.h>

namespace {

using ceilplan::planner::CostMatrix;

// Climbing costs 2 per metre on top of distance: asymmetric, like battery costs.
CostMatrix randomCosts(int targets, std::uint64_t seed) { return ceilplan::testing::randomTourCosts(targets, seed, 2.0); }

void BM_HeldKarp(benchmark::State& state) {
  const CostMatrix costs = randomCosts(static_cast<int>(state.range(0)), 1);
  for (auto _ : state) {
    const double cost = ceilplan::planner::heldKarpTour(costs).cost;
    benchmark::DoNotOptimize(cost);
  }
}
BENCHMARK(BM_HeldKarp)->Arg(12)->Unit(benchmark::kMillisecond);

void BM_Heuristic(benchmark::State& state) {
  const CostMatrix costs = randomCosts(static_cast<int>(state.range(0)), 1);
  for (auto _ : state) {
    const double cost = ceilplan::planner::heuristicTour(costs, 1).cost;
    benchmark::DoNotOptimize(cost);
  }
}
BENCHMARK(BM_Heuristic)->Arg(20)->Arg(50)->Unit(benchmark::kMillisecond);

}  // namespace
