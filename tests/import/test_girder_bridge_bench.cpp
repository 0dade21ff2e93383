// bench/import/girder-bridge, the big-structure benchmark (docs/import.md, "A 130 m girder bridge
// at 0.05 m"), run small so that its code cannot rot: a 20 m stretch of the bridge at 0.2 m,
// generated, imported and toured in both modes by the script itself. Not timed.

#include "run_command.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>
#include <cstdlib>
#include <map>
#include <sstream>

namespace ceilplan {
namespace {

namespace fs = std::filesystem;

TEST(GirderBridgeBench, ASmallStretchIsWrittenAsPolygonsImportedAsClosedSolidsAndToursItsSoffitInBothModes) {
  const fs::path dir = testing::scratchDirectory("girder_bridge");
  const std::string command = std::string(CEILPLAN_SOURCE_DIR "/bench/import/girder-bridge --ceilplan ") +
                              CEILPLAN_EXE + " --length-m 20 --resolution 0.2 " + dir.string() + " >" +
                              (dir / "bench.log").string() + " 2>&1";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << testing::readWholeFile(dir / "bench.log");

  // A CAD export's polygons: quads and the columns' octagonal caps, no triangle.
  std::istringstream ply(testing::readWholeFile(dir / "bridge.ply"));
  std::string line;
  std::size_t vertices = 0, faces = 0;
  while (std::getline(ply, line) && line != "end_header") {
    std::istringstream words(line);
    std::string keyword, element;
    std::size_t count = 0;
    if (words >> keyword >> element >> count && keyword == "element") (element == "vertex" ? vertices : faces) = count;
  }
  for (std::size_t v = 0; v < vertices; ++v) std::getline(ply, line);
  std::map<int, std::size_t> corners;
  for (std::size_t f = 0; f < faces && std::getline(ply, line); ++f) ++corners[std::stoi(line)];
  EXPECT_GT(corners[4], 400u);
  EXPECT_EQ(corners[8], 2u * 3u * 2u);  // two piers of three columns, two caps each
  EXPECT_EQ(corners.size(), 2u);

  const nlohmann::json sidecar = nlohmann::json::parse(testing::readWholeFile(dir / "bridge.bt.json"));
  EXPECT_EQ(sidecar["free_space"].get<std::string>().rfind("closed mesh, triangles facing outward: solid", 0), 0u)
      << sidecar["free_space"];

  const nlohmann::json comparison = nlohmann::json::parse(testing::readWholeFile(dir / "tour/comparison.json"));
  for (const char* mode : {"ceiling", "free"}) {
    const nlohmann::json& coverage = comparison["coverage"][mode];
    EXPECT_GT(coverage["photos"].get<int>(), 100) << mode;
    ASSERT_EQ(coverage["regions"].size(), 2u) << mode;
    for (const nlohmann::json& region : coverage["regions"]) {
      EXPECT_GT(region["area_m2"].get<double>(), 50.0) << mode << " " << region["name"];
      EXPECT_GE(region["covered_reachable_pct"].get<double>(), 99.0) << mode << " " << region["name"];
    }
  }

  const std::string table = testing::readWholeFile(dir / "table.md");
  for (const char* row : {"| import |", "| index |", "| tour, both modes |", "| import + tour |"})
    EXPECT_NE(table.find(row), std::string::npos) << row << " in\n" << table;
}

}  // namespace
}  // namespace ceilplan
