// The planner's hot paths on the shipped scenes: map conditions at a point, the motion cost
// of a 1 m motion under the bridge deck and in free air, one lattice A* query.
//   build/bench/planner/bench_planner
// The quality study (planners against the lattice reference) is bench/planner/quality-study.

#include "ceilplan/mission/vehicle.hpp"
#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/lattice_planner.hpp"
#include "ceilplan/planner/ompl_state.hpp"

#include <ompl/base/ProblemDefinition.h>

#include <benchmark/benchmark.h>

namespace {

using namespace ceilplan;

struct Scene {
  explicit Scene(const char* file)
      : map(environment::OccupancyMap::load(file)),
        environment(map, mission::Vehicle::defaultQuad().geometry),
        energy(mission::Vehicle::defaultQuad().energy),
        model(environment, energy, planner::CostModelOptions{}),
        rules(environment, 0.05) {}
  environment::OccupancyMap map;
  environment::Environment environment;
  energy::EnergyModel energy;
  planner::FlightCostModel model;
  planner::SafetyRules rules;
};

Scene& bridge() {
  static Scene scene(CEILPLAN_SOURCE_DIR "/maps/bridge.bt");
  return scene;
}

Scene& warehouse() {
  static Scene scene(CEILPLAN_SOURCE_DIR "/maps/warehouse.bt");
  return scene;
}

// Runs `query(x)` with x sweeping the bridge's bays in 13 mm steps.
template <typename Query>
void sweep(benchmark::State& state, Query&& query) {
  double x = 6.0;
  for (auto _ : state) {
    const auto result = query(x);
    benchmark::DoNotOptimize(result);
    x = x > 26.0 ? 6.0 : x + 0.013;
  }
}

void BM_ConditionsUnderDeck(benchmark::State& state) {
  sweep(state, [](double x) { return bridge().model.conditionsAt({x, 0.7, 5.85}); });
}
BENCHMARK(BM_ConditionsUnderDeck);

void BM_MotionCost1mUnderDeck(benchmark::State& state) {
  sweep(state, [](double x) { return bridge().model.integrate({x, 0.7, 5.85}, {x + 1.0, 0.7, 5.85}); });
}
BENCHMARK(BM_MotionCost1mUnderDeck);

void BM_MotionCost1mFreeAir(benchmark::State& state) {
  sweep(state, [](double x) { return bridge().model.integrate({x, -7.0, 3.0}, {x + 1.0, -7.0, 3.0}); });
}
BENCHMARK(BM_MotionCost1mFreeAir);

void BM_MotionValidity1mUnderDeck(benchmark::State& state) {
  sweep(state, [](double x) { return bridge().rules.isMotionValid({x, 0.7, 5.85}, {x + 1.0, 0.7, 5.85}); });
}
BENCHMARK(BM_MotionValidity1mUnderDeck);

// The warehouse query of the quality study, lattice spacing 0.2 m (docs/planner.md).
void BM_LatticeWarehouse(benchmark::State& state) {
  const Scene& scene = warehouse();
  planner::seedOmpl(1);
  const planner::FlightPlanner flight_planner(scene.rules, scene.model, planner::ObjectiveChoice{});
  const ompl::base::SpaceInformationPtr& si = flight_planner.spaceInformation();
  for (auto _ : state) {
    planner::LatticeSettings settings;
    settings.spacing_m = 0.2;
    planner::LatticePlanner lattice(si, settings);
    auto definition = std::make_shared<ompl::base::ProblemDefinition>(si);
    ompl::base::ScopedState<> start(si), goal(si);
    planner::setPosition(start.get(), {7.5, 6, 7.9});
    planner::setPosition(goal.get(), {22.5, 14, 7.9});
    definition->setStartAndGoalStates(start, goal, 1e-6);
    definition->setOptimizationObjective(flight_planner.objectivePtr());
    lattice.setProblemDefinition(definition);
    const ompl::base::PlannerStatus status = lattice.solve(600.0);
    state.counters["expansions"] = static_cast<double>(lattice.expansions());
    state.counters["solved"] = status == ompl::base::PlannerStatus::EXACT_SOLUTION;
  }
}
BENCHMARK(BM_LatticeWarehouse)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
