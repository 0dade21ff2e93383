#pragma once
// The coverage outputs: photos.csv (one row per photo) and coverage.json (per region: area,
// covered area at the required GSD, incidence and overlap, unreachable area, a GSD histogram, the
// centres of uncovered and unreachable elements), built from a coverage plan and its
// independent re-check. Formats: docs/coverage.md, "Outputs".

#include "ceilplan/mission/coverage_check.hpp"
#include "ceilplan/mission/coverage_plan.hpp"

#include <nlohmann/json.hpp>

#include <Eigen/Core>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::io {

// One row of photos.csv.
struct PhotoRow {
  int index = 0;                  // 1-based, in flying order
  std::optional<int> sortie;      // 1-based; empty until a tour assigns it
  std::optional<double> t_s;      // when the photo is taken, from the first take-off; empty until a tour times it
  Eigen::Vector3d camera_m = Eigen::Vector3d::Zero();  // the camera's optical centre, map frame
  double yaw_deg = 0.0;           // heading, clockwise from north
  double gimbal_pitch_deg = 0.0;  // +90 straight up
  double distance_m = 0.0;        // area-weighted mean distance to the surface it covers
  double gsd_mm_px = 0.0;         // area-weighted mean GSD over the surface it covers
  std::string region;
};

// The plan's photos in its order, sortie and time left empty.
std::vector<PhotoRow> photoRows(const mission::CoveragePlan& plan);

// Header `index,sortie,t_s,x,y,z,yaw_deg,gimbal_pitch_deg,distance_m,gsd_mm_px,region`, then one
// line per row: positions and distances in metres to the millimetre, angles to 0.01 deg, GSD to
// 0.001 mm/px; an empty sortie or time is an empty field; a region name with a comma, quote
// or line break is quoted (RFC 4180).
std::string photosCsv(const std::vector<PhotoRow>& rows);

// coverage.json: {"regions": [...], "photos": N, "check": {...}} with, per region of the plan
// (and of the check, same order): name, faces, required gsd_mm_px, overlap_pct {front, side},
// max_incidence_deg, area_m2, reachable_area_m2, unreachable_area_m2, covered_area_m2,
// covered_pct (of the area), covered_reachable_pct, mean_gsd_mm_px, gsd_histogram {edges_mm_px,
// area_m2, unseen_area_m2}, photos, passes, uncovered_centres and unreachable_centres ([x, y, z]).
// Throws ceilplan::InputError when the check does not match the plan's regions.
nlohmann::json coverageJson(const mission::CoveragePlan& plan, const mission::CoverageCheck& check);

// Both written atomically (whole or not at all).
void writePhotosCsv(const std::filesystem::path& file, const std::vector<PhotoRow>& rows);
void writeCoverageJson(const std::filesystem::path& file, const nlohmann::json& coverage);

}  // namespace ceilplan::io
