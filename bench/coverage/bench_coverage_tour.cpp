// Coverage tours end to end, as `ceilplan tour` plans them (mission::planTour): the views, the
// stops, the legs between near neighbours, the order, the sorties, the flight record, wear and
// duty, and the independent re-check of the photos flown, with the phase split as counters.
//   BM_FullBridgeSoffitTour/0 and /1: the full soffit of the shipped bridge (every downward face
//     of the superstructure, 1 mm/px, 70 % / 60 % overlap, the camera of
//     maps/coverage/bridge_soffit.yaml) in ceiling and free mode. Target: under 60 s.
//   BM_LongDeckSoffitTour/0 and /1: the soffit between the girders of a generated 200 m bridge
//     (ceilplan mapgen --scene bridge --bridge-length-m 200), same camera. Target: under 10 min.
//   BM_ViaductDeckTour/0 and /1: the same soffit of a generated 1 km viaduct (--bridge-length-m
//     1000), about 10,000 photos. Target: under 2 minutes and 4 GB.
//   BM_SoffitSplitScaling/GSD/0: the full soffit at GSD / 100 mm/px in ceiling mode, about 1,000
//     to 10,000 photos: the CPU time of the order-and-split phase (order_cpu_s) and of the split
//     within it (split_cpu_s) against the photos, whose exponents docs/tours.md ("Large tours")
//     fits; per_sortie is photos per sortie; tour_cpu_s is the whole tour's CPU time.
// Map loading and indexing (the PlanningContext) happen outside the timed loop. docs/coverage.md,
// "Speed".

#include "ceilplan/environment/scenes.hpp"
#include "ceilplan/environment/voxel_grid.hpp"
#include "ceilplan/io/coverage_output.hpp"
#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/mission/tour_planner.hpp"

#include <benchmark/benchmark.h>

#include <cstdint>
#include <ctime>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <utility>

namespace {

using namespace ceilplan;

mission::Mission soffitMission(const Eigen::Vector3d& min_m, const Eigen::Vector3d& max_m) {
  mission::Mission mission =
      io::readMission(std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/coverage/bridge_soffit.yaml");
  mission.surfaces.at(0).name = "soffit";
  mission.surfaces.at(0).shape = mission::RegionShape::makeBox(min_m, max_m);
  return mission;
}

void report(benchmark::State& state, const mission::TourResult& tour) {
  state.SetLabel(mission::flightModeName(tour.mode));
  const mission::RegionCoverageCheck& check = tour.coverage_check->regions.at(0);
  state.counters["photos"] = static_cast<double>(tour.photos.size());
  state.counters["sorties"] = static_cast<double>(tour.plan.sorties.size());
  state.counters["charge_ah"] = tour.plan.charge_ah;
  state.counters["route_m"] = io::routeLength_m(tour);
  state.counters["area_m2"] = check.area_m2;
  state.counters["covered_reachable_pct"] = 100.0 * check.coveredReachableShare();
  state.counters["unreachable_m2"] = check.unreachable_area_m2;
  state.counters["legs_stored"] = static_cast<double>(tour.legs.size());
  const mission::CoverageTimes& views = tour.coverage->times;
  state.counters["views_s"] = views.surfaces_s + views.candidates_s + views.costs_s;  // elements, candidates, prices
  state.counters["selection_s"] = views.selection_s + views.passes_s;                 // set cover and passes
  const mission::TourTimes& t = tour.times;
  state.counters["stops_s"] = t.stops_s;
  state.counters["legs_s"] = t.legs_s;
  state.counters["order_s"] = t.order_s;
  state.counters["order_cpu_s"] = t.order_cpu_s;
  state.counters["split_cpu_s"] = t.split_cpu_s;
  state.counters["routing_s"] = t.routing_s;
  state.counters["refining_s"] = t.refining_s;
  state.counters["record_s"] = t.record_s;
  state.counters["check_s"] = t.coverage_check_s;
  state.counters["rounds"] = t.rounds;
}

// Argument 0: ceiling mode, 1: free mode.
mission::FlightMode modeArgument(std::int64_t argument) {
  return argument == 0 ? mission::FlightMode::Ceiling : mission::FlightMode::Free;
}

void runTour(benchmark::State& state, const mission::Mission& mission, const mission::PlanningContext& context,
             mission::FlightMode mode) {
  mission::TourOptions options;
  mission::TourResult tour;
  // The process's CPU time, every thread: the benchmark's own CPU column counts the main thread only.
  const std::clock_t start = std::clock();
  for (auto _ : state) tour = mission::planTour(mission, context, mode, options);
  state.counters["tour_cpu_s"] = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  report(state, tour);
}

void BM_FullBridgeSoffitTour(benchmark::State& state) {
  static const mission::Mission mission = soffitMission({-2.0, -5.5, 4.95}, {50.0, 5.5, 6.05});
  static const mission::PlanningContext context(mission);
  runTour(state, mission, context, modeArgument(state.range(0)));
}
BENCHMARK(BM_FullBridgeSoffitTour)->Arg(0)->Arg(1)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

void BM_SoffitSplitScaling(benchmark::State& state) {
  static const mission::Mission full = soffitMission({-2.0, -5.5, 4.95}, {50.0, 5.5, 6.05});
  static const mission::PlanningContext context(full);
  mission::Mission mission = full;
  mission.surfaces.at(0).gsd_mm_px = static_cast<double>(state.range(0)) / 100.0;
  state.counters["gsd_mm_px"] = mission.surfaces.at(0).gsd_mm_px;
  runTour(state, mission, context, modeArgument(state.range(1)));
  state.counters["per_sortie"] = state.counters["photos"] / state.counters["sorties"];
}
BENCHMARK(BM_SoffitSplitScaling)
    ->ArgsProduct({{80, 55, 45, 38, 33, 30}, {0}})
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);

// The soffit between the girders of a generated bridge `length_m` long, in ceiling (0) or free
// (1) mode; the map generated and indexed once for both.
void runDeckTour(benchmark::State& state, double length_m) {
  static std::map<double, std::pair<mission::Mission, std::unique_ptr<mission::PlanningContext>>> decks;
  auto found = decks.find(length_m);
  if (found == decks.end()) {
    mission::Mission mission = soffitMission({0.0, -4.0, 5.95}, {length_m, 4.0, 6.05});
    environment::SceneOptions scene;
    scene.bridge_length_m = length_m;
    environment::OccupancyMap map(environment::toOcTree(environment::generateScene(environment::Scene::Bridge, scene)),
                                  "bridge " + std::to_string(static_cast<int>(length_m)) + " m (generated)");
    auto context =
        std::make_unique<mission::PlanningContext>(std::move(map), mission.vehicle, mission.battery, mission.planning);
    found = decks.emplace(length_m, std::make_pair(std::move(mission), std::move(context))).first;
  }
  runTour(state, found->second.first, *found->second.second, modeArgument(state.range(0)));
}

void BM_LongDeckSoffitTour(benchmark::State& state) { runDeckTour(state, 200.0); }
BENCHMARK(BM_LongDeckSoffitTour)->Arg(0)->Arg(1)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

void BM_ViaductDeckTour(benchmark::State& state) { runDeckTour(state, 1000.0); }
BENCHMARK(BM_ViaductDeckTour)->Arg(0)->Arg(1)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

}  // namespace
