// Where a route from home reaches (planner::ReachableSpace, what a tour floods before it chooses
// its stops): the flood from the mission's home at the tour's 0.4 m on two threads, and one
// reaches() query at each of the mission's targets' points moved 0.5 m off the surface. On the
// shipped bridge and geb079's corridor mission; more missions (e.g. the fine maps of
// scripts/bench-fine-maps) with CEILPLAN_REACH_MISSIONS=a.yaml:b.yaml.

#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/mission/planning_context.hpp"
#include "ceilplan/planner/lattice_settings.hpp"
#include "ceilplan/planner/reachable_space.hpp"

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace ceilplan;

void flood(benchmark::State& state, const std::filesystem::path& mission_file) {
  const mission::Mission mission = io::readMission(mission_file);
  const mission::PlanningContext context(mission);
  for (auto _ : state) {
    const planner::ReachableSpace space(context.baseRules(), mission.home_m, planner::kTourLatticeSpacing_m, 2);
    state.counters["reached_nodes"] = static_cast<double>(space.reachedNodeCount());
  }
  state.counters["known_Mvoxels"] = static_cast<double>(context.map().tree().getNumLeafNodes()) / 1e6;
}

void reachesQuery(benchmark::State& state, const std::filesystem::path& mission_file) {
  const mission::Mission mission = io::readMission(mission_file);
  const mission::PlanningContext context(mission);
  const planner::ReachableSpace space(context.baseRules(), mission.home_m, planner::kTourLatticeSpacing_m, 2);
  std::size_t k = 0, reached = 0, asked = 0;
  for (auto _ : state) {
    const Eigen::Vector3d& point = mission.targets[k++ % mission.targets.size()].point_m;
    const Eigen::Vector3d off_surface = point + 0.5 * (mission.home_m - point).normalized();
    reached += space.reaches(off_surface);
    ++asked;
  }
  state.counters["reached_share"] = asked ? static_cast<double>(reached) / asked : 0.0;
}

void registerMission(const std::string& label, const std::filesystem::path& file) {
  benchmark::RegisterBenchmark(("flood/" + label).c_str(), flood, file)
      ->Iterations(1)
      ->UseRealTime()
      ->Unit(benchmark::kSecond);
  benchmark::RegisterBenchmark(("reaches/" + label).c_str(), reachesQuery, file)->Unit(benchmark::kMicrosecond);
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path maps = std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps";
  registerMission("bridge", maps / "bridge.yaml");
  registerMission("geb079_corridor", maps / "real/geb079_corridor.yaml");
  if (const char* extra = std::getenv("CEILPLAN_REACH_MISSIONS")) {
    std::stringstream list(extra);
    for (std::string file; std::getline(list, file, ':');)
      if (!file.empty()) registerMission(std::filesystem::path(file).stem().string(), file);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
