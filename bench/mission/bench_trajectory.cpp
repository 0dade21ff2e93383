// Trajectory time scaling: a meandering route of N waypoints (gentle bends, climbs, a dwell every
// tenth waypoint) at 20 Hz, every corner blend accepted (the re-check's own cost is the map's).

#include "ceilplan/mission/trajectory.hpp"

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

ceilplan::mission::SortieRoute meander(int waypoints) {
  ceilplan::mission::SortieRoute route;
  route.home_m = {0, 0, 0.5};
  for (int k = 0; k < waypoints; ++k) {
    const double x = 2.0 * k, y = 3.0 * std::sin(0.3 * k), z = 3.0 + std::sin(0.1 * k);
    route.waypoints.emplace_back(Eigen::Vector3d(x, y, z), k % 10 == 9 ? 5.0 : 0.0);
  }
  route.waypoints.emplace_back(Eigen::Vector3d(2.0 * waypoints, 0, 0.5));
  return route;
}

void BM_TimeScale(benchmark::State& state) {
  const ceilplan::mission::SortieRoute route = meander(static_cast<int>(state.range(0)));
  ceilplan::mission::TrajectoryOptions options;
  options.path_is_safe = [](const std::vector<Eigen::Vector3d>&) { return true; };
  std::size_t setpoints = 0;
  for (auto _ : state) {
    const auto trajectory = ceilplan::mission::timeScale(route, {}, options);
    setpoints = trajectory.setpoints.size();
    benchmark::DoNotOptimize(setpoints);
  }
  state.counters["setpoints"] = static_cast<double>(setpoints);
}
BENCHMARK(BM_TimeScale)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
