// Mission files: every shipped mission parses, and each kind of bad file fails with one line
// naming the file and the key.

#include "ceilplan/core/error.hpp"
#include "ceilplan/io/flag_file.hpp"
#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/io/vehicle_file.hpp"

#include "run_command.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <vector>

namespace ceilplan::io {
namespace {

const std::filesystem::path kMaps = std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps";

TEST(MissionFile, EveryShippedMissionParses) {
  int missions = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kMaps)) {
    if (entry.path().extension() != ".yaml") continue;
    ++missions;
    const mission::Mission mission = readMission(entry.path());
    EXPECT_TRUE(std::filesystem::is_regular_file(mission.map_file)) << entry.path();
    EXPECT_TRUE(std::filesystem::is_regular_file(mission.vehicle_file)) << entry.path();
    EXPECT_GE(mission.targets.size(), 8u) << entry.path();
    EXPECT_TRUE(mission.origin.has_value()) << entry.path();
    EXPECT_LT(mission.battery.reserve_soc, mission.battery.start_soc);
  }
  EXPECT_EQ(missions, 4);
}

TEST(MissionFile, ReadsEveryKeyOfTheBridgeMission) {
  const mission::Mission mission = readMission(kMaps / "bridge.yaml");
  EXPECT_EQ(mission.map_file, kMaps / "bridge.bt");
  EXPECT_EQ(mission.vehicle_file, kMaps / "vehicles/quad.yaml");
  EXPECT_DOUBLE_EQ(mission.battery.pack.capacity_ah, 5.2);
  EXPECT_DOUBLE_EQ(mission.battery.pack.charge_current_a, 10.4);
  EXPECT_DOUBLE_EQ(mission.battery.start_soc, 0.95);
  EXPECT_DOUBLE_EQ(mission.battery.reserve_soc, 0.25);
  EXPECT_EQ(mission.home_m, Eigen::Vector3d(-4.0, 0.0, 0.5));
  EXPECT_DOUBLE_EQ(mission.requireOrigin().latitude_deg, 52.218);
  EXPECT_DOUBLE_EQ(mission.requireOrigin().longitude_deg, 0.0923);
  EXPECT_DOUBLE_EQ(mission.requireOrigin().altitude_m, 12.0);
  EXPECT_DOUBLE_EQ(mission.planning.speeds.cruise_m_s, 2.0);
  EXPECT_DOUBLE_EQ(mission.planning.speeds.inspection_m_s, 0.5);
  EXPECT_DOUBLE_EQ(mission.planning.speeds.climb_m_s, 1.0);
  EXPECT_DOUBLE_EQ(mission.planning.speeds.descent_m_s, 0.8);
  EXPECT_EQ(mission.mode, "ceiling");
  EXPECT_EQ(mission.planning.seed, 1u);
  ASSERT_EQ(mission.targets.size(), 13u);
  EXPECT_EQ(mission.targets[0].name, "deck_bay_06");
  EXPECT_EQ(mission.targets[0].point_m, Eigen::Vector3d(6.0, 0.0, 6.0));
  EXPECT_DOUBLE_EQ(mission.targets[0].dwell_s, 20);
  EXPECT_DOUBLE_EQ(mission.targets[0].standoff_min_m, 0.3);
  EXPECT_DOUBLE_EQ(mission.targets[0].standoff_max_m, 1.5);
}

// The bridge mission with `from` replaced by `to`, its paths made absolute so it can live in the
// scratch directory.
std::filesystem::path variant(const std::string& name, const std::string& from, const std::string& to) {
  std::string text = testing::readWholeFile(kMaps / "bridge.yaml");
  auto replace = [&text](const std::string& a, const std::string& b) {
    const std::size_t at = text.find(a);
    if (at == std::string::npos) throw std::logic_error("test variant: '" + a + "' not in bridge.yaml");
    text.replace(at, a.size(), b);
  };
  replace("map: bridge.bt", "map: " + (kMaps / "bridge.bt").string());
  replace("vehicle: vehicles/quad.yaml", "vehicle: " + (kMaps / "vehicles/quad.yaml").string());
  if (!from.empty()) replace(from, to);
  const std::filesystem::path file = testing::scratchDirectory("mission_" + name) / "mission.yaml";
  std::ofstream(file) << text;
  return file;
}

std::string errorOf(const std::filesystem::path& file) {
  try {
    readMission(file);
  } catch (const ceilplan::InputError& e) {
    return e.what();
  }
  return "no error";
}

