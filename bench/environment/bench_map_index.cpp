// Building the map index (grid, column runs, distance field) and a vehicle's Environment on it,
// per map: time and memory per million known voxels. The shipped maps by default; with
// `--maps DIR`, every .bt file in DIR too (scripts/bench-map-index generates the shipped scenes
// at 0.1 and 0.05 m, a 200 m bridge, and geb079 resampled to 0.02 m, and runs each map in its
// own process so the peak resident memory is that map's).
//   build/bench/environment/bench_map_index [--maps DIR] [--benchmark_filter=...]
//   build/bench/environment/bench_map_index --resample IN.bt FACTOR OUT.bt

#include "ceilplan/environment/environment.hpp"
#include "ceilplan/environment/map_index.hpp"
#include "ceilplan/mission/vehicle.hpp"

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using namespace ceilplan::environment;

VehicleGeometry quad() { return ceilplan::mission::Vehicle::defaultQuad().geometry; }

double peakRssMegabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

// CPU time of the whole process (every thread), user and system: on a machine shared with other
// work, wall time measures the others as well; CPU time divided by the threads used does not.
double processCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * t.tv_usec; };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

void reportSizes(benchmark::State& state, const OccupancyMap& map, const MapIndex& index, double seconds_per_build,
                 double cpu_seconds_per_build) {
  const double voxel_m3 = std::pow(map.resolution_m(), 3);
  const double known =
      std::round(index.grid().frame().voxelCount() - index.unknownSummary().unknown_volume_m3 / voxel_m3);
  state.counters["known_Mvox"] = known / 1e6;
  state.counters["box_Mvox"] = static_cast<double>(index.grid().frame().voxelCount()) / 1e6;
  state.counters["s_per_Mknown"] = seconds_per_build / (known / 1e6);
  state.counters["cpu_s"] = cpu_seconds_per_build;
  state.counters["cpu_s_per_Mknown"] = cpu_seconds_per_build / (known / 1e6);
  state.counters["index_MB"] = static_cast<double>(index.memoryBytes()) / (1 << 20);
  state.counters["MB_per_Mknown"] = static_cast<double>(index.memoryBytes()) / (1 << 20) / (known / 1e6);
  state.counters["peak_rss_MB"] = peakRssMegabytes();
}

// The index of one map, with the default (occupied) policy on two threads, as probe and plan build it.
void indexBuild(benchmark::State& state, const std::string& file, int workers) {
  const OccupancyMap map = OccupancyMap::load(file);
  MapIndexOptions options;
  options.workers = workers;
  std::shared_ptr<const MapIndex> index;
  double seconds = 0.0, cpu_seconds = 0.0;
  for (auto _ : state) {
    index.reset();
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = processCpuSeconds();
    try {
      index = MapIndex::build(map, options);
    } catch (const ceilplan::Error& e) {  // a box too large to index densely
      state.SkipWithError(e.what());
      return;
    }
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    cpu_seconds = processCpuSeconds() - cpu_start;
  }
  reportSizes(state, map, *index, seconds, cpu_seconds);
}

// A second vehicle geometry (free mode's standoff: margins 1 m wider) on the shared index:
// only its footprint masks are built.
void secondEnvironment(benchmark::State& state, const std::string& file) {
  const OccupancyMap map = OccupancyMap::load(file);
  std::shared_ptr<const MapIndex> index;
  try {
    index = MapIndex::build(map);
  } catch (const ceilplan::Error& e) {
    state.SkipWithError(e.what());
    return;
  }
  const Environment first(index, quad());
  VehicleGeometry standoff = quad();
  standoff.margin_m += 1.0;
  standoff.top_margin_m += 1.0;
  double cpu_seconds = 0.0;
  for (auto _ : state) {
    const double cpu_start = processCpuSeconds();
    const Environment second(index, standoff);
    benchmark::DoNotOptimize(second.memoryBytes());
    cpu_seconds += processCpuSeconds() - cpu_start;
  }
  state.counters["cpu_s"] = cpu_seconds / static_cast<double>(state.iterations());
  state.counters["masks_MB"] = static_cast<double>(first.memoryBytes()) / (1 << 20);
  state.counters["peak_rss_MB"] = peakRssMegabytes();
}

// Writes `in` resampled `factor` times finer (each voxel split into factor^3): a real scan at a
// finer resolution than it was recorded at, for the index's scaling (a box within the dense limit).
void resample(const std::string& in, int factor, const std::string& out) {
  const OccupancyMap map = OccupancyMap::load(in);
  const VoxelGrid coarse = VoxelGrid::fromTree(map.tree());
  const GridFrame& frame = coarse.frame();
  VoxelGrid fine(GridFrame(frame.resolution_m() / factor,
                           {frame.origin()[0] * factor, frame.origin()[1] * factor, frame.origin()[2] * factor},
                           {frame.size()[0] * factor, frame.size()[1] * factor, frame.size()[2] * factor}));
  for (int k = 0; k < fine.frame().size()[2]; ++k)
    for (int j = 0; j < fine.frame().size()[1]; ++j)
      for (int i = 0; i < fine.frame().size()[0]; ++i) fine.set(i, j, k, coarse.at(i / factor, j / factor, k / factor));
  toOcTree(fine)->writeBinary(out);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 5 && std::strcmp(argv[1], "--resample") == 0) {
    resample(argv[2], std::atoi(argv[3]), argv[4]);
    return 0;
  }
  std::vector<std::string> maps;
  for (const auto& entry : std::filesystem::directory_iterator(CEILPLAN_SOURCE_DIR "/maps"))
    if (entry.path().extension() == ".bt") maps.push_back(entry.path().string());
  std::vector<char*> arguments;
  for (int a = 0; a < argc; ++a) {
    if (std::strcmp(argv[a], "--maps") == 0 && a + 1 < argc) {
      for (const auto& entry : std::filesystem::directory_iterator(argv[++a]))
        if (entry.path().extension() == ".bt") maps.push_back(entry.path().string());
      continue;
    }
    arguments.push_back(argv[a]);
  }
  std::sort(maps.begin(), maps.end());
  for (const std::string& file : maps) {
    const std::string name = std::filesystem::path(file).stem().string();
    for (const int workers : {1, 2})
      benchmark::RegisterBenchmark(("IndexBuild/" + name + "/workers:" + std::to_string(workers)).c_str(), indexBuild,
                                   file, workers)
          ->Unit(benchmark::kMillisecond)
          ->MeasureProcessCPUTime()
          ->UseRealTime()
          ->Iterations(1)
          ->Repetitions(3)
          ->ReportAggregatesOnly(false);
    benchmark::RegisterBenchmark(("SecondEnvironment/" + name).c_str(), secondEnvironment, file)
        ->Unit(benchmark::kMillisecond)
        ->MeasureProcessCPUTime()
        ->UseRealTime();
  }
  int count = static_cast<int>(arguments.size());
  benchmark::Initialize(&count, arguments.data());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
