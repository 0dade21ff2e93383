#include "ceilplan/io/coverage_output.hpp"

#include "ceilplan/core/format.hpp"
#include "ceilplan/io/atomic_file.hpp"
#include "ceilplan/io/json_values.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace ceilplan::io {
namespace {

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

nlohmann::json points(const std::vector<Eigen::Vector3d>& centres) {
  nlohmann::json list = nlohmann::json::array();
  for (const Eigen::Vector3d& c : centres) list.push_back({c.x(), c.y(), c.z()});
  return list;
}

double percent(double part, double whole) { return whole > 0.0 ? 100.0 * part / whole : 100.0; }

}  // namespace

std::string photosCsv(const std::vector<PhotoRow>& rows) {
  std::ostringstream out;
  out << "index,sortie,t_s,x,y,z,yaw_deg,gimbal_pitch_deg,distance_m,gsd_mm_px,region\n";
  for (const PhotoRow& row : rows) {
    out << row.index << ',' << (row.sortie ? std::to_string(*row.sortie) : "") << ','
        << (row.t_s ? formatFixed(*row.t_s, 2) : "") << ',' << formatFixed(row.camera_m.x(), 3) << ','
        << formatFixed(row.camera_m.y(), 3) << ',' << formatFixed(row.camera_m.z(), 3) << ','
        << formatFixed(row.yaw_deg, 2) << ',' << formatFixed(row.gimbal_pitch_deg, 2) << ','
        << formatFixed(row.distance_m, 3) << ',' << formatFixed(row.gsd_mm_px, 3) << ',' << csvField(row.region)
        << '\n';
  }
  return out.str();
}

namespace {

// Throws unless `check` is a re-check of `plan`'s regions, element for element; `file` names the output.
void requireMatchingCheck(const mission::CoveragePlan& plan, const mission::CoverageCheck& check, const char* file) {
  if (check.regions.size() != plan.regions.size())
    throw ceilplan::InputError(std::string(file) + ": the check has " + std::to_string(check.regions.size()) +
                               " regions, the plan " + std::to_string(plan.regions.size()));
  for (std::size_t r = 0; r < plan.regions.size(); ++r) {
    const mission::RegionPlan& planned = plan.regions[r];
    const mission::RegionCoverageCheck& checked = check.regions[r];
    if (checked.name != planned.region.name || checked.covered.size() != planned.surface.elements.size() ||
        checked.best_gsd_mm_px.size() != checked.covered.size() ||
        checked.view_count.size() != checked.covered.size() || planned.reachable.size() != checked.covered.size())
      throw ceilplan::InputError(std::string(file) + ": region " + std::to_string(r) + " of the check is '" +
                                 checked.name + "', of the plan '" + planned.region.name + "'");
  }
}

}  // namespace

std::string coverageElementsCsv(const mission::CoveragePlan& plan, const mission::CoverageCheck& check) {
  requireMatchingCheck(plan, check, "coverage_elements.csv");
  std::ostringstream out;
  out << "region,x,y,z,nx,ny,nz,area_m2,reachable,covered,best_gsd_mm_px,views\n";
  for (std::size_t r = 0; r < plan.regions.size(); ++r) {
    const mission::RegionPlan& planned = plan.regions[r];
    const mission::RegionCoverageCheck& checked = check.regions[r];
    const std::string name = csvField(planned.region.name);
    for (std::size_t e = 0; e < planned.surface.elements.size(); ++e) {
      const environment::SurfaceElement& element = planned.surface.elements[e];
      const double best = checked.best_gsd_mm_px[e];
      out << name << ',' << formatFixed(element.centre_m.x(), 3) << ',' << formatFixed(element.centre_m.y(), 3) << ','
          << formatFixed(element.centre_m.z(), 3) << ',' << formatFixed(element.normal.x(), 4) << ','
          << formatFixed(element.normal.y(), 4) << ',' << formatFixed(element.normal.z(), 4) << ','
          << formatNumber(element.area_m2, 6) << ',' << (planned.reachable[e] ? 1 : 0) << ','
          << (checked.covered[e] ? 1 : 0) << ',' << (std::isfinite(best) ? formatFixed(best, 3) : "") << ','
          << checked.view_count[e] << '\n';
    }
  }
  return out.str();
}

