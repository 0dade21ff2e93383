// `ceilplan current` and `ceilplan calibrate` as a user runs them.

#include "run_command.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>

using ceilplan::testing::readWholeFile;
using ceilplan::testing::runCeilplan;
using ceilplan::testing::scratchDirectory;

namespace {

const std::string kQuad = std::string(CEILPLAN_SOURCE_DIR) + "/maps/vehicles/quad.yaml";
const std::string kPublishedData = std::string(CEILPLAN_SOURCE_DIR) + "/maps/calibration/published-ceiling-hover.csv";

nlohmann::json currentJson(const std::string& arguments, const std::string& test) {
  const auto json_path = scratchDirectory(test) / "current.json";
  const auto result = runCeilplan("current " + arguments + " --json " + json_path.string());
  EXPECT_EQ(result.exit_code, 0) << result.err;
  return nlohmann::json::parse(readWholeFile(json_path));
}

void writeFile(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

// Exit `exit_code` (2: bad input; docs/cli.md) with one line on stderr that contains `needle`.
void expectOneLineError(const std::string& arguments, const std::string& needle, int exit_code = 2) {
  const auto result = runCeilplan(arguments);
  EXPECT_EQ(result.exit_code, exit_code) << arguments;
  EXPECT_NE(result.err.find(needle), std::string::npos) << arguments << "\n" << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
}

class CurrentCommand : public ::testing::Test {};
using CalibrateCommand = CurrentCommand;

}  // namespace

TEST_F(CurrentCommand, ShippedVehicleFileReproducesThePapersCurrents) {
  EXPECT_NEAR(currentJson("--vehicle " + kQuad, "free")["current_a"].get<double>(), 9.5, 1e-9);
  EXPECT_NEAR(currentJson("--vehicle " + kQuad + " --gap-m 0.05", "ceiling")["current_a"].get<double>(), 8.0, 1e-9);
  EXPECT_NEAR(currentJson("--gap-m 0.05", "builtin")["current_a"].get<double>(), 8.0, 1e-9);
}

TEST_F(CurrentCommand, PrintsCurrentPowerAndTheBreakdown) {
  const auto result = runCeilplan("current --gap-m 0.05 --ground-gap-m 0.5 --speed-m-s 3 --climb-m-s 0.2 --soc 0.8");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const char* key : {"current_a", "power_w", "induced_w", "profile_w", "parasitic_w", "climb_w", "avionics_w",
                          "ceiling_factor", "ground_factor"})
    EXPECT_NE(result.out.find(key), std::string::npos) << key;
}

TEST_F(CurrentCommand, SweepRunsFromContactToThreeRadiiAndEndsInFreeAir) {
  const nlohmann::json report = currentJson("--sweep", "sweep");
  const auto& rows = report["sweep"];
  ASSERT_EQ(rows.size(), 61u);
  EXPECT_DOUBLE_EQ(rows.front()["gap_m"].get<double>(), 0.0);
  EXPECT_NEAR(rows.back()["gap_m"].get<double>(), 3.0 * 0.127, 1e-12);
  EXPECT_NEAR(rows.back()["current_a"].get<double>(), report["free_air_current_a"].get<double>(), 1e-12);
  for (std::size_t i = 1; i < rows.size(); ++i)
    EXPECT_GE(rows[i]["current_a"].get<double>(), rows[i - 1]["current_a"].get<double>());
}

TEST_F(CurrentCommand, RefusesBadInputWithOneLine) {
  expectOneLineError("current --gap-m -0.1", "negative");
  expectOneLineError("current --gap-m nan", "not a number");
  expectOneLineError("current --speed-m-s 40", "max_speed_m_s");
  expectOneLineError("current --soc 1.5", "outside [0, 1]");
  expectOneLineError("current --coverage 2", "coverage");
  expectOneLineError("current --vehicle /nonexistent/vehicle.yaml", "/nonexistent/vehicle.yaml: no such vehicle file");
}

