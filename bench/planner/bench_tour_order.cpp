// Tour ordering: exact Held-Karp at 12 targets, the heuristic at 20 and 50.

#include "ceilplan/planner/tour_order.hpp"

#include <benchmark/benchmark.h>

#include <random>

namespace {

using ceilplan::planner::CostMatrix;

// Targets in a 50 x 20 x 6 m box; climbing costs 2 per metre on top of distance (asymmetric).
CostMatrix randomCosts(int targets, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> x(0, 50), y(-10, 10), z(0, 6);
  std::vector<Eigen::Vector3d> points(targets + 1);
  for (auto& p : points) p = {x(random), y(random), z(random)};
  CostMatrix costs(targets + 1, targets + 1);
  for (int i = 0; i <= targets; ++i)
    for (int j = 0; j <= targets; ++j)
      costs(i, j) = (points[j] - points[i]).norm() + 2.0 * std::max(0.0, points[j].z() - points[i].z());
  return costs;
}

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
