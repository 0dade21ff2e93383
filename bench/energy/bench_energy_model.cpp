// One current evaluation with the gaps known: the planner's cost calls this per state.
// Target (docs/energy.md, "Performance"): under 100 ns.

#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/energy/paper_quad.hpp"

#include <benchmark/benchmark.h>

#include <array>
#include <cstddef>

using namespace ceilplan::energy;

namespace {

constexpr std::size_t kInputs = 1024;  // varied inputs, so nothing is folded or predicted away

struct Inputs {
  std::array<double, kInputs> gap_m;
  std::array<FlightCondition, kInputs> flight;
  Inputs() {
    for (std::size_t i = 0; i < kInputs; ++i) {
      gap_m[i] = i % 8 == 0 ? kNoSurface : 0.4 * static_cast<double>((i * 37) % 1000) / 1000.0;
      flight[i].ground_gap_m = i % 3 == 0 ? 0.5 : kNoSurface;
      flight[i].speed_m_s = static_cast<double>(i % 13);
      flight[i].climb_m_s = static_cast<double>(i % 5) * 0.5 - 1.0;
      flight[i].soc = 0.3 + 0.6 * static_cast<double>(i % 97) / 97.0;
    }
  }
};

const Inputs& inputs() {
  static const Inputs shared;
  return shared;
}

// Runs `evaluate(model, inputs, i)` once per iteration, cycling i through the inputs.
template <typename Evaluate>
void cycleThroughInputs(benchmark::State& state, Evaluate evaluate) {
  const EnergyModel model(paperQuadParameters());
  const Inputs& in = inputs();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(evaluate(model, in, i));
    i = (i + 1) % kInputs;
  }
}

void BM_CurrentSameGapOnAllRotors(benchmark::State& state) {
  cycleThroughInputs(state, [](const EnergyModel& model, const Inputs& in, std::size_t i) {
    return model.currentA(in.gap_m[i], 1.0, in.flight[i]);
  });
}
BENCHMARK(BM_CurrentSameGapOnAllRotors);

void BM_CurrentPerRotorGaps(benchmark::State& state) {
  cycleThroughInputs(state, [](const EnergyModel& model, const Inputs& in, std::size_t i) {
    const RotorCeiling rotors[4] = {{in.gap_m[i], 1.0},
                                    {in.gap_m[(i + 1) % kInputs], 0.5},
                                    {in.gap_m[(i + 2) % kInputs], 1.0},
                                    {in.gap_m[(i + 3) % kInputs], 0.0}};
    return model.currentA(rotors, 4, in.flight[i]);
  });
}
BENCHMARK(BM_CurrentPerRotorGaps);

void BM_FullBreakdown(benchmark::State& state) {
  cycleThroughInputs(state, [](const EnergyModel& model, const Inputs& in, std::size_t i) {
    return model.breakdown(in.gap_m[i], 1.0, in.flight[i]);
  });
}
BENCHMARK(BM_FullBreakdown);

}  // namespace
