// The environment's commands as a user runs them.

#include "run_command.hpp"

#include <gtest/gtest.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>

namespace ceilplan {
namespace {

const std::string kBridge = CEILPLAN_SOURCE_DIR "/maps/bridge.bt";
const std::string kVehicle = CEILPLAN_SOURCE_DIR "/maps/vehicles/quad.yaml";

TEST(ProbeCommand, UnderTheDeckReportsTheGapsAndWritesJson) {
  const auto dir = testing::scratchDirectory("probe");
  const auto result = testing::runCeilplan("probe --map " + kBridge + " --at 6,0,5.8 --vehicle " + kVehicle +
                                           " --json " + (dir / "probe.json").string());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("ceiling_gap_m: 0.1700"), std::string::npos) << result.out;
  const auto json = nlohmann::json::parse(testing::readWholeFile(dir / "probe.json"));
  EXPECT_NEAR(json["ceiling_gap_m"].get<double>(), 6.0 - 5.83, 1e-6);
  EXPECT_NEAR(json["ceiling_coverage"].get<double>(), 1.0, 1e-9);
  EXPECT_NEAR(json["ground_gap_m"].get<double>(), 5.83, 1e-6);
  EXPECT_NEAR(json["clearance_m"].get<double>(), 0.2, 1e-6);
  EXPECT_TRUE(json["valid"].get<bool>());
  EXPECT_EQ(json["rotors"].size(), 4u);
}

TEST(ProbeCommand, BadInputGivesOneLineAndExitCodeTwo) {
  for (const std::string& arguments :
       {"probe --map " + kBridge + " --at 6,0,30 --vehicle " + kVehicle,       // outside the map
        "probe --map " + kBridge + " --at 6,0 --vehicle " + kVehicle,          // two numbers
        "probe --map " + kBridge + " --at 6,nan,3 --vehicle " + kVehicle,      // not finite
        "probe --map /nonexistent.bt --at 6,0,3 --vehicle " + kVehicle,        // missing map
        "probe --map " + kBridge + " --at 6,0,3 --vehicle /nonexistent.yaml",  // missing vehicle
        "probe --map " + kVehicle + " --at 6,0,3 --vehicle " + kVehicle}) {    // not a map
    const auto result = testing::runCeilplan(arguments);
    EXPECT_EQ(result.exit_code, 2) << arguments << "\n" << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_EQ(result.err.rfind("ceilplan: error: ", 0), 0u) << result.err;
  }
}

TEST(MapinfoCommand, SummarisesTheBridge) {
  const auto dir = testing::scratchDirectory("mapinfo");
  const auto result = testing::runCeilplan("mapinfo --map " + kBridge + " --json " + (dir / "info.json").string());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto json = nlohmann::json::parse(testing::readWholeFile(dir / "info.json"));
  EXPECT_DOUBLE_EQ(json["resolution_m"].get<double>(), 0.1);
  EXPECT_NEAR(json["extent_m"]["max"][0].get<double>() - json["extent_m"]["min"][0].get<double>(), 60.0, 1e-9);
  EXPECT_GT(json["ceiling_area_share"].get<double>(), 0.3);
  EXPECT_LT(json["ceiling_area_share"].get<double>(), 0.7);
}

TEST(UnknownSpaceFlags, ProbeReportsThePolicyItApplied) {
  const auto dir = testing::scratchDirectory("probe_unknown");
  const auto result =
      testing::runCeilplan("probe --map " + kBridge + " --at 6,0,5.8 --vehicle " + kVehicle +
                           " --unknown fill --unknown-fill-max-m 0.5 --json " + (dir / "p.json").string());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("unknown: fill (pockets up to 0.5 m)"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("assumed_free: false"), std::string::npos) << result.out;
  const auto json = nlohmann::json::parse(testing::readWholeFile(dir / "p.json"));
  EXPECT_EQ(json["unknown"]["policy"], "fill");
  EXPECT_DOUBLE_EQ(json["unknown"]["fill_max_m"].get<double>(), 0.5);
  EXPECT_GT(json["unknown"]["unknown_volume_m3"].get<double>(), 100.0);     // above the deck, unseen from below
  EXPECT_EQ(json["unknown"]["assumed_free_volume_m3"].get<double>(), 0.0);  // it reaches the map's edge
  EXPECT_FALSE(json["assumed_free"].get<bool>());
  EXPECT_FALSE(json["point_assumed_free"].get<bool>());

  const auto bold = testing::runCeilplan("probe --map " + kBridge + " --at 6,0,6.5 --vehicle " + kVehicle +
                                         " --unknown free --json " + (dir / "free.json").string());
  ASSERT_EQ(bold.exit_code, 0) << bold.err;
  const auto free = nlohmann::json::parse(testing::readWholeFile(dir / "free.json"));
  EXPECT_EQ(free["unknown"]["policy"], "free");
  EXPECT_TRUE(free["unknown"]["fill_max_m"].is_null());
  EXPECT_TRUE(free["point_assumed_free"].get<bool>());  // above the deck
}

TEST(UnknownSpaceFlags, BadValuesGiveOneLineNamingTheFlag) {
  const std::string probe = "probe --map " + kBridge + " --at 6,0,3 --vehicle " + kVehicle;
  const struct {
    std::string arguments;
    int exit_code;
    std::string says;
  } cases[] = {
      {probe + " --unknown maybe", 2, "--unknown"},
      {probe + " --unknown fill --unknown-fill-max-m -1", 2, "--unknown-fill-max-m"},
      {probe + " --unknown fill --unknown-fill-max-m nan", 2, "--unknown-fill-max-m"},
      {probe + " --unknown-fill-max-m 0.5", 2, "applies only to --unknown fill"},
      {probe + " --unknown-free", 2, "--unknown-free"},  // the old switch: replaced by --unknown free
      {"mapinfo --map " + kBridge + " --unknown sometimes", 2, "--unknown"},
  };
  for (const auto& c : cases) {
    const auto result = testing::runCeilplan(c.arguments);
    EXPECT_EQ(result.exit_code, c.exit_code) << c.arguments << "\n" << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_NE(result.err.find(c.says), std::string::npos) << result.err;
  }
}

TEST(MapinfoCommand, ReportsThePolicyAndWritesASlice) {
  const auto dir = testing::scratchDirectory("mapinfo_slice");
  const auto result =
      testing::runCeilplan("mapinfo --map " + kBridge + " --unknown free --json " + (dir / "info.json").string() +
                           " --slice-z 6.5 --slice-csv " + (dir / "slice.csv").string() + " --vehicle " + kVehicle);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("unknown: free: "), std::string::npos) << result.out;
  const auto json = nlohmann::json::parse(testing::readWholeFile(dir / "info.json"));
  EXPECT_EQ(json["unknown"]["policy"], "free");
  EXPECT_NEAR(json["unknown"]["assumed_free_volume_m3"].get<double>(), json["volume_m3"]["unknown"].get<double>(),
              1e-6);
  const std::string slice = testing::readWholeFile(dir / "slice.csv");
  EXPECT_EQ(slice.rfind("# ceilplan ", 0), 0u) << "the provenance comment first: " << slice.substr(0, 80);
  EXPECT_NE(slice.find("\nx_m,y_m,state,under_ceiling,valid,assumes_free\n"), std::string::npos);
  EXPECT_EQ(std::count(slice.begin(), slice.end(), '\n'), 2 + 600 * 200);
  EXPECT_NE(slice.find(",assumed_free,"), std::string::npos);  // above the deck
  EXPECT_NE(slice.find(",free,"), std::string::npos);          // beside the deck
  const auto outside =
      testing::runCeilplan("mapinfo --map " + kBridge + " --slice-z 9 --slice-csv " + (dir / "x.csv").string());
  EXPECT_EQ(outside.exit_code, 2);  // bad input (docs/cli.md)
  EXPECT_NE(outside.err.find("--slice-z 9 lies outside the map"), std::string::npos) << outside.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.csv"));
}

