// `ceilplan duty` as a user runs it: the paper's table by default, JSON and CSV outputs,
// YAML configs, and one clear line with a non-zero exit for bad input.

#include "run_command.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

namespace ceilplan::testing {
namespace {

TEST(CliDuty, WithNoArgumentsReproducesThePapersTable) {
  const CommandResult r = runCeilplan("duty");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("34.1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("43.7"), std::string::npos);
  EXPECT_NE(r.out.find("43.50"), std::string::npos);
  EXPECT_NE(r.out.find("40.50"), std::string::npos);
  EXPECT_NE(r.out.find("274.04"), std::string::npos);
  EXPECT_NE(r.out.find("230.77"), std::string::npos);
  EXPECT_NE(r.out.find("15.79"), std::string::npos);
}

TEST(CliDuty, JsonHoldsOneObjectPerCaseWithTheDocumentedKeys) {
  const auto dir = scratchDirectory("duty_json");
  const CommandResult r = runCeilplan("duty --dt-s 0 --json " + (dir / "duty.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(readWholeFile(dir / "duty.json"));
  ASSERT_EQ(j["cases"].size(), 2u);
  const auto& ceiling = j["cases"][1];
  EXPECT_DOUBLE_EQ(ceiling["flight_current_a"].get<double>(), 8.0);
  EXPECT_NEAR(ceiling["min_soc"].get<double>(), 0.95 - 8.0 / 3.0 / 5.2, 1e-12);
  EXPECT_NEAR(ceiling["charge_end_min"].get<double>(), 25.0 + 8.0 * 20.0 / 10.4, 1e-9);
  EXPECT_NEAR(ceiling["fec_per_mission"].get<double>(), 8.0 / 3.0 / 5.2, 1e-9);
  EXPECT_NEAR(ceiling["fec_per_day"].get<double>(), 15 * 8.0 / 3.0 / 5.2, 1e-9);
  EXPECT_NEAR(ceiling["fec_total"].get<double>(), 450 * 8.0 / 3.0 / 5.2, 1e-9);
  EXPECT_NEAR(ceiling["charge_ah_total"].get<double>(), 450 * 8.0 / 3.0, 1e-9);
  EXPECT_NEAR(ceiling["reduction_pct"].get<double>(), 100.0 * (1 - 8.0 / 9.5), 1e-9);
  EXPECT_EQ(j["cases"][0]["reduction_pct"].get<double>(), 0.0);
}

TEST(CliDuty, CsvDirectoryHoldsMissionDayAndRunSeriesPerCase) {
  const auto dir = scratchDirectory("duty_csv");
  const CommandResult r = runCeilplan("duty --days 2 --csv-dir " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* name : {"cases.csv", "case1_mission.csv", "case1_day.csv", "case1_run.csv", "case2_run.csv"})
    EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
  const std::string mission = readWholeFile(dir / "case1_mission.csv");
  EXPECT_EQ(mission.rfind("t_s,current_a,soc,fec,fec_continuous,mode\n", 0), 0u);
  EXPECT_NE(mission.find(",charge\n"), std::string::npos);
}

TEST(CliDuty, ReadsTheSameKeysFromAYamlConfig) {
  const auto dir = scratchDirectory("duty_yaml");
  const auto config = dir / "study.yaml";
  std::ofstream(config) << "flight_current_a: [9.5, 7.0]\ndays: 1\ndt-s: 0\n";
  const CommandResult r = runCeilplan("duty --config " + config.string() + " --json " + (dir / "out.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(readWholeFile(dir / "out.json"));
  EXPECT_DOUBLE_EQ(j["cases"][1]["flight_current_a"].get<double>(), 7.0);
  EXPECT_NEAR(j["cases"][1]["fec_total"].get<double>(), 15 * 7.0 / 3.0 / 5.2, 1e-9);
}

TEST(CliDuty, ReportsEachAgeingModelPerCaseWithReductionsAndEndOfLife) {
  const auto dir = scratchDirectory("duty_ageing");
  const CommandResult r = runCeilplan("duty --dt-s 0 --json " + (dir / "duty.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* model : {"fec:", "xu:", "schmalstieg:", "woehler:"}) EXPECT_NE(r.out.find(model), std::string::npos) << model;
  const auto j = nlohmann::json::parse(readWholeFile(dir / "duty.json"));
  const auto& ceiling_models = j["cases"][1]["ageing"];
  ASSERT_EQ(ceiling_models.size(), 4u);
  const auto& xu = ceiling_models[1];
  EXPECT_EQ(xu["model"], "xu");
  // Reference-models.md section 5: Xu's cycle damage falls 18.2 % with the pack kept new.
  EXPECT_NEAR(xu["wear_reduction_new_pack_pct"].get<double>(), 18.2, 0.05);
  EXPECT_NEAR(ceiling_models[0]["wear_reduction_new_pack_pct"].get<double>(), 100 * (1 - 8.0 / 9.5), 1e-6);
  for (const auto& model : ceiling_models) {
    EXPECT_GT(model["capacity_fade"].get<double>(), 0.0) << model["model"];
    EXPECT_TRUE(model["days_to_end_of_life"].is_number()) << model["model"];
    EXPECT_GT(model["fade_reduction_pct"].get<double>(), 0.0) << model["model"];
  }
  EXPECT_FALSE(xu["warnings"].empty());
}

TEST(CliDuty, OneModelOverYearsWritesTheStateOfHealthSeries) {
  const auto dir = scratchDirectory("duty_years");
  const CommandResult r =
      runCeilplan("duty --model xu --years 2 --temperature-c 35 --dt-s 0 --json " + (dir / "d.json").string() +
                  " --csv-dir " + (dir / "csv").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(readWholeFile(dir / "d.json"));
  EXPECT_EQ(j["scenario"]["study_days"].get<int>(), 730);
  ASSERT_EQ(j["cases"][0]["ageing"].size(), 1u);
  const std::string soh = readWholeFile(dir / "csv" / "case1_soh.csv");
  EXPECT_EQ(soh.rfind("model,day,soh\nxu,1,", 0), 0u) << soh.substr(0, 40);
}

struct BadInput {
  const char* arguments;
  const char* says;
};

class CliDutyBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliDutyBadInput, FailsWithOneClearLine) {
  const CommandResult r = runCeilplan(std::string("duty ") + GetParam().arguments);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_LT(r.exit_code, 128) << "crashed: " << r.err;
  EXPECT_NE(r.err.find(GetParam().says), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

INSTANTIATE_TEST_SUITE_P(
    Refusals, CliDutyBadInput,
    ::testing::Values(BadInput{"--capacity-ah 0", "--capacity-ah"}, BadInput{"--capacity-ah -5.2", "--capacity-ah"},
                      BadInput{"--flight-current-a -1", "--flight-current-a"},
                      BadInput{"--flight-current-a nan", "--flight-current-a"},
                      BadInput{"--flight-min nan", "--flight-min"}, BadInput{"--idle-min -5", "--idle-min"},
                      BadInput{"--soc-start 1.5", "--soc-start"}, BadInput{"--soc-start 0", "--soc-start"},
                      BadInput{"--charge-current-a 0", "--charge-current-a"},
                      BadInput{"--charge-max-min 10", "mission 3 of day 1"},
                      BadInput{"--unknown-flag 3", "--unknown-flag"},
                      BadInput{"--temperature-c 298", "kelvin"}, BadInput{"--model rainbow", "--model"},
                      BadInput{"--eol-soh 1.2", "--eol-soh"},
                      BadInput{"--config /nonexistent/study.yaml", "/nonexistent/study.yaml"}),
    [](const auto& info) {
      std::string name;
      for (const char c : std::string(info.param.arguments)) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
      return name;
    });

TEST(CliDuty, MalformedYamlIsRefusedWithItsLine) {
  const auto dir = scratchDirectory("duty_bad_yaml");
  const auto config = dir / "bad.yaml";
  std::ofstream(config) << "days: 3\nflight_min: [20\n";
  const CommandResult r = runCeilplan("duty --config " + config.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("malformed YAML"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("line"), std::string::npos) << r.err;
}

TEST(CliDuty, FailedRunLeavesNoPartialOutput) {
  const auto dir = scratchDirectory("duty_no_partial");
  const CommandResult r =
      runCeilplan("duty --charge-max-min 10 --json " + (dir / "out.json").string() + " --csv-dir " + (dir / "csv").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace ceilplan::testing
