#pragma once
/// @file
/// The coverage outputs: photos.csv (one row per photo) and coverage.json (per region: area,
/// covered area at the required GSD, incidence and overlap, unreachable area, a GSD histogram, the
/// centres of uncovered and unreachable elements), built from a coverage plan and its
/// independent re-check. Formats: docs/coverage.md, "Outputs".

#include "ceilplan/io/provenance.hpp"
#include "ceilplan/mission/coverage_check.hpp"
#include "ceilplan/mission/coverage_plan.hpp"
#include "ceilplan/mission/tour_planner.hpp"

#include <nlohmann/json.hpp>

#include <Eigen/Core>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::io {

/// One row of photos.csv, and the plan's photos as rows (mission/coverage_plan.hpp).
using mission::PhotoRow;
using mission::photoRows;

/// Header `index,sortie,t_s,x,y,z,yaw_deg,gimbal_pitch_deg,distance_m,gsd_mm_px,region`, then one
/// line per row: positions and distances in metres to the millimetre, angles to 0.01 deg, GSD to
/// 0.001 mm/px; an empty sortie or time is an empty field; a region name with a comma, quote
/// or line break is quoted (RFC 4180).
std::string photosCsv(const std::vector<PhotoRow>& rows);

/// coverage.json: {"regions": [...], "photos": N, "check": {...}} with, per region of the plan
/// (and of the check, same order): name, faces, required gsd_mm_px, overlap_pct {front, side},
/// max_incidence_deg, area_m2, reachable_area_m2, unreachable_area_m2, covered_area_m2,
/// covered_pct (of the area), covered_reachable_pct, mean_gsd_mm_px, gsd_histogram {edges_mm_px,
/// area_m2, unseen_area_m2}, photos, passes, uncovered_centres and unreachable_centres ([x, y, z]).
/// Throws ceilplan::InputError when the check does not match the plan's regions.
nlohmann::json coverageJson(const mission::CoveragePlan& plan, const mission::CoverageCheck& check);

/// coverage_elements.csv, for the coverage figures (scripts/plot-coverage): header
/// `region,x,y,z,nx,ny,nz,area_m2,reachable,covered,best_gsd_mm_px,views`, one line per surface
/// element of every region: its face centre (m, to the millimetre) and unit normal, its area, 1 or
/// 0 for reachable (some valid pose could cover it) and covered (by the re-check), the best GSD
/// of the photos seeing it anywhere in the frame (empty if none does) and how many photos see it
/// at or below the required GSD and incidence. Throws ceilplan::InputError as coverageJson does.
std::string coverageElementsCsv(const mission::CoveragePlan& plan, const mission::CoverageCheck& check);

/// Both written atomically (whole or not at all), with `provenance`: the CSV's first line is its
/// comment, the JSON holds it as "provenance".
void writePhotosCsv(const std::filesystem::path& file, const std::vector<PhotoRow>& rows, const Provenance& provenance);
/// coverage.json, written atomically with `provenance`.
void writeCoverageJson(const std::filesystem::path& file, const nlohmann::json& coverage, const Provenance& provenance);

/// A coverage tour's files in its directory: photos.csv (the photos as flown, with sortie and
/// time), coverage.json (the plan with the re-check of the photos flown) and
/// coverage_elements.csv (each element as the re-check found it), each with `provenance`. Throws
/// ceilplan::InputError when the tour has no coverage plan.
void writeCoverageFiles(const std::filesystem::path& dir, const mission::TourResult& tour,
                        const Provenance& provenance);

/// tour.json's "coverage": photos, route_m, and per region name, area_m2, reachable_area_m2,
/// covered_area_m2, covered_pct, covered_reachable_pct, unreachable_area_m2, mean_gsd_mm_px.
nlohmann::json coverageSummaryJson(const mission::TourResult& tour);

/// A coverage tour's totals over every region, by the re-check: the photos, the route length,
/// the share of the reachable surface covered (%) and the mean GSD of the covered area. Throws
/// ceilplan::InputError when the tour has no coverage plan.
struct CoverageSummary {
  std::size_t photos = 0;                ///< photos taken
  double route_m = 0.0;                  ///< route length through the photos
  double covered_reachable_pct = 100.0;  ///< share of the reachable surface covered
  double mean_gsd_mm_px = 0.0;           ///< mean GSD of the covered area
};
/// The summary of a coverage tour, as above.
CoverageSummary coverageSummary(const mission::TourResult& tour);

/// Both modes' coverage side by side, as comparison.json's "coverage".
nlohmann::json coverageComparisonJson(const mission::TourResult& ceiling, const mission::TourResult& free);

/// Length of the route flown (every leg of every sortie), metres.
double routeLength_m(const mission::TourResult& tour);

}  // namespace ceilplan::io
