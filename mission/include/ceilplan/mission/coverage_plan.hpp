#pragma once
// Coverage planning up to the choice of views: for each region, its surface elements, candidate
// views, the wear-aware set cover, and the chosen views ordered into passes. The result is what
// a tour flies: photo stops (fixed poses with a dwell) grouped into passes, plus the elements
// no valid pose can see. docs/coverage.md.

#include "ceilplan/environment/environment.hpp"
#include "ceilplan/mission/camera.hpp"
#include "ceilplan/mission/coverage_passes.hpp"
#include "ceilplan/mission/coverage_region.hpp"
#include "ceilplan/mission/coverage_views.hpp"
#include "ceilplan/mission/region_surface.hpp"
#include "ceilplan/mission/view_selection.hpp"
#include "ceilplan/planner/flight_cost_model.hpp"
#include "ceilplan/core/error.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace ceilplan::mission {

// One photo the plan takes: where, how, and what it delivers.
struct PlannedPhoto {
  CameraPose pose;
  Eigen::Vector3d camera_m = Eigen::Vector3d::Zero();
  int region = 0;               // index into CoveragePlan::regions
  int pass = 0;                 // index into that region's passes
  double distance_m = 0.0;      // area-weighted mean over the elements it covers
  double gsd_mm_px = 0.0;       // likewise
  double covered_area_m2 = 0.0; // of the region, in the covered part of the image
  double hover_current_a = 0.0; // at the pose, under the mode's cost model
  double stop_s = 0.0;          // hover here this long (0 when shooting on the move)
  double max_speed_m_s = 0.0;   // flying on to the next photo: the transit speed, on the move capped by the blur limit and photo interval
};

struct RegionPlan {
  CoverageRegion region;
  RegionSurface surface;
  std::vector<std::uint8_t> reachable;  // per element: some valid candidate pose covers it
  double reachable_area_m2 = 0.0;
  double unreachable_area_m2 = 0.0;
  double heading_deg = 0.0;             // the region's long axis (regionHeading)
  std::vector<std::uint32_t> photos;    // indices into CoveragePlan::photos, in pass order
  PassPlan passes;                      // views index `photos` (passes[k].views[i] -> photos[...])
  std::size_t candidates = 0;           // candidate views after filtering
  GenerationStats generation;           // seeds, poses tried, repairs
  SetCoverResult selection;             // candidate indices, costs and improvement counters

  // Centres of the elements no candidate covers.
  std::vector<Eigen::Vector3d> unreachableCentres() const;
};

// Seconds spent per phase, summed over regions.
struct CoverageTimes {
  double surfaces_s = 0.0;
  double candidates_s = 0.0;  // lattice, visibility and repairs
  double costs_s = 0.0;
  double selection_s = 0.0;   // greedy and local improvement
  double passes_s = 0.0;
};

struct CoveragePlan {
  std::vector<RegionPlan> regions;
  std::vector<PlannedPhoto> photos;  // region by region, each in pass order
  double charge_estimate_ah = 0.0;   // sum of the chosen views' costs (the selection's estimate)
  CoverageTimes times;
};

struct CoveragePlanOptions {
  ViewGenerationOptions views;
  ViewCostOptions costs;
  SetCoverOptions selection;
  // Progress of the long phases: (phase name, fraction of that phase). Never prints.
  std::function<void(const std::string&, double)> progress;
};

// Plans the views of every region. `cost_model` is the mode's (free mode: proximity effects
// off, as a conventional planner prices hover) and must be built on `environment`.
// Throws ceilplan::InputError before any map work for a bad camera or region, or a camera that
// cannot inspect a region (checkCameraReaches); then for a region with no surface in it.
CoveragePlan planCoverage(const environment::Environment& environment, const planner::FlightCostModel& cost_model,
                          const Camera& camera, const std::vector<CoverageRegion>& regions,
                          const CoveragePlanOptions& options = {});

}  // namespace ceilplan::mission
