// Tour ordering: exact Held-Karp at 12 targets, the heuristic at 20 and 50; the sortie split
// that follows, at 20 and 50 targets.

#include "ceilplan/mission/sortie_plan.hpp"
#include "ceilplan/mission/tour_order.hpp"
#include "test_tour_random_costs.hpp"

#include <benchmark/benchmark.h>

namespace {

using ceilplan::mission::CostMatrix;

// Climbing costs 2 per metre on top of distance: asymmetric, like battery costs.
CostMatrix randomCosts(int targets, std::uint64_t seed) {
  return ceilplan::testing::randomTourCosts(targets, seed, 2.0);
}

void BM_HeldKarp(benchmark::State& state) {
  const CostMatrix costs = randomCosts(static_cast<int>(state.range(0)), 1);
  for (auto _ : state) {
    const double cost = ceilplan::mission::heldKarpTour(costs).cost;
    benchmark::DoNotOptimize(cost);
  }
}
BENCHMARK(BM_HeldKarp)->Arg(12)->Unit(benchmark::kMillisecond);

void BM_Heuristic(benchmark::State& state) {
  const CostMatrix costs = randomCosts(static_cast<int>(state.range(0)), 1);
  for (auto _ : state) {
    const double cost = ceilplan::mission::heuristicTour(costs, 1).cost;
    benchmark::DoNotOptimize(cost);
  }
}
BENCHMARK(BM_Heuristic)->Arg(20)->Arg(50)->Unit(benchmark::kMillisecond);

// Legs at 9.5 A and 2 m/s over the random matrix's distances, 20 s dwells at 8 A: a 50-target
// tour needs several sorties of the paper's pack.
void BM_Sorties(benchmark::State& state) {
  using namespace ceilplan::mission;
  const int targets = static_cast<int>(state.range(0));
  const CostMatrix metres = randomCosts(targets, 1);
  TourCosts legs;
  legs.names.assign(targets + 1, "target");
  legs.dwells.assign(targets + 1, Dwell{20.0, 8.0, std::nullopt, {}});
  legs.legs = PairTable<LegCost>(targets + 1);
  for (int i = 0; i <= targets; ++i)
    for (int j = 0; j <= targets; ++j) {
      const double duration_s = metres(i, j) / 2.0;
      legs.legs[i][j] = {9.5 * duration_s / 3600.0, duration_s, 9.5, {}, {}};
    }
  const std::vector<int> order = heuristicTour(metres, 1).targets;
  SortieOptions options;
  options.ageing_model = "xu";
  for (auto _ : state) {
    const double wear = planSorties(legs, order, BatterySpec{}, options).wear;
    benchmark::DoNotOptimize(wear);
  }
}
BENCHMARK(BM_Sorties)->Arg(20)->Arg(50)->Unit(benchmark::kMillisecond);

}  // namespace
