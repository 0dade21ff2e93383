// A coverage tour's files as `ceilplan tour --mode both` writes them (the ctest fixture plans
// tests/coverage/missions/bridge_strip.yaml into CEILPLAN_TOURS_DIR/bridge_strip): photos.csv
// with exactly its columns, coverage.json with every key docs/coverage.md lists,
// coverage_elements.csv adding up to it, and the
// autopilot files carrying the camera (docs/flying.md): every photo row is a waypoint at its
// pose with its yaw, the gimbal pitch commanded before it, a hold and one
// MAV_CMD_IMAGE_START_CAPTURE; speed commands only where the speed changes; the WPL the same
// items as the .plan. Read with the tests' own parsing, none of the writers' code. The strip's
// sorties are flown as trajectories in test_flying_tours.cpp (ShippedTrajectories.CoverageStrip).

#include "ceilplan/io/autopilot_export.hpp"
#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/mission/camera.hpp"
#include "flying_fixture.hpp"
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>

namespace ceilplan::testing {
namespace {

const std::filesystem::path kStripMission =
    std::filesystem::path(CEILPLAN_SOURCE_DIR) / "tests" / "coverage" / "missions" / "bridge_strip.yaml";
const std::filesystem::path kStripTours = std::filesystem::path(CEILPLAN_TOURS_DIR) / "bridge_strip";

std::vector<std::string> fieldsOf(const std::string& line, char separator) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, separator)) fields.push_back(field);
  if (!line.empty() && line.back() == separator) fields.emplace_back();
  return fields;
}

struct PhotoCsvRow {
  int index, sortie;
  double t_s;
  Eigen::Vector3d camera_m;
  double yaw_deg, gimbal_pitch_deg, distance_m, gsd_mm_px;
  std::string region;
};

std::vector<PhotoCsvRow> readPhotosCsv(const std::filesystem::path& file) {
  std::stringstream text(readWholeFile(file));
  std::string line;
  std::getline(text, line);
  EXPECT_EQ(line.rfind("# ceilplan ", 0), 0u) << "the provenance comment: " << line;
  std::getline(text, line);
  EXPECT_EQ(line, "index,sortie,t_s,x,y,z,yaw_deg,gimbal_pitch_deg,distance_m,gsd_mm_px,region");
  std::vector<PhotoCsvRow> rows;
  while (std::getline(text, line)) {
    const std::vector<std::string> f = fieldsOf(line, ',');
    EXPECT_EQ(f.size(), 11u) << line;
    if (f.size() != 11u) continue;
    rows.push_back({std::stoi(f[0]),
                    std::stoi(f[1]),
                    std::stod(f[2]),
                    {std::stod(f[3]), std::stod(f[4]), std::stod(f[5])},
                    std::stod(f[6]),
                    std::stod(f[7]),
                    std::stod(f[8]),
                    std::stod(f[9]),
                    f[10]});
  }
  return rows;
}

double angleBetween_deg(double a, double b) { return std::abs(std::remainder(a - b, 360.0)); }

void expectCoverageJson(const nlohmann::json& coverage, const mission::Mission& mission, std::size_t photos) {
  ASSERT_EQ(coverage["regions"].size(), mission.surfaces.size());
  const nlohmann::json& region = coverage["regions"][0];
  const mission::CoverageRegion& surface = mission.surfaces[0];
  EXPECT_EQ(region["name"], surface.name);
  EXPECT_EQ(region["gsd_mm_px"].get<double>(), surface.gsd_mm_px);
  EXPECT_EQ(region["photos"].get<std::size_t>(), photos);
  for (const char* key : {"area_m2", "reachable_area_m2", "unreachable_area_m2", "covered_area_m2", "covered_pct",
                          "covered_reachable_pct", "mean_gsd_mm_px"})
    EXPECT_TRUE(region[key].is_number()) << key;
  const double area = region["area_m2"];
  EXPECT_GT(area, 10.0);  // 5 m x 2.4 m of deck underside between the girders
  EXPECT_NEAR(region["reachable_area_m2"].get<double>() + region["unreachable_area_m2"].get<double>(), area, 1e-6);
  EXPECT_GE(region["covered_reachable_pct"].get<double>(), 99.0);
  EXPECT_NEAR(region["covered_pct"].get<double>(), 100.0 * region["covered_area_m2"].get<double>() / area, 1e-6);
  EXPECT_LE(region["mean_gsd_mm_px"].get<double>(), surface.gsd_mm_px);
  // The histogram: 8 edges, an area per bin, the unseen rest; together the whole area.
  const nlohmann::json& histogram = region["gsd_histogram"];
  ASSERT_EQ(histogram["edges_mm_px"].size(), 8u);
  ASSERT_EQ(histogram["area_m2"].size(), 8u);
  double binned = histogram["unseen_area_m2"];
  for (const auto& bin : histogram["area_m2"]) binned += bin.get<double>();
  EXPECT_NEAR(binned, area, 1e-6);
  EXPECT_TRUE(region["uncovered_centres"].is_array());
  EXPECT_TRUE(region["unreachable_centres"].is_array());
  EXPECT_EQ(region["unreachable_centres"].empty(), region["unreachable_area_m2"].get<double>() == 0.0);
}

