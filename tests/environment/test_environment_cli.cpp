// The environment's commands as a user runs them.

#include "run_command.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

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
       {"probe --map " + kBridge + " --at 6,0,30 --vehicle " + kVehicle,            // outside the map
        "probe --map " + kBridge + " --at 6,0 --vehicle " + kVehicle,               // two numbers
        "probe --map " + kBridge + " --at 6,nan,3 --vehicle " + kVehicle,           // not finite
        "probe --map /nonexistent.bt --at 6,0,3 --vehicle " + kVehicle,             // missing map
        "probe --map " + kBridge + " --at 6,0,3 --vehicle /nonexistent.yaml",       // missing vehicle
        "probe --map " + kVehicle + " --at 6,0,3 --vehicle " + kVehicle}) {         // not a map
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

TEST(MapgenCommand, RefusesAnUnknownSceneAndLeavesNoFile) {
  const auto dir = testing::scratchDirectory("mapgen");
  const auto result = testing::runCeilplan("mapgen --scene castle --out " + (dir / "x.bt").string());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("unknown scene"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.bt"));
}

}  // namespace
}  // namespace ceilplan
