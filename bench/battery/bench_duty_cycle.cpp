// Duty-cycle simulation speed. Targets: an event-driven 10-year run of 15 missions a day well
// under a second (docs/battery.md, "Speed"); the same with capacity fade fed back through the Xu
// model under a second (docs/ageing.md).

#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/battery/duty_cycle.hpp"
#include "ceilplan/battery/lifetime.hpp"

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

// 15 ten-minute 8 A flights a day: shallow enough that the pack survives the whole 10 years,
// so every one of the 54,750 missions is simulated and fed to the model.
void BM_TenYearsWithXuFade(benchmark::State& state) {
  DutyCycle duty;
  duty.mission = flyIdleChargeMission(8.0, 600.0, 300.0, 10.4, 1200.0, 0.95);
  LifetimeOptions options;
  options.study_days = 3650;
  options.max_projection_days = 3650;
  double days = 0.0;
  for (auto _ : state) {
    auto model = makeAgeingModel("xu", {});
    const LifetimeResult result = projectLifetime(Pack{}, duty, *model, {}, options);
    days = static_cast<double>(result.soh_by_day.size());
    benchmark::DoNotOptimize(result.capacity_loss);
  }
  state.counters["days"] = days;
}

BENCHMARK(BM_TenYearsWithXuFade)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DutyCycleExact)->Arg(1)->Arg(10)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DutyCycle30sSteps)->Arg(10)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ceilplan::battery