void expectError(const std::string& name, const std::string& from, const std::string& to, const std::string& expected) {
  const std::filesystem::path file = variant(name, from, to);
  const std::string message = errorOf(file);
  EXPECT_NE(message.find(file.string() + ": "), std::string::npos) << message;
  EXPECT_NE(message.find(expected), std::string::npos) << name << ": " << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(MissionFile, TheUnchangedVariantParses) { EXPECT_EQ(errorOf(variant("unchanged", "", "")), "no error"); }

TEST(MissionFile, BadVariantsNameTheKey) {
  const std::string map_line = "map: " + (kMaps / "bridge.bt").string();
  expectError("missing_map", map_line, "", "missing key 'map'");
  expectError("absent_map", map_line, "map: nowhere.bt", "'map' names");
  expectError("reserve_above_start", "reserve_soc: 0.25", "reserve_soc: 0.97",
              "'battery.reserve_soc' 0.97 is not below 'battery.start_soc' 0.95");
  expectError("nan_capacity", "capacity_ah: 5.2", "capacity_ah: .nan", "'battery.capacity_ah' must be a finite number");
  expectError("negative_capacity", "capacity_ah: 5.2", "capacity_ah: -5.2",
              "'battery.capacity_ah' must be in [0.01, 1000] Ah, got -5.2");
  expectError("huge_capacity", "capacity_ah: 5.2", "capacity_ah: 5e9",
              "'battery.capacity_ah' must be in [0.01, 1000] Ah");
  expectError("text_capacity", "capacity_ah: 5.2", "capacity_ah: lots", "'battery.capacity_ah' must be a number");
  expectError("soc_over_one", "start_soc: 0.95", "start_soc: 1.5", "'battery.start_soc' must be in (0, 1], got 1.5");
  expectError("missing_charge", "charge_current_a: 10.4", "", "missing key 'battery.charge_current_a'");
  expectError("duplicate_target", "name: deck_bay_14_north", "name: deck_bay_06",
              "duplicate target name 'deck_bay_06' at 'targets[1]'");
  expectError("nan_point", "point: [6.0, 0.0, 6.0]", "point: [6.0, .nan, 6.0]",
              "'targets[0].point[1]' must be a finite");
  expectError("short_point", "point: [6.0, 0.0, 6.0]", "point: [6.0, 0.0]", "'targets[0].point' must be [x, y, z]");
  expectError("negative_dwell", "dwell_s: 20", "dwell_s: -20", "'targets[0].dwell_s' must be in [0, 3600] s, got -20");
  expectError("inverted_standoff", "standoff_m: [0.3, 1.5]", "standoff_m: [1.5, 0.3]", "standoff range");
  expectError("home_missing", "home: [-4.0, 0.0, 0.5]", "", "missing key 'home'");
  expectError("bad_latitude", "lat: 52.218", "lat: 152.218", "'origin.lat' must be in [-90, 90] deg, got 152.218");
  expectError("negative_speed", "cruise_m_s: 2.0", "cruise_m_s: -2.0", "'speeds.cruise_m_s' must be in [0.01, 15] m/s");
  expectError("climb_beyond_physics", "climb_m_s: 1.0", "climb_m_s: 100",
              "'speeds.climb_m_s' must be in [0.01, 10] m/s");
  expectError("negative_seed", "seed: 1", "seed: -1", "'seed' must be a whole number in [1, 4294967295], got '-1'");
  expectError("bad_mode", "mode: ceiling", "mode: min-wear",
              "'mode' must be one of ceiling, free, both, got 'min-wear'");
  expectError("no_targets", "targets:", "targets: []\nignored_targets:", "unknown key 'ignored_targets'");
  expectError("bad_yaml", "home: [-4.0, 0.0, 0.5]", "home: [-4.0, 0.0", "malformed YAML");
  EXPECT_NE(errorOf(kMaps / "nowhere.yaml").find("no such mission file"), std::string::npos);
}

// What yaml-cpp would let through: a second document (Load reads the first only), a repeated key
// (it answers with one of the values), and a speed so small that a route's time overflows.
TEST(MissionFile, NothingIsIgnoredOrAcceptedSilently) {
  expectError("second_document", "seed: 1", "seed: 1\n---\nseed: 2",
              "holds 2 YAML documents (split by '---'); a mission file is one document");
  expectError("key_twice", "seed: 1", "seed: 1\nseed: 2", "key 'seed' is given twice");
  expectError("key_twice_in_a_section", "cruise_m_s: 2.0", "cruise_m_s: 2.0, cruise_m_s: 3.0",
              "key 'speeds.cruise_m_s' is given twice");
  expectError("tiny_inspection_speed", "inspection_m_s: 0.5", "inspection_m_s: 1e-300",
              "'speeds.inspection_m_s' must be in [0.01, 15] m/s (the vehicle's max_speed_m_s), got 1e-300");
  expectError("map_is_a_device", "map: " + (kMaps / "bridge.bt").string(), "map: /dev/zero",
              "'map' names /dev/zero: is a device, not a file; give a regular file");
}

TEST(MissionFile, AnUnknownKeyIsAnErrorNamingTheNearestValidKey) {
  // Typos must never fall back to a default silently.
  expectError("typo_capacity", "capacity_ah: 5.2", "capacity_a: 5.2",
              "unknown key 'battery.capacity_a'; did you mean 'capacity_ah'?");
  expectError("typo_top_level", "home: [-4.0, 0.0, 0.5]", "hone: [-4.0, 0.0, 0.5]",
              "unknown key 'hone'; did you mean 'home'?");
  expectError("typo_target", "dwell_s: 20, standoff_m: [0.3, 1.5]}", "dwel_s: 20, standoff_m: [0.3, 1.5]}",
              "unknown key 'targets[0].dwel_s'; did you mean 'dwell_s'?");
  expectError("typo_speed", "cruise_m_s: 2.0", "cruse_m_s: 2.0",
              "unknown key 'speeds.cruse_m_s'; did you mean 'cruise_m_s'?");
}

TEST(MissionFile, ATourNeedsTargets) {
  const std::filesystem::path file = variant("empty_targets", "", "");
  std::string text = testing::readWholeFile(file);
  text = text.substr(0, text.find("targets:")) + "targets: []\n";
  std::ofstream(file) << text;
  EXPECT_NE(errorOf(file).find("'targets' must be a non-empty list"), std::string::npos) << errorOf(file);
}

TEST(MissionFile, EveryTargetNeedsAName) {
  expectError("empty_name", "name: deck_bay_06", "name: ''", "'targets[0].name' is empty");
}

TEST(BatteryFile, AFileOfAnotherKindSaysWhatItIs) {
  try {
    readBattery(kMaps / "vehicles/quad.yaml");
    FAIL() << "a vehicle file was read as a battery file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("this is a vehicle file, not a battery file"), std::string::npos) << e.what();
  }
  try {
    readVehicle(kMaps / "bridge.yaml");
    FAIL() << "a mission file was read as a vehicle file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("this is a mission file, not a vehicle file"), std::string::npos) << e.what();
  }
}

TEST(BatteryFile, AMissionFileServesAsABatteryFile) {
  const mission::BatterySpec battery = readBattery(kMaps / "bridge.yaml");
  EXPECT_DOUBLE_EQ(battery.pack.capacity_ah, 5.2);
  EXPECT_DOUBLE_EQ(battery.reserve_soc, 0.25);
}

TEST(BatteryFile, NoFileMeansThePapersPack) {
  const mission::BatterySpec paper = readBatteryOrDefault({});
  EXPECT_EQ(paper.description, mission::BatterySpec{}.description);
  EXPECT_DOUBLE_EQ(paper.start_soc, 0.95);
  EXPECT_DOUBLE_EQ(readBatteryOrDefault(kMaps / "bridge.yaml").reserve_soc, 0.25);
  EXPECT_THROW(readBatteryOrDefault(kMaps / "missing.yaml"), InputError);
}

TEST(BatteryFile, UnknownKeysAndOutOfRangeNumbersAreRefused) {
  const std::filesystem::path dir = testing::scratchDirectory("battery_files");
  const auto errorFor = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    try {
      readBattery(dir / name);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(errorFor("typo.yaml", "capacity_a: 3.0\n").find("unknown key 'capacity_a'; did you mean 'capacity_ah'?"),
            std::string::npos);
  EXPECT_NE(errorFor("health.yaml", "state_of_health: 1.5\n").find("'state_of_health' must be in (0, 1], got 1.5"),
            std::string::npos);
  EXPECT_NE(errorFor("cells.yaml", "cell_count: 4.5\n").find("'cell_count' must be a whole number in [1, 24]"),
            std::string::npos);
  EXPECT_EQ(errorFor("fine.yaml", "capacity_ah: 3.0\nstart_soc: 0.9\n"), "no error");
  std::filesystem::create_directories(dir / "folder.yaml");
  EXPECT_NE(errorFor("folder.yaml", "").find("is a directory, not a battery file"), std::string::npos);
  EXPECT_NE(errorFor("twice.yaml", "capacity_ah: 3.0\ncapacity_ah: 4.0\n").find("key 'capacity_ah' is given twice"),
            std::string::npos);
  EXPECT_NE(errorFor("two.yaml", "capacity_ah: 3.0\n---\ncapacity_ah: 4.0\n")
                .find("two.yaml: holds 2 YAML documents (split by '---'); a battery file is one document"),
            std::string::npos);
}

// The energy model flies the vehicle's pack: a battery of another cell count (a 6S pack given
// for the 4S quadrotor) would be planned at 4S without a word, so it is refused, naming both
// files and both counts. A battery that leaves the count out takes the vehicle's.
TEST(BatteryFile, ACellCountThatIsNotTheVehiclesIsRefusedNamingBothFiles) {
  const std::filesystem::path vehicle_file = kMaps / "vehicles/quad.yaml";
  const mission::Vehicle quad = readVehicle(vehicle_file);
  ASSERT_EQ(quad.energy.pack.cell_count, 4);
  const std::filesystem::path dir = testing::scratchDirectory("battery_cells");
  std::ofstream(dir / "six.yaml") << "capacity_ah: 5.2\ncell_count: 6\n";
  try {
    readBattery(dir / "six.yaml", quad, vehicle_file);
    FAIL() << "a 6S battery for a 4S vehicle was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find((dir / "six.yaml").string() + ": 'cell_count' is 6 cells, but " + vehicle_file.string() +
                           " has a 4-cell pack"),
              std::string::npos)
        << message;
  }
  std::ofstream(dir / "four.yaml") << "capacity_ah: 5.2\ncell_count: 4\n";
  EXPECT_EQ(readBattery(dir / "four.yaml", quad, vehicle_file).pack.cell_count, 4);
  std::ofstream(dir / "unsaid.yaml") << "capacity_ah: 5.2\n";
  mission::Vehicle hexa = quad;
  hexa.energy.pack.cell_count = 6;
  EXPECT_EQ(readBattery(dir / "unsaid.yaml", hexa).pack.cell_count, 6);
  EXPECT_EQ(readBatteryOrDefault({}, hexa).pack.cell_count, 6);

  // In a mission file the battery section is checked against the mission's vehicle.
  const std::filesystem::path mission = variant("six_cells", "capacity_ah: 5.2", "capacity_ah: 5.2\n  cell_count: 6");
  try {
    readMission(mission);
    FAIL() << "a mission with a 6S battery for its 4S vehicle was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(mission.string() + ": 'battery.cell_count' is 6 cells, but " + vehicle_file.string() +
                           " has a 4-cell pack"),
              std::string::npos)
        << message;
  }
}

