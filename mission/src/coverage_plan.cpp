#include "ceilplan/mission/coverage_plan.hpp"

#include <algorithm>
#include <chrono>

namespace ceilplan::mission {
namespace {

constexpr double kLaneDistanceShare = 0.8;  // views this close to the farthest level form the lanes

class Stopwatch {
 public:
  double lap_s() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - start_).count();
    start_ = now;
    return seconds;
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace

std::vector<Eigen::Vector3d> RegionPlan::unreachableCentres() const {
  std::vector<Eigen::Vector3d> centres;
  for (std::size_t e = 0; e < surface.elements.size(); ++e)
    if (!reachable[e]) centres.push_back(surface.elements[e].centre_m);
  return centres;
}

PhotoRow photoRow(const CoveragePlan& plan, std::size_t k, int index) {
  const PlannedPhoto& photo = plan.photos.at(k);
  PhotoRow row;
  row.index = index;
  row.camera_m = photo.camera_m;
  row.yaw_deg = photo.pose.yaw_deg;
  row.gimbal_pitch_deg = photo.pose.gimbal_pitch_deg;
  row.distance_m = photo.distance_m;
  row.gsd_mm_px = photo.gsd_mm_px;
  row.region = plan.regions.at(static_cast<std::size_t>(photo.region)).region.name;
  return row;
}

std::vector<PhotoRow> photoRows(const CoveragePlan& plan) {
  std::vector<PhotoRow> rows;
  for (std::size_t k = 0; k < plan.photos.size(); ++k) rows.push_back(photoRow(plan, k, static_cast<int>(k + 1)));
  return rows;
}

CoveragePlan planCoverage(const environment::Environment& environment, const planner::FlightCostModel& cost_model,
                          const Camera& camera, const std::vector<CoverageRegion>& regions,
                          const CoveragePlanOptions& options) {
  // Everything that can be checked without the map, before any map work.
  camera.validate();
  if (regions.empty()) throw ceilplan::InputError("a coverage plan needs at least one surface region");
  for (const CoverageRegion& region : regions) {
    region.validate();
    checkCameraReaches(camera, region);
  }
  if (&cost_model.environment() != &environment)
    throw ceilplan::InputError("the coverage cost model must be built on the environment the views are planned in");

  CoveragePlan plan;
  Stopwatch clock;
  for (const CoverageRegion& region : regions) {
    RegionPlan result;
    result.region = region;
    result.surface =
        extractRegionSurface(environment.grid(), region.shape, region.faces, "surface region '" + region.name + "'");
    result.heading_deg = regionHeading(result.surface);
    plan.regions.push_back(std::move(result));
  }
  plan.times.surfaces_s += clock.lap_s();

  for (std::size_t r = 0; r < plan.regions.size(); ++r) {
    RegionPlan& result = plan.regions[r];
    const CoverageRegion& region = result.region;
    ViewGenerationOptions view_options = options.views;
    if (options.progress)
      view_options.progress = [&](double share) { options.progress("views of " + region.name, share); };
    const CandidateViews candidates = generateCandidateViews(environment, camera, region, result.surface, view_options);
    result.reachable = candidates.reachable;
    result.generation = candidates.stats;
    result.candidates = candidates.size();
    for (std::size_t e = 0; e < result.surface.elements.size(); ++e)
      (result.reachable[e] ? result.reachable_area_m2 : result.unreachable_area_m2) +=
          result.surface.elements[e].area_m2;
    plan.times.candidates_s += clock.lap_s();

    const std::vector<ViewCost> costs = viewCosts(cost_model, camera, candidates, options.costs);
    std::vector<double> charge(costs.size()), area(result.surface.elements.size());
    for (std::size_t v = 0; v < costs.size(); ++v) charge[v] = costs[v].charge_ah;
    for (std::size_t e = 0; e < area.size(); ++e) area[e] = result.surface.elements[e].area_m2;
    plan.times.costs_s += clock.lap_s();

    result.selection = chooseViews(candidates, area, charge, options.selection);
    plan.charge_estimate_ah += result.selection.cost;
    plan.times.selection_s += clock.lap_s();

    // The chosen views as photos, then ordered into passes.
    std::vector<PlannedPhoto> chosen;
    std::vector<CameraPose> poses;
    std::vector<Eigen::Vector3d> cameras;
    for (const std::uint32_t v : result.selection.chosen) {
      PlannedPhoto photo;
      photo.pose = candidates.poses[v];
      photo.camera_m = cameraPosition(camera, photo.pose.body_m, photo.pose.yaw_deg);
      photo.region = static_cast<int>(r);
      photo.covered_area_m2 = candidates.summaries[v].area_m2;
      photo.distance_m = candidates.summaries[v].distance_m;
      photo.gsd_mm_px = candidates.summaries[v].gsd_mm_px;
      photo.hover_current_a = costs[v].hover_current_a;
      photo.stop_s = costs[v].stop_s;
      photo.max_speed_m_s = costs[v].speed_m_s;
      poses.push_back(photo.pose);
      cameras.push_back(photo.camera_m);
      chosen.push_back(photo);
    }
    // Lanes from the views near the farthest distance level (the regular tiling); the rest are
    // inserted where they cost the route least.
    const double far_m = distanceLevels(camera, region, 1).front();
    std::vector<std::uint8_t> in_lanes;
    in_lanes.reserve(chosen.size());
    for (const PlannedPhoto& photo : chosen) in_lanes.push_back(photo.distance_m >= kLaneDistanceShare * far_m ? 1 : 0);
    const double lane_width_m = 2.0 * far_m * camera.halfWidthTan() * region.widthShare();
    result.passes = orderIntoPasses(poses, cameras, result.heading_deg, lane_width_m, in_lanes);
    for (std::size_t p = 0; p < result.passes.passes.size(); ++p)
      for (std::uint32_t& view : result.passes.passes[p].views) {
        PlannedPhoto photo = chosen[view];
        photo.pass = static_cast<int>(p);
        view = static_cast<std::uint32_t>(plan.photos.size());
        result.photos.push_back(view);
        plan.photos.push_back(photo);
      }
    plan.times.passes_s += clock.lap_s();
  }
  return plan;
}

}  // namespace ceilplan::mission
