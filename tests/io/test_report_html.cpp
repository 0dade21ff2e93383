// report.html: the structure near a route, the page self-contained (three.js embedded, no
// placeholder left, nothing fetched), its data block parsed back with a real JSON parser, and
// bad models refused.

#include "ceilplan/core/error.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/report_html.hpp"
#include "run_command.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

namespace ceilplan::io {
namespace {

// A 10 x 4 x 3 m hall at 0.1 m: floor and a 0.3 m thick ceiling slab at z 2.7-3.0.
environment::VoxelGrid hall() {
  environment::VoxelGrid grid(environment::GridFrame(0.1, {0, 0, 0}, {100, 40, 30}));
  grid.fillBox({0, 0, 0}, {10, 4, 3}, environment::CellState::Free);
  grid.fillBox({0, 0, 0}, {10, 4, 0.1}, environment::CellState::Occupied);
  grid.fillBox({0, 0, 2.7}, {10, 4, 3}, environment::CellState::Occupied);
  return grid;
}

ReportModel model() {
  ReportModel m;
  m.title = "hall </script> & <b>co</b>";
  m.home_m = {1, 2, 0.5};
  m.reserve_soc = 0.25;
  ReportPlan plan;
  plan.name = "ceiling";
  for (int k = 0; k <= 10; ++k)
    plan.samples.push_back({k * 1.0, {1.0 + 0.5 * k, 2, 2.5}, 8.0 + 0.1 * k, 0.95 - 0.01 * k, 1});
  plan.targets.push_back({"slab", {3, 2, 2.7}, Eigen::Vector3d(3, 2, 2.5)});
  plan.photos.push_back({{3, 2, 2.5}, 0, 90, 60, 45, 0.2});
  plan.coverage.push_back({{3, 2, 2.7}, -Eigen::Vector3d::UnitZ(), 0.5, 0.4});
  plan.coverage.push_back({{4, 2, 2.7}, -Eigen::Vector3d::UnitZ(), 0.5, std::nan("")});
  plan.summary = {{"charge", "0.1 Ah"}};
  m.plans = {plan, plan};
  m.plans[1].name = "free";
  m.comparison_header = {"", "ceiling", "free"};
  m.comparison_rows = {{"charge [Ah]", "0.1", "0.2"}};
  m.structure.voxel_m = 0.1;
  m.structure.centres_m = {{3.05, 2.05, 2.75}};
  return m;
}

TEST(ReportStructure, ExposedOccupiedVoxelsNearTheRouteOnly) {
  const environment::VoxelGrid grid = hall();
  const std::vector<Eigen::Vector3d> route{{2, 2, 2.0}, {4, 2, 2.0}};
  const ReportStructure s = structureNear(grid, route, 1.0);
  EXPECT_DOUBLE_EQ(s.voxel_m, 0.1);
  ASSERT_FALSE(s.centres_m.empty());
  ASSERT_EQ(s.faces.size(), s.centres_m.size());
  for (std::size_t v = 0; v < s.centres_m.size(); ++v) {
    const Eigen::Vector3d& c = s.centres_m[v];
    // The ceiling slab's underside layer only, its face down: the slab's inner voxels show no
    // face, its top faces unknown space, the floor is 1.9 m away.
    EXPECT_NEAR(c.z(), 2.75, 1e-9);
    EXPECT_EQ(s.faces[v], 1 << 4);
    double nearest = 1e9;
    for (double x = 2; x <= 4; x += 0.5) nearest = std::min(nearest, (c - Eigen::Vector3d(x, 2, 2)).norm());
    EXPECT_LE(nearest, 1.0 + 0.5);
  }
  // A cap forces coarser cells.
  const ReportStructure coarse = structureNear(grid, route, 1.0, s.centres_m.size() / 3);
  EXPECT_GT(coarse.voxel_m, 0.1);
  for (std::uint8_t faces : coarse.faces) EXPECT_EQ(faces, 1 << 4);
  EXPECT_LE(coarse.centres_m.size(), s.centres_m.size() / 3);
  EXPECT_TRUE(structureNear(grid, route, 0.5).centres_m.empty());
}

TEST(ReportHtml, OneSelfContainedPageWithTheDataBlock) {
  const std::filesystem::path dir = testing::scratchDirectory("report");
  writeReportHtml(dir / "report.html", model());
  const std::string page = testing::readWholeFile(dir / "report.html");
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(page.find("REVISION=\"111\""), std::string::npos) << "three.js r111 embedded";
  EXPECT_NE(page.find("OrbitControls"), std::string::npos);
  EXPECT_EQ(page.find("/*CEILPLAN:"), std::string::npos);
  EXPECT_EQ(page.find("<script src"), std::string::npos);
  EXPECT_EQ(page.find("http://cdn"), std::string::npos);
  EXPECT_EQ(page.find("https://cdn"), std::string::npos);
  // The data block holds no "</" (the title's "</script>" escaped), and parses.
  const std::string open = "<script type=\"application/json\" id=\"ceilplan-data\">";
  const std::size_t begin = page.find(open) + open.size();
  const std::size_t end = page.find("</script>", begin);
  const std::string block = page.substr(begin, end - begin);
  EXPECT_EQ(block.find("</"), std::string::npos);
  const nlohmann::json data = nlohmann::json::parse(block);
  // Written part by part, the block is still the document as jsonText writes it, "</" escaped.
  std::string canonical = jsonText(data);
  for (std::size_t at = canonical.find("</"); at != std::string::npos; at = canonical.find("</", at + 3))
    canonical.replace(at, 2, "<\\/");
  EXPECT_EQ(block, canonical);
  EXPECT_EQ(data["title"], "hall </script> & <b>co</b>");
  EXPECT_EQ(data["reserve_soc"], 0.25);
  EXPECT_EQ(data["home"], nlohmann::json::parse("[1.0, 2.0, 0.5]"));
  ASSERT_EQ(data["plans"].size(), 2u);
  const nlohmann::json& plan = data["plans"][0];
  EXPECT_EQ(plan["name"], "ceiling");
  for (const char* key : {"t", "x", "y", "z", "current", "soc", "sortie"})
    EXPECT_EQ(plan["samples"][key].size(), 11u) << key;
  EXPECT_EQ(plan["samples"]["x"][10], 6.0);
  EXPECT_EQ(plan["targets"][0]["viewpoint"], nlohmann::json::parse("[3.0, 2.0, 2.5]"));
  EXPECT_EQ(plan["photos"][0]["pitch_deg"], 90.0);
  EXPECT_EQ(plan["coverage"]["patches"].size(), 2u);
  EXPECT_TRUE(plan["coverage"]["patches"][1]["v"].is_null());
  EXPECT_EQ(data["structure"]["cells"], nlohmann::json::parse("[0, 0, 0, 63]"));  // all faces when none given
  EXPECT_EQ(data["structure"]["origin"], nlohmann::json::parse("[3.05, 2.05, 2.75]"));
  EXPECT_EQ(data["comparison"]["rows"][0][2], "0.2");
}

TEST(ReportHtml, TheWrittenFileIsTheDocumentWithEveryPartInItsPlace) {
  // writeReportHtml streams the page part by part; reportHtml builds it whole. Both are the
  // template with each placeholder replaced, in the template's order: three.js, OrbitControls,
  // the data, the viewer. A title that quotes a placeholder stays a title.
  ReportModel m = model();
  m.title = "quoting /*CEILPLAN:APP*/ and /*CEILPLAN:THREE*/";
  const std::filesystem::path dir = testing::scratchDirectory("report_parts");
  writeReportHtml(dir / "report.html", m);
  const std::string page = testing::readWholeFile(dir / "report.html");
  EXPECT_EQ(page, reportHtml(m));
  const std::size_t three = page.find("REVISION=\"111\""), orbit = page.find("var OrbitControls = function"),
                    data = page.find("id=\"ceilplan-data\""), title = page.find("quoting /*CEILPLAN:APP*/"),
                    viewer = page.find("window.ceilplanReport");
  ASSERT_NE(three, std::string::npos);
  ASSERT_NE(title, std::string::npos);
  EXPECT_LT(three, orbit);
  EXPECT_LT(orbit, data);
  EXPECT_LT(data, title);
  EXPECT_LT(title, viewer);
  EXPECT_EQ(page.find("/*CEILPLAN:"), title + std::string("quoting ").size()) << "only the title's own text";
  EXPECT_EQ(page.find("/*CEILPLAN:THREE*/"), page.rfind("/*CEILPLAN:THREE*/"));
}

TEST(ReportHtml, LongSamplesAreWrittenAsTheWholeArraysDump) {
  // A long plan's sample columns go into the page as each whole column's dump (values rounded to
  // the millimetre, the SOC to 1e-5), and the page's data parses back to them.
  ReportModel m = model();
  m.plans.resize(1);
  m.plans[0].samples.clear();
  nlohmann::json x = nlohmann::json::array(), soc = nlohmann::json::array(), sortie = nlohmann::json::array();
  for (int k = 0; k < 10000; ++k) {
    const ReportSample s{0.1 * k, {1.0 + 0.0123456 * k, 2.0, 2.5}, 8.0, 0.95 - 0.0000711 * k, 1 + k / 5000};
    m.plans[0].samples.push_back(s);
    x.push_back(std::round(s.position_m.x() * 1e3) / 1e3);
    soc.push_back(std::round(s.soc * 1e5) / 1e5);
    sortie.push_back(s.sortie);
  }
  const std::string page = reportHtml(m);
  for (const auto& [key, column] :
       {std::pair<std::string, const nlohmann::json*>{"x", &x}, {"soc", &soc}, {"sortie", &sortie}})
    EXPECT_NE(page.find("\"" + key + "\":" + column->dump() + ","), std::string::npos) << key;
  const std::string open = "<script type=\"application/json\" id=\"ceilplan-data\">";
  const std::size_t begin = page.find(open) + open.size();
  const nlohmann::json data = nlohmann::json::parse(page.substr(begin, page.find("</script>", begin) - begin));
  const nlohmann::json& samples = data["plans"][0]["samples"];
  EXPECT_EQ(samples["x"], x);
  EXPECT_EQ(samples["soc"], soc);
  EXPECT_EQ(samples["sortie"], sortie);
  EXPECT_EQ(samples["t"].size(), 10000u);
  EXPECT_EQ(data["plans"][0]["name"], "ceiling");
}

TEST(ReportHtml, RefusesBadModels) {
  const auto refuses = [](const ReportModel& m, const std::string& words) {
    try {
      reportHtml(m);
      ADD_FAILURE() << words;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  ReportModel m = model();
  m.plans.clear();
  refuses(m, "no plan");
  m = model();
  m.plans[1].samples.clear();
  refuses(m, "plan 'free' has no samples");
  m = model();
  m.plans[0].samples[3].soc = 1.5;
  refuses(m, "sample 4 SOC must lie in [0, 1]");
  m = model();
  m.plans[0].samples[5].t_s = 0.5;
  refuses(m, "sample 6: time goes backwards");
  m = model();
  m.plans[0].samples[2].position_m.x() = std::nan("");
  refuses(m, "must be finite");
  m = model();
  m.comparison_rows[0].pop_back();
  refuses(m, "comparison row has 2 cells");
  m = model();
  m.plans[0].photos[0].horizontal_fov_deg = 0;
  refuses(m, "photo with a bad angle");
}

}  // namespace
}  // namespace ceilplan::io
