// Speed targets of the ageing models (docs/ageing.md, "Speed"): rainflow over 10 million samples in under 1 s;
// a 10-year history (15 missions a day, 6 samples each) fed mission by mission to the Xu model,
// reading the capacity loss after every mission as a duty simulation would, in under 1 s.
#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/battery/rainflow.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <random>
#include <vector>

namespace cb = ceilplan::battery;

namespace {

constexpr unsigned kSeed = 12345;  // printed in the benchmark's label

std::vector<double> randomSoc(std::size_t count) {
  std::mt19937_64 rng(kSeed);
  std::uniform_real_distribution<double> soc(0.0, 1.0);
  std::vector<double> series(count);
  for (double& v : series) v = soc(rng);
  return series;
}

void BM_Rainflow10MillionRandomSamples(benchmark::State& state) {
  const std::vector<double> series = randomSoc(10'000'000);
  std::size_t rows = 0;
  for (auto _ : state) {
    cb::RainflowCounter counter;
    std::vector<cb::RainflowCycle> cycles;
    cycles.reserve(series.size() / 2);
    counter.add(series, cycles);
    const auto rest = counter.residue();
    rows = cycles.size() + rest.size();
    benchmark::DoNotOptimize(cycles.data());
  }
  state.SetLabel("seed " + std::to_string(kSeed) + ", " + std::to_string(rows) + " cycle rows");
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(series.size()));
}
BENCHMARK(BM_Rainflow10MillionRandomSamples)->Unit(benchmark::kMillisecond);

// One mission as the duty engine samples it: take-off, cruise, landing, idle, charge, full.
std::vector<cb::AgeingSample> mission(double start_s, double lowest_soc) {
  return {{start_s, 0.95, 9.5},
          {start_s + 600.0, 0.5 * (0.95 + lowest_soc), 9.5},
          {start_s + 1200.0, lowest_soc, 0.0},
          {start_s + 1500.0, lowest_soc, -10.4},
          {start_s + 2600.0, 0.85, -10.4},
          {start_s + 2900.0, 0.95, 0.0}};
}

void tenYearsMissionByMission(benchmark::State& state, const char* model_name) {
  cb::AgeingModelOptions options;
  options.cell_voltage_of_soc = [](double soc) { return 3.3 + 0.9 * soc; };
  const int missions = 10 * 365 * 15;
  double loss = 0.0;
  for (auto _ : state) {
    const auto model = cb::makeAgeingModel(model_name, options);
    for (int m = 0; m < missions; ++m) {
      // Capacity fade deepens the next mission, as in the duty simulation.
      const auto samples = mission(m * 5760.0, std::max(0.05, 0.341 - 0.3 * loss));
      model->addSamples(samples);
      loss = model->capacityLoss();
    }
    const double final_loss = loss;  // const: see docs/contributing.md on DoNotOptimize
    benchmark::DoNotOptimize(final_loss);
  }
  state.SetLabel(std::to_string(missions * 6) + " samples, final loss " + std::to_string(loss));
}

void BM_XuTenYearsMissionByMission(benchmark::State& state) { tenYearsMissionByMission(state, "xu"); }
BENCHMARK(BM_XuTenYearsMissionByMission)->Unit(benchmark::kMillisecond);

void BM_SchmalstiegTenYearsMissionByMission(benchmark::State& state) { tenYearsMissionByMission(state, "schmalstieg"); }
BENCHMARK(BM_SchmalstiegTenYearsMissionByMission)->Unit(benchmark::kMillisecond);

}  // namespace
