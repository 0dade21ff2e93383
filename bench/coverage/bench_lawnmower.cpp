// The peer baseline of coverage tours: the lawnmower a pilot would fly with QGroundControl's
// Survey pattern, on the regions of a shipped coverage mission, flown through ceilplan's own
// energy model and re-checked by its own independent coverage check (checkCoverage).
//   Lanes along the region's long axis, one lane spacing apart: the footprint's width x (1 - side
//   overlap); photos one trigger distance apart along a lane: its height x (1 - front overlap),
//   as QGroundControl's Survey derives them (docs/coverage.md, "The lawnmower baseline").
//   The camera looks straight up (normal to a soffit) from the distance where the required GSD
//   holds at the corners of the central part of the image that the check counts as covered.
//   Lanes are flown boustrophedon; a pose the safety rules refuse is dropped, as a pilot would
//   move a photo off a structure (counted as `skipped`).
//   Legs between photos are straight where the dense re-check passes, else routed; the legs out
//   of home and back are routed in the mode; all at the model's speeds, a hover stop per photo.
//   Sorties may start at each lane's first photo and are split by planSorties, as a tour's are.
//   BM_Lawnmower/MISSION/MODE/TOUR/GSD: MISSION 0 bridge soffit, 1 tunnel crown, 2 warehouse roof
//   (maps/coverage/*.yaml), 3 the full bridge soffit (bridge_soffit.yaml with its box widened to every
//   downward face of the superstructure, as bench_coverage_tour's BM_FullBridgeSoffitTour); MODE 0 ceiling, 1 free;
//   TOUR 1 also plans ceilplan's own tour of the mission in that mode and reports its figures beside the lawnmower's
//   (tour_*); every region at GSD / 100 mm/px.

#include "ceilplan/io/coverage_output.hpp"
#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/mission/coverage_check.hpp"
#include "ceilplan/mission/route_planning.hpp"
#include "ceilplan/mission/tour_planner.hpp"
#include "ceilplan/mission/viewpoint.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>

