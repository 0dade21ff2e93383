// Gap, clearance and validity queries on the shipped bridge scene, against OctoMap's castRay
// (the naive way), and the cost of loading and indexing the largest shipped map.
//   build/bench/environment/bench_environment

#include "ceilplan/environment/environment.hpp"
#include "ceilplan/mission/vehicle.hpp"

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <random>
#include <vector>

namespace {

using namespace ceilplan::environment;

VehicleGeometry quad() {
  static const VehicleGeometry vehicle = ceilplan::mission::Vehicle::defaultQuad().geometry;
  return vehicle;
}

const OccupancyMap& bridgeMap() {
  static const OccupancyMap map = OccupancyMap::load(CEILPLAN_SOURCE_DIR "/maps/bridge.bt");
  return map;
}

const Environment& bridge() {
  static const Environment environment(bridgeMap(), quad());
  return environment;
}

// Body positions under and beside the deck, where a planner samples.
const std::vector<Eigen::Vector3d>& samples() {
  static const std::vector<Eigen::Vector3d> points = [] {
    std::mt19937 random(1);
    std::uniform_real_distribution<double> x(0.5, 47.5), y(-9.5, 9.5), z(0.5, 5.9);
    std::vector<Eigen::Vector3d> p(4096);
    for (auto& point : p) point = {x(random), y(random), z(random)};
    return p;
  }();
  return points;
}

void BM_CeilingGapSinglePoint(benchmark::State& state) {
  const Environment& environment = bridge();
  std::size_t n = 0;
  for (auto _ : state) {
    const double gap = environment.ceilingGapAt(samples()[n++ & 4095]);
    benchmark::DoNotOptimize(gap);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_CeilingGapSinglePoint);

// The naive way: one upward ray per point, ending at the hit voxel's centre (not its face).
void BM_CeilingGapSinglePointCastRay(benchmark::State& state) {
  const octomap::OcTree& tree = bridgeMap().tree();
  std::size_t n = 0;
  for (auto _ : state) {
    const Eigen::Vector3d& p = samples()[n++ & 4095];
    octomap::point3d end;
    const bool hit = tree.castRay(octomap::point3d(p.x(), p.y(), p.z()), octomap::point3d(0, 0, 1), end, false, 8.0);
    const double gap = hit ? end.z() - p.z() : -1.0;
    benchmark::DoNotOptimize(gap);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_CeilingGapSinglePointCastRay);

// All four rotor discs, exact area coverage.
void BM_CeilingGapVehicle(benchmark::State& state) {
  const Environment& environment = bridge();
  std::size_t n = 0;
  for (auto _ : state) {
    const SurfaceGaps gaps = environment.ceiling(samples()[n++ & 4095]);
    benchmark::DoNotOptimize(gaps.coverage);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_CeilingGapVehicle);

// Rotor discs straddling a girder's edge (y = -1.2 m) under the deck: the columns under each
// disc give different gaps, so every column's exact share of the disc is weighed.
void BM_CeilingGapVehicleAtEdges(benchmark::State& state) {
  const Environment& environment = bridge();
  std::size_t n = 0;
  for (auto _ : state) {
    const Eigen::Vector3d& p = samples()[n++ & 4095];
    const SurfaceGaps gaps = environment.ceiling({p.x(), -1.2 + 0.159, 4.7});
    benchmark::DoNotOptimize(gaps.coverage);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_CeilingGapVehicleAtEdges);

// The naive footprint: castRay on a 5 x 5 grid over each rotor disc (inside points only, 21 per
// disc). Argument 0: rays run to the top of the map, to find the nearest surface as
// Environment::ceiling does; argument 1: rays stop at the 4 R reach (coverage only).
void BM_CeilingGapVehicleCastRay(benchmark::State& state) {
  const bool reach_only = state.range(0) == 1;
  const octomap::OcTree& tree = bridgeMap().tree();
  const VehicleGeometry vehicle = quad();
  std::vector<Eigen::Vector2d> footprint;
  for (const auto& rotor : vehicle.rotor_positions_m)
    for (int i = -2; i <= 2; ++i)
      for (int j = -2; j <= 2; ++j) {
        const Eigen::Vector2d offset(i * vehicle.rotor_radius_m / 2.5, j * vehicle.rotor_radius_m / 2.5);
        if (offset.norm() <= vehicle.rotor_radius_m) footprint.push_back(rotor + offset);
      }
  std::size_t n = 0;
  for (auto _ : state) {
    const Eigen::Vector3d& p = samples()[n++ & 4095];
    int covered = 0;
    for (const auto& point : footprint) {
      octomap::point3d end;
      covered +=
          tree.castRay(octomap::point3d(p.x() + point.x(), p.y() + point.y(), p.z() + 0.03), octomap::point3d(0, 0, 1),
                       end, false, reach_only ? 4 * vehicle.rotor_radius_m : 7.0 - p.z());
    }
    benchmark::DoNotOptimize(covered);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_CeilingGapVehicleCastRay)->Arg(0)->Arg(1);

void BM_Clearance(benchmark::State& state) {
  const Environment& environment = bridge();
  std::size_t n = 0;
  for (auto _ : state) {
    const double clearance = environment.clearance_m(samples()[n++ & 4095]);
    benchmark::DoNotOptimize(clearance);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Clearance);

void BM_StateValidity(benchmark::State& state) {
  const Environment& environment = bridge();
  std::size_t n = 0;
  for (auto _ : state) {
    const bool valid = environment.isStateValid(samples()[n++ & 4095]);
    benchmark::DoNotOptimize(valid);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_StateValidity);

// Hugging the deck: the fast path never applies, the exact cylinder test always runs.
void BM_StateValidityUnderDeck(benchmark::State& state) {
  const Environment& environment = bridge();
  std::size_t n = 0;
  for (auto _ : state) {
    const Eigen::Vector3d p(6.0 + 0.01 * (n++ & 255), 0.0, 5.9);
    const bool valid = environment.isStateValid(p);
    benchmark::DoNotOptimize(valid);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_StateValidityUnderDeck);

// Load + index the largest shipped map (the warehouse and the bridge have the most voxels);
// reports the process's peak resident memory.
void BM_LoadAndIndex(benchmark::State& state, const char* file) {
  for (auto _ : state) {
    const OccupancyMap map = OccupancyMap::load(file);
    const Environment environment(map, quad());
    benchmark::DoNotOptimize(environment.grid().frame().voxelCount());
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  state.counters["peak_rss_MB"] = static_cast<double>(usage.ru_maxrss) / 1024.0;
}
BENCHMARK_CAPTURE(BM_LoadAndIndex, bridge, CEILPLAN_SOURCE_DIR "/maps/bridge.bt")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LoadAndIndex, warehouse, CEILPLAN_SOURCE_DIR "/maps/warehouse.bt")->Unit(benchmark::kMillisecond);

}  // namespace