nlohmann::json coverageJson(const mission::CoveragePlan& plan, const mission::CoverageCheck& check) {
  requireMatchingCheck(plan, check, "coverage.json");
  nlohmann::json regions = nlohmann::json::array();
  for (std::size_t r = 0; r < plan.regions.size(); ++r) {
    const mission::RegionPlan& planned = plan.regions[r];
    const mission::RegionCoverageCheck& checked = check.regions[r];
    const mission::CoverageRegion& region = planned.region;
    nlohmann::json faces = nlohmann::json::array();
    for (const mission::FaceKind kind : {mission::FaceKind::Down, mission::FaceKind::Side, mission::FaceKind::Up})
      if (region.faces.has(kind)) faces.push_back(mission::faceKindName(kind));
    regions.push_back({
        {"name", region.name},
        {"faces", faces},
        {"gsd_mm_px", region.gsd_mm_px},
        {"overlap_pct", {{"front", region.overlap_front_pct}, {"side", region.overlap_side_pct}}},
        {"max_incidence_deg", region.max_incidence_deg},
        {"area_m2", checked.area_m2},
        {"reachable_area_m2", checked.reachable_area_m2},
        {"unreachable_area_m2", checked.unreachable_area_m2},
        {"covered_area_m2", checked.covered_area_m2},
        {"covered_pct", percent(checked.covered_area_m2, checked.area_m2)},
        {"covered_reachable_pct", percent(checked.covered_reachable_area_m2, checked.reachable_area_m2)},
        {"mean_gsd_mm_px", checked.mean_gsd_mm_px},
        {"gsd_histogram",
         {{"edges_mm_px", checked.gsd_bin_edges_mm_px},
          {"area_m2", checked.gsd_bin_area_m2},
          {"unseen_area_m2", checked.unseen_area_m2}}},
        {"photos", planned.photos.size()},
        {"passes", planned.passes.passes.size()},
        {"uncovered_centres", points(mission::uncoveredCentres(planned.surface, checked))},
        {"unreachable_centres", points(planned.unreachableCentres())},
    });
  }
  return {{"regions", regions},
          {"photos", plan.photos.size()},
          {"check",
           {{"rays", check.rays},
            {"method", "every photo against every surface element; lines of sight through the OctoMap tree"}}}};
}

void writePhotosCsv(const std::filesystem::path& file, const std::vector<PhotoRow>& rows,
                    const Provenance& provenance) {
  writeTextAtomically(file, [&](std::ostream& out) { out << provenance.csvComment() << '\n' << photosCsv(rows); });
}

void writeCoverageJson(const std::filesystem::path& file, const nlohmann::json& coverage,
                       const Provenance& provenance) {
  writeJsonFile(file, withProvenance(coverage, provenance));
}

void writeCoverageFiles(const std::filesystem::path& dir, const mission::TourResult& tour,
                        const Provenance& provenance) {
  if (!tour.coverage || !tour.coverage_check)
    throw ceilplan::InputError("the tour has no coverage plan: photos.csv and coverage.json belong to coverage tours");
  writePhotosCsv(dir / "photos.csv", tour.photos, provenance);
  writeCoverageJson(dir / "coverage.json", coverageJson(*tour.coverage, *tour.coverage_check), provenance);
  const std::string elements = coverageElementsCsv(*tour.coverage, *tour.coverage_check);
  writeTextAtomically(dir / "coverage_elements.csv", [&](std::ostream& out) {
    out << provenance.csvComment() << '\n' << elements;
  });
}

double routeLength_m(const mission::TourResult& tour) {
  double length_m = 0.0;
  for (const mission::Sortie& sortie : tour.plan.sorties)
    for (const mission::SortieLeg& leg : sortie.legs) length_m += tour.legs[leg.from][leg.to].evaluation.length_m;
  return length_m;
}

namespace {

const mission::CoverageCheck& checked(const mission::TourResult& tour) {
  if (!tour.coverage || !tour.coverage_check) throw ceilplan::InputError("the tour has no coverage plan");
  return *tour.coverage_check;
}

}  // namespace

CoverageSummary coverageSummary(const mission::TourResult& tour) {
  double reachable = 0.0, covered_reachable = 0.0, covered = 0.0, gsd_area = 0.0;
  for (const mission::RegionCoverageCheck& region : checked(tour).regions) {
    reachable += region.reachable_area_m2;
    covered_reachable += region.covered_reachable_area_m2;
    covered += region.covered_area_m2;
    gsd_area += region.mean_gsd_mm_px * region.covered_area_m2;
  }
  return {tour.photos.size(), routeLength_m(tour), percent(covered_reachable, reachable),
          covered > 0.0 ? gsd_area / covered : 0.0};
}

nlohmann::json coverageSummaryJson(const mission::TourResult& tour) {
  const mission::CoverageCheck& check = checked(tour);
  nlohmann::json regions = nlohmann::json::array();
  for (const mission::RegionCoverageCheck& region : check.regions)
    regions.push_back({{"name", region.name},
                       {"area_m2", region.area_m2},
                       {"reachable_area_m2", region.reachable_area_m2},
                       {"unreachable_area_m2", region.unreachable_area_m2},
                       {"covered_area_m2", region.covered_area_m2},
                       {"covered_pct", percent(region.covered_area_m2, region.area_m2)},
                       {"covered_reachable_pct", percent(region.covered_reachable_area_m2, region.reachable_area_m2)},
                       {"mean_gsd_mm_px", region.mean_gsd_mm_px}});
  const CoverageSummary summary = coverageSummary(tour);
  return {{"photos", summary.photos},
          {"route_m", summary.route_m},
          {"covered_reachable_pct", summary.covered_reachable_pct},
          {"mean_gsd_mm_px", summary.mean_gsd_mm_px},
          {"regions", regions}};
}

nlohmann::json coverageComparisonJson(const mission::TourResult& ceiling, const mission::TourResult& free) {
  return {{"ceiling", coverageSummaryJson(ceiling)}, {"free", coverageSummaryJson(free)}};
}

}  // namespace ceilplan::io
