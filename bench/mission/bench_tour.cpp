// A 20-target inspection tour on the shipped bridge, end to end as `ceilplan tour --mode
// ceiling` runs it: map indexing, viewpoints, 210 legs planned on two threads (the shared roadmap, the
// command's defaults), order, sorties, wear and duty projection. The bridge mission's 13
// targets plus 7 more deck bays. Target: under 60 s on the 2-core machine.

#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/mission/tour_planner.hpp"
#include "ceilplan/planner/flight_planner.hpp"

#include <benchmark/benchmark.h>

namespace {

using namespace ceilplan;

mission::Mission twentyTargetBridge() {
  mission::Mission mission = io::readMission(std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/bridge.yaml");
  const double bays[][2] = {{10.0, 0.0}, {18.0, 0.0}, {26.0, 0.0}, {34.0, 0.0}, {42.0, 0.0}, {18.0, -2.8}, {42.0, 2.8}};
  for (const auto& bay : bays) {
    mission::InspectionTarget target;
    target.name = "extra_deck_bay_" + std::to_string(static_cast<int>(bay[0])) +
                  (bay[1] > 0   ? "_north"
                   : bay[1] < 0 ? "_south"
                                : "");
    target.point_m = Eigen::Vector3d(bay[0], bay[1], 6.0);
    target.dwell_s = 20.0;
    mission.targets.push_back(target);
  }
  return mission;
}

void BM_TwentyTargetBridgeTour(benchmark::State& state) {
  const mission::Mission mission = twentyTargetBridge();
  planner::seedOmpl(1);
  mission::TourOptions options;
  for (auto _ : state) {
    const mission::PlanningContext context(mission);
    const mission::TourResult tour = mission::planTour(mission, context, mission::FlightMode::Ceiling, options);
    state.counters["targets"] = static_cast<double>(tour.stops.size());
    state.counters["sorties"] = static_cast<double>(tour.plan.sorties.size());
    state.counters["charge_ah"] = tour.plan.charge_ah;
    const double charge_ah = tour.plan.charge_ah;
    benchmark::DoNotOptimize(charge_ah);
  }
}
BENCHMARK(BM_TwentyTargetBridgeTour)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

}  // namespace