TEST_F(CurrentCommand, RefusesVehicleFilesWithoutRotorsOrWithNegativeMass) {
  const auto dir = scratchDirectory("bad_vehicles");
  writeFile(dir / "no_rotors.yaml", "name: x\nmass_kg: 1.0\n");
  writeFile(dir / "zero_rotors.yaml", "mass_kg: 1.0\nrotors:\n  count: 0\n  radius_m: 0.1\n");
  std::string negative_mass = readWholeFile(kQuad);
  negative_mass.replace(negative_mass.find("mass_kg: 1.4"), 12, "mass_kg: -1.0");
  writeFile(dir / "negative_mass.yaml", negative_mass);
  writeFile(dir / "typo.yaml", readWholeFile(kQuad) + "  hover_curent_a: 9\n");
  expectOneLineError("current --vehicle " + (dir / "no_rotors.yaml").string(), "missing key 'rotors'");
  expectOneLineError("current --vehicle " + (dir / "zero_rotors.yaml").string(), "rotors.count");
  expectOneLineError("current --vehicle " + (dir / "negative_mass.yaml").string(),
                     "'mass_kg' must be in (0, 200] kg, got -1");
  expectOneLineError("current --vehicle " + (dir / "typo.yaml").string(),
                     "unknown key 'power.hover_curent_a'; did you mean 'hover_current_a'?");
}

TEST_F(CalibrateCommand, FitsThePublishedDataAndWritesAVehicleFileThatCurrentReads) {
  const auto dir = scratchDirectory("calibrate_published");
  const auto out = dir / "calibrated.yaml";
  const auto result = runCeilplan("calibrate --data " + kPublishedData + " --vehicle " + kQuad + " --out " +
                                  out.string() + " --json " + (dir / "fit.json").string());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("rmse_a"), std::string::npos);
  const nlohmann::json fit = nlohmann::json::parse(readWholeFile(dir / "fit.json"));
  ASSERT_EQ(fit["fitted"].size(), 3u);
  for (const auto& parameter : fit["fitted"]) {
    EXPECT_LE(parameter["allowed_min"].get<double>(), parameter["value"].get<double>());
    EXPECT_LE(parameter["value"].get<double>(), parameter["allowed_max"].get<double>());
  }
  // The written file keeps the geometry keys and gives the fitted model back.
  EXPECT_NE(readWholeFile(out).find("airframe:"), std::string::npos);
  const double free_air = currentJson("--vehicle " + out.string(), "calibrated")["current_a"].get<double>();
  EXPECT_NEAR(free_air, 9.5, 3.0 * fit["rmse_a"].get<double>());
}

TEST_F(CalibrateCommand, RecoversTheShippedVehicleFromItsOwnPredictions) {
  const auto dir = scratchDirectory("calibrate_roundtrip");
  std::string csv = "gap_m,soc,current_a\n";
  for (double gap : {-1.0, 0.0, 0.01, 0.03, 0.05, 0.08, 0.12, 0.2})
    for (double soc : {0.9, 0.5}) {
      const std::string gap_flag = gap < 0 ? "" : " --gap-m " + std::to_string(gap);
      const double current =
          currentJson("--vehicle " + kQuad + gap_flag + " --soc " + std::to_string(soc), "roundtrip_point")["current_a"]
              .get<double>();
      char row[96];
      std::snprintf(row, sizeof row, "%s,%.3f,%.12f\n", gap < 0 ? "none" : std::to_string(gap).c_str(), soc, current);
      csv += row;
    }
  writeFile(dir / "data.csv", csv);
  EXPECT_EQ(runCeilplan("calibrate --data " + (dir / "data.csv").string() + " --fit hover_power_w,k1,k2_m --out " +
                        (dir / "v.yaml").string() + " --json " + (dir / "fit.json").string())
                .exit_code,
            0);
  const nlohmann::json fit = nlohmann::json::parse(readWholeFile(dir / "fit.json"));
  EXPECT_LT(fit["rmse_a"].get<double>(), 1e-6);
  for (const auto& parameter : fit["fitted"])
    EXPECT_NEAR(parameter["value"].get<double>(), parameter["start"].get<double>(),
                1e-3 * parameter["start"].get<double>())
        << parameter["parameter"];
}