TEST(MapgenCommand, BuildsALongerBridgeAndRefusesALengthElsewhere) {
  const auto dir = testing::scratchDirectory("mapgen_length");
  const auto result =
      testing::runCeilplan("mapgen --scene bridge --bridge-length-m 96 --out " + (dir / "b.bt").string());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("scene bridge, length 96 m, resolution 0.1 m, seed 1: 1080 x 200 x 74 voxels"),
            std::string::npos)
      << result.out;
  const auto info =
      testing::runCeilplan("mapinfo --map " + (dir / "b.bt").string() + " --json " + (dir / "b.json").string());
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const auto json = nlohmann::json::parse(testing::readWholeFile(dir / "b.json"));
  EXPECT_NEAR(json["extent_m"]["max"][0].get<double>(), 102.0, 1e-9);
  EXPECT_NEAR(json["ceiling_area_share"].get<double>(), 0.5, 0.1);  // the deck over 96 of the 108 m
  for (const char* bad : {"--scene bridge --bridge-length-m 50", "--scene tunnel --bridge-length-m 96",
                          "--scene bridge --bridge-length-m 8"}) {
    const auto refused = testing::runCeilplan(std::string("mapgen ") + bad + " --out " + (dir / "x.bt").string());
    EXPECT_EQ(refused.exit_code, 2) << bad;
    EXPECT_NE(refused.err.find("bridge length"), std::string::npos) << refused.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.bt"));
  }
}

TEST(MapgenCommand, RefusesAnUnknownSceneAndLeavesNoFile) {
  const auto dir = testing::scratchDirectory("mapgen");
  const auto result = testing::runCeilplan("mapgen --scene castle --out " + (dir / "x.bt").string());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("unknown scene"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.bt"));
}

}  // namespace
}  // namespace ceilplan
