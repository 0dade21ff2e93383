// The tour's shared roadmap on the shipped bridge: building it for home and the 13 targets'
// viewpoints (every lattice node and edge checked and costed, two threads) and one Dijkstra
// search from a place to all the others, in ceiling and free mode.

#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/mission/planning_context.hpp"
#include "ceilplan/planner/flight_planner.hpp"

#include "ceilplan/mission/viewpoint.hpp"
#include "ceilplan/planner/lattice_roadmap.hpp"

#include <benchmark/benchmark.h>

#include <memory>

namespace {

using namespace ceilplan;

struct BridgeRoadmap {
  mission::Mission mission = io::readMission(std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/bridge.yaml");
  mission::PlanningContext setup{mission};
  mission::PlanningContext::Mode mode;
  std::unique_ptr<planner::FlightPlanner> planner;  // owns the objective
  std::vector<Eigen::Vector3d> places;

  explicit BridgeRoadmap(mission::FlightMode planning_mode) {
    mode = setup.mode(planning_mode);
    planner = std::make_unique<planner::FlightPlanner>(*mode.rules, *mode.model,
                                                       setup.objective(mission.home_m, mission.home_m));
    places.push_back(mission.home_m);
    mission::ViewpointOptions options;
    options.mode = planning_mode;
    options.min_ceiling_gap_m = setup.options().min_ceiling_gap_m + 0.01;
    options.standoff_m = setup.options().standoff_m;
    const environment::Environment& environment = setup.environment();
    for (mission::InspectionTarget target : mission.targets) {
      if (planning_mode == mission::FlightMode::Free) target.standoff_max_m = std::max(target.standoff_max_m, 3.0);
      places.push_back(mission::chooseViewpoint(target, environment, setup.energy(), options).position_m);
    }
  }
};

// The tour's settings: 0.4 m, two threads.
planner::LatticeSettings tourSettings() {
  planner::LatticeSettings settings;
  settings.workers = 2;
  return settings;
}

void roadmapBuild(benchmark::State& state, mission::FlightMode planning_mode) {
  BridgeRoadmap bridge(planning_mode);
  for (auto _ : state) {
    planner::LatticeRoadmap roadmap(bridge.planner->spaceInformation(), tourSettings());
    roadmap.build(bridge.planner->objective(), bridge.places);
    state.counters["nodes"] = static_cast<double>(roadmap.validNodeCount());
    state.counters["edges"] = static_cast<double>(roadmap.edgeCount());
    state.counters["MB"] = static_cast<double>(roadmap.memoryBytes()) / 1e6;
    const auto routes = roadmap.routesFrom(0);
    std::size_t reached = 0;
    for (const auto& route : routes) reached += route.has_value();
    state.counters["reached"] = static_cast<double>(reached);
  }
}

void roadmapSearch(benchmark::State& state, mission::FlightMode planning_mode) {
  BridgeRoadmap bridge(planning_mode);
  planner::LatticeRoadmap roadmap(bridge.planner->spaceInformation(), tourSettings());
  roadmap.build(bridge.planner->objective(), bridge.places);
  int from = 0;
  for (auto _ : state) {
    const auto routes = roadmap.routesFrom(from);
    benchmark::DoNotOptimize(routes.data());
    from = (from + 1) % static_cast<int>(bridge.places.size());
  }
}

BENCHMARK_CAPTURE(roadmapBuild, ceiling, mission::FlightMode::Ceiling)
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(roadmapBuild, free, mission::FlightMode::Free)
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(roadmapSearch, ceiling, mission::FlightMode::Ceiling)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(roadmapSearch, free, mission::FlightMode::Free)->Unit(benchmark::kMillisecond);

}  // namespace