TEST(MissionFile, MissingOriginIsAnErrorOnlyWhenExporting) {
  const std::filesystem::path file = variant("no_origin", "origin: {lat: 52.218, lon: 0.0923, alt: 12.0}", "");
  const mission::Mission mission = readMission(file);
  EXPECT_FALSE(mission.origin.has_value());
  try {
    mission.requireOrigin();
    FAIL() << "expected an error";
  } catch (const ceilplan::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing key 'origin'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("needed to export to an autopilot"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ceilplan::io

namespace ceilplan::io {
namespace {

// yaml-cpp 0.7's LoadAll never returned on these (fuzz-vehicle-yaml, fuzz-mission-yaml and
// fuzz-flag-file, docs/fuzzing.md): each reader now refuses them in words, at once (a hang fails the test by
// ctest's timeout).
TEST(YamlFiles, TheFuzzersHangsAreRefusedInWords) {
  const std::filesystem::path dir = std::filesystem::path(CEILPLAN_SOURCE_DIR) / "tests/io/fuzz_regressions_yaml";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::filesystem::path& file = entry.path();
    for (const auto& read : std::vector<std::function<void()>>{[&] { readMission(file); }, [&] { readVehicle(file); },
                                                               [&] { readBattery(file); }}) {
      try {
        read();
        ADD_FAILURE() << file << " was read";
      } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(file.string() + ": ", 0), 0u) << e.what();
      }
    }
    std::ifstream config(file);
    EXPECT_THROW(readFlagFile(config, {"days"}, "duty"), InputError) << file;
    ++files;
  }
  EXPECT_EQ(files, 3);
}

}  // namespace
}  // namespace ceilplan::io
