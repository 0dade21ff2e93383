#include "ceilplan/io/coverage_output.hpp"

#include "ceilplan/io/atomic_file.hpp"
#include "ceilplan/core/format.hpp"

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

std::vector<PhotoRow> photoRows(const mission::CoveragePlan& plan) {
  std::vector<PhotoRow> rows;
  for (std::size_t k = 0; k < plan.photos.size(); ++k) {
    const mission::PlannedPhoto& photo = plan.photos[k];
    PhotoRow row;
    row.index = static_cast<int>(k + 1);
    row.camera_m = photo.camera_m;
    row.yaw_deg = photo.pose.yaw_deg;
    row.gimbal_pitch_deg = photo.pose.gimbal_pitch_deg;
    row.distance_m = photo.distance_m;
    row.gsd_mm_px = photo.gsd_mm_px;
    row.region = plan.regions.at(static_cast<std::size_t>(photo.region)).region.name;
    rows.push_back(row);
  }
  return rows;
}

std::string photosCsv(const std::vector<PhotoRow>& rows) {
  std::ostringstream out;
  out << "index,sortie,t_s,x,y,z,yaw_deg,gimbal_pitch_deg,distance_m,gsd_mm_px,region\n";
  for (const PhotoRow& row : rows) {
    out << row.index << ',' << (row.sortie ? std::to_string(*row.sortie) : "") << ','
        << (row.t_s ? formatFixed(*row.t_s, 2) : "") << ',' << formatFixed(row.camera_m.x(), 3) << ','
        << formatFixed(row.camera_m.y(), 3) << ',' << formatFixed(row.camera_m.z(), 3) << ',' << formatFixed(row.yaw_deg, 2)
        << ',' << formatFixed(row.gimbal_pitch_deg, 2) << ',' << formatFixed(row.distance_m, 3) << ','
        << formatFixed(row.gsd_mm_px, 3) << ',' << csvField(row.region) << '\n';
  }
  return out.str();
}

nlohmann::json coverageJson(const mission::CoveragePlan& plan, const mission::CoverageCheck& check) {
  if (check.regions.size() != plan.regions.size())
    throw ceilplan::InputError("coverage.json: the check has " + std::to_string(check.regions.size()) +
                               " regions, the plan " + std::to_string(plan.regions.size()));
  nlohmann::json regions = nlohmann::json::array();
  for (std::size_t r = 0; r < plan.regions.size(); ++r) {
    const mission::RegionPlan& planned = plan.regions[r];
    const mission::RegionCoverageCheck& checked = check.regions[r];
    if (checked.name != planned.region.name || checked.covered.size() != planned.surface.elements.size())
      throw ceilplan::InputError("coverage.json: region " + std::to_string(r) + " of the check is '" + checked.name +
                                 "', of the plan '" + planned.region.name + "'");
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

void writePhotosCsv(const std::filesystem::path& file, const std::vector<PhotoRow>& rows) {
  writeTextAtomically(file, [&](std::ostream& out) { out << photosCsv(rows); });
}

void writeCoverageJson(const std::filesystem::path& file, const nlohmann::json& coverage) {
  writeTextAtomically(file, [&](std::ostream& out) { out << coverage.dump(2) << '\n'; });
}

}  // namespace ceilplan::io
