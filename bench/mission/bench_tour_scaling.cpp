// How a point tour's cost grows with its targets (issue 26, "per-target work that scales"):
// ceiling-mode tours of the shipped bridge with 20, 50, 100, 200 and 400 targets on the deck's
// underside, end to end as `ceilplan tour --no-export` runs them (the command's defaults, two
// threads), then the outputs written. Counters: the process's CPU seconds in each phase
// (TourTimes' *_cpu_s, every thread), in writing the outputs, and in all; the charge.
// docs/tours.md, "Speed", has the table and the fitted exponents.

#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/io/provenance.hpp"
#include "ceilplan/io/tour_files.hpp"
#include "ceilplan/mission/tour_planner.hpp"

#include <benchmark/benchmark.h>

#include <ctime>
#include <filesystem>
#include <string>
#include <utility>

namespace {

using namespace ceilplan;

double processCpuS() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// Offsets 0, 0.6, -0.6, 1.2, -1.2 m for index 0, 1, 2, 3, 4.
double gridOffset_m(int index) {
  const int step = (index + 1) / 2;
  return 0.6 * static_cast<double>(step) * (index % 2 == 1 ? 1.0 : -1.0);
}

// The bridge mission with `count` targets on the deck's underside (z = 6 m), spread over its 36
// panels (12 bays between cross-frames, 3 lanes between girders) and within each panel on a
// 5 x 3 grid 0.6 m apart, panel by panel: 20 targets lie in 20 panels, 400 fill them all.
mission::Mission deckTargets(int count) {
  mission::Mission mission = io::readMission(std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/bridge.yaml");
  mission.targets.clear();
  constexpr int kBays = 12, kLanes = 3, kPanels = kBays * kLanes;
  const double lanes_m[kLanes] = {0.0, 2.8, -2.8};
  for (int k = 0; k < count; ++k) {
    const int panel = k % kPanels, slot = k / kPanels;
    const int bay = panel % kBays, lane = panel / kBays;
    // Slot 0 at the panel's centre, then out along the bay and across the lane.
    const double along_m = gridOffset_m(slot % 5), across_m = gridOffset_m(slot / 5 % 3);
    mission::InspectionTarget target;
    target.name = "deck_" + std::to_string(k);
    target.point_m = Eigen::Vector3d(2.0 + 4.0 * bay + along_m, lanes_m[lane] + across_m, 6.0);
    target.dwell_s = 20.0;
    target.standoff_min_m = 0.3;
    target.standoff_max_m = 1.5;
    mission.targets.push_back(target);
  }
  return mission;
}

void BM_DeckTourScaling(benchmark::State& state) {
  const mission::Mission mission = deckTargets(static_cast<int>(state.range(0)));
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "ceilplan_bench_tour_scaling";
  for (auto _ : state) {
    const double start_s = processCpuS();
    const mission::PlanningContext context(mission);
    const double context_s = processCpuS() - start_s;
    const mission::TourResult tour = mission::planTour(mission, context, mission::FlightMode::Ceiling, {});
    const double write_start_s = processCpuS();
    io::writeTourDirectory(out, tour, mission, context.environment(), std::nullopt,
                           io::Provenance::of("bench_tour_scaling"));
    const double end_s = processCpuS();
    const mission::TourTimes& t = tour.times;
    const std::pair<const char*, double> counters[] = {{"cpu_s", end_s - start_s},
                                                       {"map_s", context_s},
                                                       {"stops_s", t.stops_cpu_s},
                                                       {"legs_s", t.legs_cpu_s},
                                                       {"order_s", t.order_cpu_s},
                                                       {"routing_s", t.routing_cpu_s},
                                                       {"refining_s", t.refining_cpu_s},
                                                       {"record_s", t.record_cpu_s},
                                                       {"write_s", end_s - write_start_s},
                                                       {"charge_ah", tour.plan.charge_ah},
                                                       {"sorties", static_cast<double>(tour.plan.sorties.size())}};
    for (const auto& [name, value] : counters) state.counters[name] = value;
  }
  std::filesystem::remove_all(out);
}
BENCHMARK(BM_DeckTourScaling)
    ->Arg(20)
    ->Arg(50)
    ->Arg(100)
    ->Arg(200)
    ->Arg(400)
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);

}  // namespace