namespace {

using namespace ceilplan;

const char* const kMissions[] = {"bridge_soffit", "tunnel_crown", "warehouse_ceiling", "bridge_soffit"};
constexpr int kFullSoffit = 3;  // kMissions' bridge_soffit with the full soffit's box

struct Lawnmower {
  std::vector<mission::CameraPose> photos;  // flying order
  std::vector<int> lane_starts;             // positions in `photos` where a lane begins
  int skipped = 0;                          // poses the safety rules refuse
};

// The photos of one down-facing region: lanes along its long horizontal axis.
void addRegionPhotos(const mission::Camera& camera, const mission::CoverageRegion& region,
                     const mission::RegionSurface& surface, const mission::PlanningContext& context, Lawnmower& out) {
  const double a = region.widthShare() * camera.halfWidthTan();  // the covered part's corner, as tangents
  const double b = region.heightShare() * camera.halfHeightTan();
  // gsd_mm_px grows with the line of sight and 1 / cos(incidence): both (1 + a^2 + b^2)^(1/2) at a corner.
  const double distance_m = camera.distanceForGsd_m(region.gsd_mm_px) / (1.0 + a * a + b * b);
  const Eigen::Vector2d footprint_m = camera.footprint_m(distance_m);
  const double lane_spacing_m = footprint_m.x() * region.widthShare();
  const double trigger_m = footprint_m.y() * region.heightShare();

  Eigen::AlignedBox2d bounds;
  for (const environment::SurfaceElement& e : surface.elements) bounds.extend(e.centre_m.head<2>());
  const bool along_x = bounds.sizes().x() >= bounds.sizes().y();
  const int along = along_x ? 0 : 1, across = 1 - along;
  const double yaw_deg = along_x ? 90.0 : 0.0;  // clockwise from north (+y): the image height runs along the lane
  const auto count = [](double extent_m, double step_m) {
    return std::max(1, static_cast<int>(std::ceil(extent_m / step_m - 1e-9)));
  };
  const int lanes = count(bounds.sizes()[across], lane_spacing_m);
  const int shots = count(bounds.sizes()[along], trigger_m);
  for (int lane = 0; lane < lanes; ++lane) {
    out.lane_starts.push_back(static_cast<int>(out.photos.size()));
    for (int i = 0; i < shots; ++i) {
      const int k = lane % 2 == 0 ? i : shots - 1 - i;  // boustrophedon
      Eigen::Vector2d centre;
      centre[across] = bounds.min()[across] + (lane + 0.5) * lane_spacing_m;
      centre[along] = bounds.min()[along] + (k + 0.5) * trigger_m;
      // The highest element over the covered part sets the height: the GSD holds on all of it
      // (a flat survey altitude; a curved surface's lower parts come closer and are seen smaller).
      double surface_z_m = -std::numeric_limits<double>::infinity();
      for (const environment::SurfaceElement& e : surface.elements) {
        const Eigen::Vector2d offset = e.centre_m.head<2>() - centre;
        if (std::abs(offset[across]) <= 0.5 * lane_spacing_m && std::abs(offset[along]) <= 0.5 * trigger_m)
          surface_z_m = std::max(surface_z_m, e.centre_m.z());
      }
      if (!std::isfinite(surface_z_m)) continue;  // no surface over this photo: QGC would shoot it, nothing to see
      mission::CameraPose pose;
      pose.yaw_deg = yaw_deg;
      pose.gimbal_pitch_deg = 90.0;
      pose.body_m = Eigen::Vector3d(centre.x(), centre.y(), surface_z_m - distance_m);
      pose.body_m -= mission::cameraPosition(camera, pose.body_m, yaw_deg) - pose.body_m;
      if (!context.baseRules().isStateValid(pose.body_m)) {
        ++out.skipped;
        continue;
      }
      out.photos.push_back(pose);
    }
  }
}

mission::LegCost legCost(const planner::PathEvaluation& evaluation) {
  return {evaluation.charge_ah, evaluation.duration_s, evaluation.mean_current_a, {}, {}};
}

struct Flown {
  mission::SortiePlan plan;
  double route_m = 0.0;
};

// Flies the photos in their order from home, sorties starting at lane starts.
Flown fly(const mission::Mission& mission, const mission::PlanningContext& context, mission::FlightMode mode,
          const Lawnmower& mower) {
  const int places = static_cast<int>(mower.photos.size()) + 1;
  std::vector<Eigen::Vector3d> place_m{mission.home_m};
  for (const mission::CameraPose& pose : mower.photos) place_m.push_back(pose.body_m);
  std::map<std::pair<int, int>, planner::PathEvaluation> legs;
  const auto leg = [&](int from, int to) {
    std::vector<Eigen::Vector3d> waypoints{place_m[from], place_m[to]};
    if (from == 0 || to == 0 || context.baseRules().checkPathDensely(waypoints)) {
      planner::PlanRequest request;
      request.start_m = place_m[from];
      request.goal_m = place_m[to];
      request.planner = planner::referencePlannerName();           // the lattice A*, deterministic
      request.lattice.spacing_m = planner::kTourLatticeSpacing_m;  // the tour roadmap's spacing
      waypoints = mission::planRoute(context, mode, request).plan.waypoints;
    }
    legs[{from, to}] =
        planner::evaluatePath(context.fullModel(), context.battery().pack, context.battery().start_soc, waypoints);
  };
  mission::TourCosts costs;
  costs.names.assign(static_cast<std::size_t>(places), "photo");
  costs.names[0] = "home";
  costs.legs = mission::PairTable<mission::LegCost>(places);
  costs.dwells.resize(static_cast<std::size_t>(places));
  for (int k = 1; k < places; ++k) {
    leg(k == 1 ? 0 : k - 1, k);
    const double stop_s = mission.camera->stopPerPhoto_s();
    const double hover_a =
        mission::hoverCurrentA(context.environment(), context.energy(), place_m[k], context.battery().start_soc);
    mission::Dwell& dwell = costs.dwells[static_cast<std::size_t>(k)];
    dwell.duration_s = stop_s;
    dwell.current_a = hover_a;
  }
  mission::SortieOptions options;
  for (const int start : mower.lane_starts) {
    if (start >= places - 1) continue;
    options.split_points.push_back(start);
    if (start > 0) leg(0, start + 1), leg(start, 0);
  }
  leg(places - 1, 0);
  for (const auto& [pair, evaluation] : legs) costs.legs(pair.first, pair.second) = legCost(evaluation);
  std::vector<int> order;
  for (int k = 1; k < places; ++k) order.push_back(k);
  Flown flown;
  flown.plan = mission::planSorties(costs, order, context.battery(), options);
  for (const mission::Sortie& sortie : flown.plan.sorties)
    for (const mission::SortieLeg& l : sortie.legs) flown.route_m += legs.at({l.from, l.to}).length_m;
  return flown;
}

void BM_Lawnmower(benchmark::State& state) {
  const std::string name = kMissions[state.range(0)];
  const mission::FlightMode mode = state.range(1) == 0 ? mission::FlightMode::Ceiling : mission::FlightMode::Free;
  mission::Mission mission =
      io::readMission(std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/coverage" / (name + ".yaml"));
  if (state.range(0) == kFullSoffit)
    mission.surfaces.at(0).shape = mission::RegionShape::makeBox({-2.0, -5.5, 4.95}, {50.0, 5.5, 6.05});
  for (mission::CoverageRegion& region : mission.surfaces)
    region.gsd_mm_px = static_cast<double>(state.range(3)) / 100.0;
  const mission::PlanningContext context(mission);
  const mission::Camera& camera = *mission.camera;
  Lawnmower mower;
  std::vector<mission::RegionSurface> surfaces;
  std::vector<std::vector<std::uint8_t>> reachable;
  Flown flown;
  mission::CoverageCheck check;
  double fly_s = 0.0;
  for (auto _ : state) {
    mower = {};
    surfaces.clear();
    reachable.clear();
    for (const mission::CoverageRegion& region : mission.surfaces) {
      surfaces.push_back(mission::extractRegionSurface(context.environment().grid(), region.shape, region.faces,
                                                       "surface region '" + region.name + "'"));
      reachable.emplace_back(surfaces.back().elements.size(), 1);  // the lawnmower knows none: all counted
      addRegionPhotos(camera, region, surfaces.back(), context, mower);
    }
    const auto t0 = std::chrono::steady_clock::now();
    flown = fly(mission, context, mode, mower);
    const auto t1 = std::chrono::steady_clock::now();
    fly_s = std::chrono::duration<double>(t1 - t0).count();
    check = mission::checkCoverage(context.map().tree(), camera, mission.surfaces, surfaces, reachable, mower.photos);
  }
  state.SetLabel((state.range(0) == kFullSoffit ? "full_" + name : name) + " " + mission::flightModeName(mode));
  state.counters["gsd_mm_px"] = mission.surfaces.at(0).gsd_mm_px;
  // Sharp anywhere: at or below the GSD somewhere in a frame, overlap aside; what covered_pct
  // lacks beyond it, the lanes' covered parts left between them.
  double area_m2 = 0.0, covered_m2 = 0.0, sharp_m2 = 0.0;
  for (std::size_t r = 0; r < check.regions.size(); ++r) {
    area_m2 += check.regions[r].area_m2;
    covered_m2 += check.regions[r].covered_area_m2;
    const double gsd_mm_px = mission.surfaces[r].gsd_mm_px;
    for (std::size_t e = 0; e < surfaces[r].elements.size(); ++e)
      if (check.regions[r].best_gsd_mm_px[e] <= gsd_mm_px) sharp_m2 += surfaces[r].elements[e].area_m2;
  }
  state.counters["fly_s"] = fly_s;
  state.counters["photos"] = static_cast<double>(mower.photos.size());
  state.counters["skipped"] = mower.skipped;
  state.counters["lanes"] = static_cast<double>(mower.lane_starts.size());
  state.counters["sorties"] = static_cast<double>(flown.plan.sorties.size());
  state.counters["route_m"] = flown.route_m;
  state.counters["charge_ah"] = flown.plan.charge_ah;
  state.counters["covered_pct"] = 100.0 * covered_m2 / area_m2;
  state.counters["sharp_anywhere_pct"] = 100.0 * sharp_m2 / area_m2;
  if (state.range(2) == 0) return;
  mission::TourOptions options;
  const mission::TourResult tour = mission::planTour(mission, context, mode, options);
  double tour_covered_m2 = 0.0, tour_area_m2 = 0.0, tour_reachable_covered_m2 = 0.0, tour_reachable_m2 = 0.0;
  for (const mission::RegionCoverageCheck& region : tour.coverage_check->regions) {
    tour_area_m2 += region.area_m2;
    tour_covered_m2 += region.covered_area_m2;
    tour_reachable_m2 += region.reachable_area_m2;
    tour_reachable_covered_m2 += region.covered_reachable_area_m2;
  }
  state.counters["tour_photos"] = static_cast<double>(tour.photos.size());
  state.counters["tour_sorties"] = static_cast<double>(tour.plan.sorties.size());
  state.counters["tour_route_m"] = io::routeLength_m(tour);
  state.counters["tour_charge_ah"] = tour.plan.charge_ah;
  state.counters["tour_covered_pct"] = 100.0 * tour_covered_m2 / tour_area_m2;
  state.counters["tour_reachable_covered_pct"] = 100.0 * tour_reachable_covered_m2 / tour_reachable_m2;
}
BENCHMARK(BM_Lawnmower)
    ->ArgsProduct({{0, 1, 2, kFullSoffit}, {0, 1}, {0, 1}, {200, 100, 50, 30}})
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);

}  // namespace
