// Coverage planning up to the choice of views for the full bridge soffit (every downward face
// of the superstructure: deck underside between and outside the girders, girder bottoms,
// cross-frame bottoms; 1 mm/px, 70 % front and 60 % side overlap, the upward H20 wide camera of
// maps/coverage/bridge_soffit.yaml), in each mode, with the phase split as counters. The map
// index (about a second, once per map) is built outside the timed loop. docs/coverage.md, "Speed".

#include "analytic_maps.hpp"

#include "ceilplan/energy/paper_quad.hpp"
#include "ceilplan/environment/environment.hpp"
#include "ceilplan/mission/coverage_plan.hpp"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>

namespace {

using namespace ceilplan;

struct Bridge {
  environment::OccupancyMap map =
      environment::OccupancyMap::load(std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/bridge.bt");
  environment::Environment environment{map, testing::quad()};
  energy::EnergyModel energy{energy::paperQuadParameters()};
};

const Bridge& bridge() {
  static const Bridge scene;
  return scene;
}

mission::Camera upwardH20() {
  mission::Camera camera = mission::cameraPreset("zenmuse_h20_wide").camera;
  camera.gimbal_pitch_min_deg = -30.0;
  camera.gimbal_pitch_max_deg = 90.0;
  camera.mount_offset_m = Eigen::Vector3d(0.0, 0.0, 0.05);
  return camera;
}

mission::CoverageRegion fullSoffit() {
  mission::CoverageRegion region;
  region.name = "full_soffit";
  region.shape = mission::RegionShape::makeBox({-2.0, -5.5, 4.95}, {50.0, 5.5, 6.05});
  region.faces.down = true;
  region.gsd_mm_px = 1.0;
  region.overlap_front_pct = 70.0;
  region.overlap_side_pct = 60.0;
  region.max_incidence_deg = 45.0;
  return region;
}

void BM_FullBridgeSoffitViews(benchmark::State& state) {
  const bool ceiling = state.range(0) == 0;
  planner::CostModelOptions model_options;
  model_options.proximity_effects = ceiling;
  const planner::FlightCostModel model(bridge().environment, bridge().energy, model_options);
  mission::CoveragePlanOptions options;
  options.views.mode = ceiling ? mission::FlightMode::Ceiling : mission::FlightMode::Free;
  options.views.workers = 2;
  options.costs.workers = 2;
  mission::CoveragePlan plan;
  for (auto _ : state) plan = mission::planCoverage(bridge().environment, model, upwardH20(), {fullSoffit()}, options);
  const mission::RegionPlan& region = plan.regions.at(0);
  state.SetLabel(ceiling ? "ceiling" : "free");
  state.counters["area_m2"] = region.surface.area_m2;
  state.counters["unreachable_m2"] = region.unreachable_area_m2;
  state.counters["candidates"] = static_cast<double>(region.candidates);
  state.counters["photos"] = static_cast<double>(plan.photos.size());
  state.counters["charge_ah"] = plan.charge_estimate_ah;
  state.counters["passes"] = static_cast<double>(region.passes.passes.size());
  state.counters["pass_route_m"] = region.passes.route_m;
  state.counters["generic_route_m"] = region.passes.generic_route_m;
  state.counters["surfaces_s"] = plan.times.surfaces_s;
  state.counters["candidates_s"] = plan.times.candidates_s;
  state.counters["costs_s"] = plan.times.costs_s;
  state.counters["selection_s"] = plan.times.selection_s;
  state.counters["passes_s"] = plan.times.passes_s;
}
BENCHMARK(BM_FullBridgeSoffitViews)->Arg(0)->Arg(1)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

}  // namespace
