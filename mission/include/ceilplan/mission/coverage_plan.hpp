#pragma once
/// @file
/// Coverage planning up to the choice of views: for each region, its surface elements, candidate
/// views, the wear-aware set cover, and the chosen views ordered into passes. The result is what
/// a tour flies: photo stops (fixed poses with a dwell) grouped into passes, plus the elements
/// no valid pose can see. docs/coverage.md.

#include "ceilplan/core/error.hpp"
#include "ceilplan/environment/environment.hpp"
#include "ceilplan/mission/camera.hpp"
#include "ceilplan/mission/coverage_passes.hpp"
#include "ceilplan/mission/coverage_region.hpp"
#include "ceilplan/mission/coverage_views.hpp"
#include "ceilplan/mission/region_surface.hpp"
#include "ceilplan/mission/view_selection.hpp"
#include "ceilplan/planner/flight_cost_model.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::mission {

/// One photo the plan takes: where, how, and what it delivers.
struct PlannedPhoto {
  CameraPose pose;  ///< body pose and gimbal pitch
  /// the camera's optical centre, map frame
  Eigen::Vector3d camera_m = Eigen::Vector3d::Zero();
  int region = 0;                ///< index into CoveragePlan::regions
  int pass = 0;                  ///< index into that region's passes
  double distance_m = 0.0;       ///< area-weighted mean over the elements it covers
  double gsd_mm_px = 0.0;        ///< likewise
  double covered_area_m2 = 0.0;  ///< of the region, in the covered part of the image
  double hover_current_a = 0.0;  ///< at the pose, under the mode's cost model
  double stop_s = 0.0;           ///< hover here this long (0 when shooting on the move)
  double max_speed_m_s =
      0.0;  ///< flying on to the next photo: the transit speed, on the move capped by the blur limit and photo interval
};

/// One region's part of a coverage plan: its surface, what is reachable, the photos chosen and their passes.
struct RegionPlan {
  CoverageRegion region;                ///< as the mission gives it
  RegionSurface surface;                ///< its surface elements
  std::vector<std::uint8_t> reachable;  ///< per element: some valid candidate pose covers it
  double reachable_area_m2 = 0.0;       ///< area some candidate pose covers
  double unreachable_area_m2 = 0.0;     ///< area no candidate pose covers
  double heading_deg = 0.0;             ///< the region's long axis (regionHeading)
  std::vector<std::uint32_t> photos;    ///< indices into CoveragePlan::photos, in pass order
  PassPlan passes;                      ///< views index `photos` (passes[k].views[i] -> photos[...])
  std::size_t candidates = 0;           ///< candidate views after filtering
  GenerationStats generation;           ///< seeds, poses tried, repairs
  SetCoverResult selection;             ///< candidate indices, costs and improvement counters

  /// Centres of the elements no candidate covers.
  std::vector<Eigen::Vector3d> unreachableCentres() const;
};

/// Seconds spent per phase, summed over regions.
struct CoverageTimes {
  double surfaces_s = 0.0;    ///< surface elements
  double candidates_s = 0.0;  ///< lattice, visibility and repairs
  double costs_s = 0.0;       ///< view costs
  double selection_s = 0.0;   ///< greedy and local improvement
  double passes_s = 0.0;      ///< pass arrangement
};

/// The views planCoverage chooses for a mission's surfaces in one mode (docs/coverage.md).
struct CoveragePlan {
  std::vector<RegionPlan> regions;   ///< one per surface, in the mission's order
  std::vector<PlannedPhoto> photos;  ///< region by region, each in pass order
  double charge_estimate_ah = 0.0;   ///< sum of the chosen views' costs (the selection's estimate)
  CoverageTimes times;               ///< seconds per phase
};

/// How planCoverage generates, prices and selects views.
struct CoveragePlanOptions {
  ViewGenerationOptions views;  ///< candidate generation
  ViewCostOptions costs;        ///< view costs
  SetCoverOptions selection;    ///< set cover
  /// Progress of the long phases: (phase name, fraction of that phase). Never prints.
  std::function<void(const std::string&, double)> progress;
};

/// One photo as flown: a row of photos.csv (docs/coverage.md, "Outputs").
struct PhotoRow {
  int index = 0;              ///< 1-based, in flying order
  std::optional<int> sortie;  ///< 1-based; empty until a tour assigns it
  std::optional<double> t_s;  ///< when the photo is taken, from the first take-off; empty until a tour times it
  Eigen::Vector3d camera_m = Eigen::Vector3d::Zero();  ///< the camera's optical centre, map frame
  double yaw_deg = 0.0;                                ///< heading, clockwise from north
  double gimbal_pitch_deg = 0.0;                       ///< +90 straight up
  double distance_m = 0.0;                             ///< area-weighted mean distance to the surface it covers
  double gsd_mm_px = 0.0;                              ///< area-weighted mean GSD over the surface it covers
  std::string region;                                  ///< the region's name
};

/// The row of photo `k` of the plan, numbered `index`, sortie and time left empty.
PhotoRow photoRow(const CoveragePlan& plan, std::size_t k, int index);
/// The plan's photos in its order, sortie and time left empty.
std::vector<PhotoRow> photoRows(const CoveragePlan& plan);

/// Plans the views of every region. `cost_model` is the mode's (free mode: proximity effects
/// off, as a conventional planner prices hover) and must be built on `environment`.
/// Throws ceilplan::InputError before any map work for a bad camera or region, or a camera that
/// cannot inspect a region (checkCameraReaches); then for a region with no surface in it.
CoveragePlan planCoverage(const environment::Environment& environment, const planner::FlightCostModel& cost_model,
                          const Camera& camera, const std::vector<CoverageRegion>& regions,
                          const CoveragePlanOptions& options = {});

}  // namespace ceilplan::mission