TEST_F(CalibrateCommand, RefusesWhatTheDataCannotIdentifyAndWritesNothing) {
  const auto dir = scratchDirectory("calibrate_refusals");
  writeFile(dir / "hover.csv", "gap_m,current_a\nnone,9.5\nnone,9.6\n0.05,8.0\n0.02,7.0\n");
  const auto out = dir / "v.yaml";
  expectOneLineError(
      "calibrate --data " + (dir / "hover.csv").string() + " --fit motor_efficiency --out " + out.string(),
      "cannot identify motor_efficiency");
  writeFile(dir / "bad.csv", "gap_m,current_a\nnone,9.5\n0.05,eight\n");
  expectOneLineError("calibrate --data " + (dir / "bad.csv").string() + " --out " + out.string(), "line 3");
  writeFile(dir / "unknown.csv", "gap,current_a\n0.05,8\n");
  expectOneLineError("calibrate --data " + (dir / "unknown.csv").string() + " --out " + out.string(),
                     "unknown column 'gap'");
  expectOneLineError("calibrate --data " + (dir / "hover.csv").string() + " --fit k3 --out " + out.string(),
                     "unknown calibration parameter 'k3'");
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST_F(CalibrateCommand, AFailedFitSaysWhatFailedAndWhatToDo) {
  // A failed fit is a runtime failure (exit 1), said in words: NLopt alone says "nlopt failure".
  const auto dir = scratchDirectory("calibrate_failed_fit");
  writeFile(dir / "outlier.csv", "gap_m,current_a\nnone,9.5\n0.05,1e200\n0.1,9.0\n0.3,9.4\n0.5,9.5\n");
  const auto out = dir / "v.yaml";
  expectOneLineError("calibrate --data " + (dir / "outlier.csv").string() + " --out " + out.string(),
                     "squared errors overflow: current_a reaches 1e+200 A; give every current in amperes", 1);
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST_F(CalibrateCommand, EchoesNoRawBytesFromABadFile) {
  const auto dir = scratchDirectory("calibrate_escapes");
  writeFile(dir / "evil.csv", "gap_m,current_a\nnone,\x1b]0;owned\x07\n");
  const auto result =
      runCeilplan("calibrate --data " + (dir / "evil.csv").string() + " --out " + (dir / "v.yaml").string());
  EXPECT_NE(result.exit_code, 0);
  EXPECT_NE(result.err.find("'\\x1B]0;owned\\x07' is not a number"), std::string::npos) << result.err;
  EXPECT_EQ(result.err.find('\x1b'), std::string::npos) << "raw escape echoed";
}

namespace {

// The lines `current` prints from "ceiling gap" on: the current and its parts, not the condition.
std::string printedBreakdown(const std::string& arguments) {
  const auto result = runCeilplan("current " + arguments);
  EXPECT_EQ(result.exit_code, 0) << arguments << "\n" << result.err;
  const std::size_t start = result.out.find("ceiling gap");
  EXPECT_NE(start, std::string::npos) << result.out;
  return start == std::string::npos ? result.out : result.out.substr(start);
}

}  // namespace

// No ceiling and no ground gap: the proximity terms are off, so only the airspeed differs.
TEST_F(CurrentCommand, AHeadwindPrintsTheCurrentOfFlyingThatMuchFasterInStillAir) {
  for (const auto& [speed, headwind, sum] : {std::tuple{"3", "4", "7"}, std::tuple{"0", "5", "5"},
                                             std::tuple{"6", "-2.5", "3.5"}, std::tuple{"0", "8", "8"}}) {
    const std::string windy = printedBreakdown(std::string("--speed-m-s ") + speed + " --headwind-m-s " + headwind);
    EXPECT_EQ(windy, printedBreakdown(std::string("--speed-m-s ") + sum))
        << speed << " m/s into " << headwind << " m/s against " << sum << " m/s in still air";
    EXPECT_NE(windy, printedBreakdown(std::string("--speed-m-s ") + speed)) << "the wind changed nothing";
  }
}

TEST_F(CurrentCommand, ShowsTheHeadwindAndAirspeedOnlyWhenThereIsWind) {
  const auto windy = runCeilplan("current --speed-m-s 2 --headwind-m-s 3");
  EXPECT_NE(windy.out.find("headwind 3 m/s (airspeed 5 m/s)"), std::string::npos) << windy.out;
  EXPECT_EQ(runCeilplan("current --speed-m-s 2").out.find("headwind"), std::string::npos);
  const nlohmann::json report = currentJson("--speed-m-s 2 --headwind-m-s -1.5", "tailwind");
  EXPECT_DOUBLE_EQ(report["airspeed_m_s"].get<double>(), 0.5) << report.dump();
}

TEST_F(CurrentCommand, RefusesAHeadwindThatIsNoNumberOrTakesTheAirspeedBeyondTheLimit) {
  expectOneLineError("current --headwind-m-s nan", "--headwind-m-s");
  expectOneLineError("current --headwind-m-s 1e9", "--headwind-m-s");
  expectOneLineError("current --speed-m-s 10 --headwind-m-s 10", "airspeed 20 m/s");
}