// The .plan's items and the WPL's rows, one for one (NaN written as nan).
void expectWplMirrorsPlan(const nlohmann::json& items, const std::filesystem::path& wpl_file) {
  std::stringstream text(readWholeFile(wpl_file));
  std::string line;
  std::getline(text, line);
  EXPECT_EQ(line, "QGC WPL 110");
  std::getline(text, line);  // home
  std::size_t k = 0;
  while (std::getline(text, line)) {
    const std::vector<std::string> f = fieldsOf(line, '\t');
    ASSERT_EQ(f.size(), 12u) << line;
    ASSERT_LT(k, items.size());
    const nlohmann::json& item = items[k];
    EXPECT_EQ(std::stoi(f[0]), static_cast<int>(k + 1)) << line;
    EXPECT_EQ(std::stoi(f[2]), item["frame"].get<int>()) << line;
    EXPECT_EQ(std::stoi(f[3]), item["command"].get<int>()) << line;
    for (int p = 0; p < 7; ++p) {
      const nlohmann::json& value = item["params"][p];
      if (value.is_null()) {
        EXPECT_EQ(f[4 + p], "nan") << line;
      } else {
        EXPECT_NEAR(std::stod(f[4 + p]), value.get<double>(), p == 4 || p == 5 ? 1e-8 : 1e-3) << line;
      }
    }
    ++k;
  }
  EXPECT_EQ(k, items.size());
}

