// The tour's shared roadmap on the shipped bridge: building it for home and the 13 targets'
// viewpoints (every lattice node and edge checked and costed, two threads) and one Dijkstra
// search from a place to all the others, in ceiling and free mode.

#include "mission_file.hpp"
#include "planning_setup.hpp"
#include "tour_run.hpp"

#include "ceilplan/planner/lattice_roadmap.hpp"
#include "ceilplan/mission/viewpoint.hpp"

#include <benchmark/benchmark.h>

#include <memory>

namespace {

using namespace ceilplan;

struct BridgeRoadmap {
  app::MissionFile mission = app::readMissionFile(std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/bridge.yaml");
  app::PlanningSetup setup{app::planningArguments(mission)};
  app::PlanningSetup::Mode mode;
  std::unique_ptr<planner::FlightPlanner> planner;  // owns the objective
  std::vector<Eigen::Vector3d> places;

  explicit BridgeRoadmap(app::PlanningMode planning_mode) {
    mode = setup.mode(planning_mode, mission.home_m, mission.home_m);
    planner = std::make_unique<planner::FlightPlanner>(*mode.rules, *mode.model,
                                                       setup.objective(mission.home_m, mission.home_m));
    places.push_back(mission.home_m);
    mission::ViewpointOptions options;
    options.mode = planning_mode == app::PlanningMode::Ceiling ? mission::ViewpointMode::Ceiling : mission::ViewpointMode::Free;
    options.min_ceiling_gap_m = setup.arguments().min_ceiling_gap_m + 0.01;
    options.standoff_m = setup.arguments().standoff_m;
    const environment::Environment& environment = setup.environment();
    for (mission::InspectionTarget target : mission.targets) {
      if (planning_mode == app::PlanningMode::Free) target.standoff_max_m = std::max(target.standoff_max_m, 3.0);
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

void roadmapBuild(benchmark::State& state, app::PlanningMode planning_mode) {
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

void roadmapSearch(benchmark::State& state, app::PlanningMode planning_mode) {
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

BENCHMARK_CAPTURE(roadmapBuild, ceiling, app::PlanningMode::Ceiling)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(roadmapBuild, free, app::PlanningMode::Free)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(roadmapSearch, ceiling, app::PlanningMode::Ceiling)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(roadmapSearch, free, app::PlanningMode::Free)->Unit(benchmark::kMillisecond);

}  // namespace
