// Duty-cycle simulation speed. Target (issue 2): an event-driven 10-year run of 15 missions a
// day well under a second.

#include "ceilplan/battery/duty_cycle.hpp"

#include <benchmark/benchmark.h>

namespace ceilplan::battery {
namespace {

void runYears(benchmark::State& state, double step_s) {
  const Pack pack;
  DutyCycle duty;
  duty.mission = flyIdleChargeMission(9.5, 1200.0, 300.0, 10.4, 1200.0, 0.95);
  duty.days = static_cast<int>(state.range(0)) * 365;
  DutyOptions options;
  options.step_s = step_s;
  options.record_first_day = false;
  for (auto _ : state) {
    const DutyResult result = simulateDuty(pack, duty, options);
    benchmark::DoNotOptimize(result.final_state.fec);
  }
  state.counters["missions"] = static_cast<double>(duty.days) * duty.missions_per_day;
}

void BM_DutyCycleExact(benchmark::State& state) { runYears(state, 0.0); }
void BM_DutyCycle30sSteps(benchmark::State& state) { runYears(state, 30.0); }

BENCHMARK(BM_DutyCycleExact)->Arg(1)->Arg(10)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DutyCycle30sSteps)->Arg(10)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ceilplan::battery