TEST(CoverageTourFiles, PhotosCoverageAndTheCameraInTheAutopilotFiles) {
  const mission::Mission mission = io::readMission(kStripMission);
  const mission::Camera& camera = *mission.camera;
  const double hold_s = camera.stopPerPhoto_s();
  for (const char* mode : {"ceiling", "free"}) {
    SCOPED_TRACE(mode);
    const std::filesystem::path dir = kStripTours / mode;
    const std::vector<PhotoCsvRow> rows = readPhotosCsv(dir / "photos.csv");
    ASSERT_FALSE(rows.empty());
    const nlohmann::json coverage = nlohmann::json::parse(readWholeFile(dir / "coverage.json"));
    expectCoverageJson(coverage, mission, rows.size());
    // coverage_elements.csv: the covered elements' areas add up to coverage.json's covered area.
    std::stringstream elements(readWholeFile(dir / "coverage_elements.csv"));
    std::string line;
    std::getline(elements, line);
    EXPECT_EQ(line.rfind("# ceilplan ", 0), 0u) << "the provenance comment: " << line;
    std::getline(elements, line);
    EXPECT_EQ(line, "region,x,y,z,nx,ny,nz,area_m2,reachable,covered,best_gsd_mm_px,views");
    double covered_m2 = 0.0;
    std::size_t element_rows = 0;
    while (std::getline(elements, line)) {
      const std::vector<std::string> f = fieldsOf(line, ',');
      ASSERT_EQ(f.size(), 12u) << line;
      ++element_rows;
      if (f[9] == "1") {
        covered_m2 += std::stod(f[7]);
        EXPECT_GE(std::stoi(f[11]), 1) << line;  // a covered element is seen by some photo
      }
    }
    EXPECT_GT(element_rows, 1000u);  // 0.1 m faces over 11 m^2
    EXPECT_NEAR(covered_m2, coverage["regions"][0]["covered_area_m2"].get<double>(), 1e-6 * element_rows);
    const nlohmann::json tour = nlohmann::json::parse(readWholeFile(dir / "tour.json"));
    ASSERT_EQ(tour["sorties"].size(), 1u);  // so mission.plan holds every photo
    double last_t = 0.0;
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const PhotoCsvRow& row = rows[k];
      EXPECT_EQ(row.index, static_cast<int>(k + 1));
      EXPECT_EQ(row.sortie, 1);
      EXPECT_GT(row.t_s, last_t);
      last_t = row.t_s;
      EXPECT_EQ(row.region, "strip");
      EXPECT_LE(row.gsd_mm_px, 1.0);
      EXPECT_GE(row.distance_m, camera.min_focus_m);
      EXPECT_GE(row.gimbal_pitch_deg, camera.gimbal_pitch_min_deg);
      EXPECT_LE(row.gimbal_pitch_deg, camera.gimbal_pitch_max_deg);
    }

    // mission.plan: walk the items with the gimbal pitch and speed in effect.
    const nlohmann::json plan = nlohmann::json::parse(readWholeFile(dir / "mission.plan"));
    const nlohmann::json& items = plan["mission"]["items"];
    const double home_amsl = plan["mission"]["plannedHomePosition"][2];
    std::optional<double> speed;  // the first is commanded whatever it is: cruiseSpeed never reaches the vehicle
    std::optional<double> pitch;
    std::size_t next_row = 0, captures = 0, waypoints = 0;
    for (std::size_t k = 0; k < items.size(); ++k) {
      const nlohmann::json& item = items[k];
      const int command = item["command"];
      const nlohmann::json& p = item["params"];
      ASSERT_EQ(p.size(), 7u);
      if (command == io::mav::kDoChangeSpeed) {
        EXPECT_EQ(p[0].get<double>(), 1.0);  // ground speed
        if (speed) {
          EXPECT_GE(std::abs(p[1].get<double>() - *speed), 0.01) << "item " << k << ": no change";
        }
        EXPECT_GT(p[1].get<double>(), 0.0);
        speed = p[1].get<double>();
      } else if (command == io::mav::kDoGimbalManagerPitchYaw) {
        EXPECT_TRUE(!pitch || *pitch != p[0].get<double>()) << "item " << k << ": no change";
        pitch = p[0].get<double>();
        EXPECT_EQ(p[1].get<double>(), 0.0);  // yaw follows the vehicle
        EXPECT_TRUE(p[2].is_null() && p[3].is_null());
        EXPECT_EQ(p[4].get<int>(), io::mav::kGimbalFlagsHorizonFollow);
      } else if (command == io::mav::kNavWaypoint) {
        ++waypoints;
        EXPECT_TRUE(p[3].is_number()) << "item " << k << ": a yaw at every waypoint";
      } else if (command == io::mav::kImageStartCapture) {
        EXPECT_EQ(p[2].get<double>(), 1.0);  // one image
        EXPECT_EQ(p[3].get<double>(), static_cast<double>(++captures));
        ASSERT_GT(k, 0u);
        const nlohmann::json& waypoint = items[k - 1];
        ASSERT_EQ(waypoint["command"], io::mav::kNavWaypoint) << "item " << k << ": a photo after its waypoint";
        const nlohmann::json& w = waypoint["params"];
        const Eigen::Vector3d body =
            io::toLocal(*mission.origin, {w[4].get<double>(), w[5].get<double>(), home_amsl + w[6].get<double>()});
        // Point targets take a photo too (contact points do not); photo rows come in flying order.
        if (next_row == rows.size()) continue;
        const PhotoCsvRow& row = rows[next_row];
        if ((mission::cameraPosition(camera, body, w[3].get<double>()) - row.camera_m).norm() > 0.01) continue;
        ++next_row;
        EXPECT_LT(angleBetween_deg(w[3].get<double>(), row.yaw_deg), 0.01) << "photo " << row.index;
        ASSERT_TRUE(pitch.has_value()) << "photo " << row.index;
        EXPECT_NEAR(*pitch, row.gimbal_pitch_deg, 0.01) << "photo " << row.index;
        EXPECT_DOUBLE_EQ(w[0].get<double>(), hold_s) << "photo " << row.index;
      } else if (command == io::mav::kNavTakeoff) {
        EXPECT_EQ(k, 0u) << "the take-off comes first";
      } else if (command == io::mav::kNavLand) {
        EXPECT_EQ(k + 1, items.size()) << "the landing comes last";
      } else {
        ADD_FAILURE() << "item " << k << ": command " << command << " unexpected in a hover-capture tour";
      }
    }
    EXPECT_EQ(next_row, rows.size()) << "photo rows found at capture waypoints";
    EXPECT_EQ(captures, tour["photos_taken"].get<std::size_t>() + tour["targets_visited"].get<std::size_t>())
        << "one capture per photo and point target, none at a contact reading";
    EXPECT_GT(waypoints, captures);
    expectWplMirrorsPlan(items, dir / "mission.waypoints");
  }
}

}  // namespace
}  // namespace ceilplan::testing
