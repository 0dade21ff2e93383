// photos.csv and coverage.json: columns, number formats, quoting, and every field of a region
// taken from the plan and its re-check.

#include "coverage_fixtures.hpp"

#include "ceilplan/io/coverage_output.hpp"
#include "ceilplan/mission/coverage_check.hpp"
#include "ceilplan/mission/coverage_plan.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace ceilplan::io {
namespace {

TEST(PhotosCsv, ColumnsAndFormats) {
  PhotoRow row;
  row.index = 1;
  row.camera_m = Eigen::Vector3d(1.23456, -2.0, 5.95);
  row.yaw_deg = 90.0;
  row.gimbal_pitch_deg = 89.999;
  row.distance_m = 2.6;
  row.gsd_mm_px = 0.8791;
  row.region = "soffit";
  PhotoRow timed = row;
  timed.index = 2;
  timed.sortie = 1;
  timed.t_s = 12.345;
  timed.region = "bay \"A\", north";
  EXPECT_EQ(photosCsv({row, timed}),
            "index,sortie,t_s,x,y,z,yaw_deg,gimbal_pitch_deg,distance_m,gsd_mm_px,region\n"
            "1,,,1.235,-2.000,5.950,90.00,90.00,2.600,0.879,soffit\n"
            "2,1,12.35,1.235,-2.000,5.950,90.00,90.00,2.600,0.879,\"bay \"\"A\"\", north\"\n");
}

TEST(CoverageJson, EveryFieldFromThePlanAndItsCheck) {
  const testing::CoverageScene& room = testing::roomScene();
  mission::CoverageRegion region;
  region.name = "ceiling";
  region.shape = mission::RegionShape::makeBox({-2, -2, 2.95}, {2, 2, 3.05});
  region.faces.down = true;
  region.gsd_mm_px = 1.0;
  const mission::Camera camera = testing::upwardCamera();
  const mission::CoveragePlan plan = mission::planCoverage(room.environment, room.ceiling_model, camera, {region});
  std::vector<mission::CameraPose> poses;
  for (const auto& photo : plan.photos) poses.push_back(photo.pose);
  const mission::CoverageCheck check = mission::checkCoverage(
      room.map.tree(), camera, {region}, {plan.regions[0].surface}, {plan.regions[0].reachable}, poses);

  const std::vector<PhotoRow> rows = photoRows(plan);
  ASSERT_EQ(rows.size(), plan.photos.size());
  EXPECT_EQ(rows.front().index, 1);
  EXPECT_FALSE(rows.front().sortie.has_value());
  EXPECT_EQ(rows.front().region, "ceiling");
  EXPECT_EQ(rows.back().camera_m, plan.photos.back().camera_m);

  const nlohmann::json json = coverageJson(plan, check);
  EXPECT_EQ(json["photos"], plan.photos.size());
  EXPECT_GT(json["check"]["rays"].get<std::size_t>(), 0u);
  const nlohmann::json& r = json["regions"].at(0);
  EXPECT_EQ(r["name"], "ceiling");
  EXPECT_EQ(r["faces"], nlohmann::json::array({"down"}));
  EXPECT_DOUBLE_EQ(r["gsd_mm_px"], 1.0);
  EXPECT_DOUBLE_EQ(r["overlap_pct"]["front"], 70.0);
  EXPECT_DOUBLE_EQ(r["overlap_pct"]["side"], 60.0);
  EXPECT_DOUBLE_EQ(r["max_incidence_deg"], 45.0);
  EXPECT_DOUBLE_EQ(r["area_m2"], check.regions[0].area_m2);
  EXPECT_NEAR(r["unreachable_area_m2"].get<double>(), 0.81, 1e-9);  // the closet
  EXPECT_NEAR(r["reachable_area_m2"].get<double>() + r["unreachable_area_m2"].get<double>(), r["area_m2"].get<double>(),
              1e-9);
  EXPECT_NEAR(r["covered_pct"].get<double>(), 100.0 * check.regions[0].covered_area_m2 / check.regions[0].area_m2,
              1e-9);
  EXPECT_GE(r["covered_reachable_pct"].get<double>(), 99.0);
  EXPECT_EQ(r["gsd_histogram"]["edges_mm_px"].size(), r["gsd_histogram"]["area_m2"].size());
  EXPECT_EQ(r["unreachable_centres"].size(), 81u);
  EXPECT_EQ(r["unreachable_centres"][0].size(), 3u);
  EXPECT_GE(r["uncovered_centres"].size(), 81u);  // the closet at least
  EXPECT_EQ(r["photos"], plan.photos.size());

  const std::filesystem::path dir = std::filesystem::path(CEILPLAN_TEST_TMP) / "coverage_output";
  std::filesystem::remove_all(dir);
  const Provenance provenance = Provenance::of("test_coverage_output");
  writeCoverageJson(dir / "coverage.json", json, provenance);
  writePhotosCsv(dir / "photos.csv", rows, provenance);
  std::ifstream in(dir / "coverage.json");
  EXPECT_EQ(nlohmann::json::parse(in), withProvenance(json, provenance));
  std::ifstream csv(dir / "photos.csv");
  std::stringstream text;
  text << csv.rdbuf();
  EXPECT_EQ(text.str(), provenance.csvComment() + "\n" + photosCsv(rows));

  mission::CoverageCheck other = check;
  other.regions[0].name = "roof";
  EXPECT_THROW(coverageJson(plan, other), ceilplan::InputError);
  EXPECT_THROW(coverageElementsCsv(plan, other), ceilplan::InputError);

  // coverage_elements.csv: one line per element, as the check found it.
  std::stringstream elements(coverageElementsCsv(plan, check));
  std::string line;
  std::getline(elements, line);
  EXPECT_EQ(line, "region,x,y,z,nx,ny,nz,area_m2,reachable,covered,best_gsd_mm_px,views");
  const mission::RegionSurface& surface = plan.regions[0].surface;
  const mission::RegionCoverageCheck& checked = check.regions[0];
  std::size_t e = 0;
  double covered_m2 = 0.0, unseen_m2 = 0.0;
  while (std::getline(elements, line)) {
    ASSERT_LT(e, surface.elements.size());
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) f.push_back(field);
    if (line.back() == ',') f.emplace_back();
    ASSERT_EQ(f.size(), 12u) << line;
    EXPECT_EQ(f[0], "ceiling");
    EXPECT_NEAR(std::stod(f[1]), surface.elements[e].centre_m.x(), 5e-4);
    EXPECT_NEAR(std::stod(f[6]), surface.elements[e].normal.z(), 5e-5);
    EXPECT_EQ(f[8], plan.regions[0].reachable[e] ? "1" : "0");
    EXPECT_EQ(f[9], checked.covered[e] ? "1" : "0");
    EXPECT_EQ(std::stoi(f[11]), checked.view_count[e]);
    if (f[10].empty()) {
      unseen_m2 += std::stod(f[7]);
      EXPECT_TRUE(std::isinf(checked.best_gsd_mm_px[e]));
    } else {
      EXPECT_NEAR(std::stod(f[10]), checked.best_gsd_mm_px[e], 5e-4);
    }
    if (f[9] == "1") covered_m2 += std::stod(f[7]);
    ++e;
  }
  EXPECT_EQ(e, surface.elements.size());
  EXPECT_NEAR(covered_m2, checked.covered_area_m2, 1e-6);
  EXPECT_NEAR(unseen_m2, checked.unseen_area_m2, 1e-6);
}

}  // namespace
}  // namespace ceilplan::io
