// `ceilplan propose` as a user runs it: a mission from a map with no hand-placed point, which
// `ceilplan tour` then flies in both modes without an edit; on a shipped scene and on a real
// scan nobody here made (geb079.bt, liboctomap-dev's office corridor). Bad input is refused
// before any work, leaving no file.

#include "run_command.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace ceilplan {
namespace {

const std::string kSource = CEILPLAN_SOURCE_DIR;
const std::string kVehicle = kSource + "/maps/vehicles/quad.yaml";
const std::string kGeb079 = "/usr/share/doc/liboctomap-dev/examples/data/geb079.bt";

// Proposes into `dir`/proposed.yaml, then tours it in both modes into `dir`/tour; checks what
// both say and that every region proposed is covered where it is reachable.
void proposeAndTour(const std::filesystem::path& dir, const std::string& propose_flags, std::size_t regions) {
  const auto proposed = testing::runCeilplan("propose " + propose_flags + " --vehicle " + kVehicle + " --out " +
                                             (dir / "proposed.yaml").string());
  ASSERT_EQ(proposed.exit_code, 0) << proposed.err;
  EXPECT_NE(proposed.out.find("proposed " + std::to_string(regions) + " overhead region"), std::string::npos)
      << proposed.out;
  EXPECT_NE(proposed.out.find("home ("), std::string::npos) << proposed.out;
  ASSERT_TRUE(std::filesystem::is_regular_file(dir / "proposed.svg"));
  const std::string yaml = testing::readWholeFile(dir / "proposed.yaml");
  EXPECT_EQ(yaml.rfind("# ceilplan ", 0), 0u) << "the provenance comes first";

  // No origin in a proposed mission: the tour writes its local-frame files and says what it skipped.
  const auto tour = testing::runCeilplan("tour --mission " + (dir / "proposed.yaml").string() + " --mode both --out " +
                                         (dir / "tour").string());
  ASSERT_EQ(tour.exit_code, 0) << tour.err << tour.out;
  EXPECT_NE(tour.out.find("geodetic exports skipped (mission.plan, mission.waypoints, mission.kmz, routes.kml, "
                          "routes.geojson)"),
            std::string::npos)
      << tour.out;
  for (const char* mode : {"ceiling", "free"}) {
    const nlohmann::json coverage =
        nlohmann::json::parse(testing::readWholeFile(dir / "tour" / mode / "coverage.json"));
    ASSERT_EQ(coverage["regions"].size(), regions) << mode;
    for (const nlohmann::json& region : coverage["regions"]) {
      EXPECT_GT(region["reachable_area_m2"].get<double>(), 0.0) << mode << " " << region["name"];
      EXPECT_GE(region["covered_reachable_pct"].get<double>(), 99.0) << mode << " " << region["name"];
    }
  }
}

TEST(ProposeCommand, AMissionFromTheWarehouseMapToursInBothModesWithoutEdits) {
  const auto dir = testing::scratchDirectory("propose_warehouse");
  proposeAndTour(dir, "--map " + kSource + "/maps/warehouse.bt --max-regions 2 --gsd-mm-px 4", 2);
}

// geb079's corridor: a ceiling with lamps, unscanned pockets in the air (the fill policy frees
// them, as maps/real/geb079_corridor.yaml does), and no floor scanned under much of it.
TEST(ProposeCommand, AMissionFromARealScanToursInBothModesWithoutEdits) {
  const auto dir = testing::scratchDirectory("propose_geb079");
  proposeAndTour(dir, "--map " + kGeb079 + " --unknown fill --crop -6,-2,0,10,2,3.5 --max-regions 1", 1);
  const std::string yaml = testing::readWholeFile(dir / "proposed.yaml");
  EXPECT_NE(yaml.find("unknown: {policy: fill, fill_max_m: 2}"), std::string::npos) << yaml;
}

TEST(ProposeCommand, BadInputIsRefusedBeforeAnyWorkAndLeavesNoFile) {
  const auto dir = testing::scratchDirectory("propose_bad");
  const std::string map = " --map " + kSource + "/maps/warehouse.bt --vehicle " + kVehicle;
  const struct {
    std::string arguments, says;
  } rows[] = {
      {"--map " + (dir / "none.bt").string() + " --vehicle " + kVehicle + " --out {out}", "none.bt"},
      {map + " --out " + (dir / "m.txt").string(),
       "--out " + (dir / "m.txt").string() + ": the mission file must end in .yaml or .yml"},
      {map + " --out {out} --crop 0,0,0,1,1", "--crop '0,0,0,1,1': expected six finite numbers"},
      {map + " --out {out} --crop 0,0,0,1,-1,1",
       "--crop '0,0,0,1,-1,1': a crop box's y minimum (0) must be below its maximum (-1)"},
      {map + " --out {out} --home nan,0,1", "--home 'nan,0,1': expected three finite numbers"},
      {map + " --out {out} --home 1.5,8,0", "the given home (1.50, 8.00, 0.00) is no valid position"},
      {map + " --out {out} --camera phantom5", "phantom5"},
      {map + " --out {out} --gsd-mm-px 0", "--gsd-mm-px"},
      {map + " --out {out} --max-regions 0", "--max-regions"},
      {map + " --out {out} --min-area-m2 100000", "no overhead region of at least 100000 m2"},
  };
  for (const auto& row : rows) {
    const auto result =
        testing::runCeilplan("propose " + testing::substituted(row.arguments, {{"{out}", (dir / "m.yaml").string()}}));
    EXPECT_EQ(result.exit_code, 2) << row.arguments << "\n" << result.err;
    EXPECT_NE(result.err.find(row.says), std::string::npos) << row.arguments << "\n" << result.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "m.yaml")) << row.arguments;
    EXPECT_FALSE(std::filesystem::exists(dir / "m.svg")) << row.arguments;
  }
}

}  // namespace
}  // namespace ceilplan
