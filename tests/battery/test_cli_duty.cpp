// `ceilplan duty` as a user runs it: the paper's table by default, JSON and CSV outputs,
// YAML configs, and one clear line with a non-zero exit for bad input.

#include "run_command.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <ostream>

namespace ceilplan::testing {
namespace {

// ---- Exit codes (docs/cli.md): 0 success, 1 runtime failure, 2 bad input or usage, 3 no path or
// infeasible. A duty cycle that depletes the pack is infeasible. ------------------------------
struct ExpectedExit {
  const char* arguments;
  int exit_code;
  const char* says;  // a fragment of the one-line message
};

const ExpectedExit kDutyExitCodes[] = {
    {"--days 1", 0, ""},
    {"--dt-s 1e-9", 2, "--dt-s"},  // allocated without bound until bad_alloc
    {"--dt-s -30", 2, "--dt-s"},
    {"--years 1e6", 2, "--years: must be at most 100, got 1e6"},  // 365 million days
    {"--years 0", 2, "--years"},
    {"--days 1000000", 2, "--days"},
    {"--capacity-ah 1e9", 2, "--capacity-ah"},
    {"--flight-min 1e9", 2, "--flight-min"},
    {"--eol-soh 1", 2, "--eol-soh"},
    {"--woehler-k 100", 2, "--woehler-k"},
    {"--chemistry \"$(printf '\\033[31mLiPo')\"", 2, "--chemistry"},
    {"--unknown-flag 3", 2, "--unknown-flag"},
    {"--dt-s 0.1", 2, "--dt-s 0.1 cuts each 45-min mission into 27000 steps"},
    {"--missions-per-day 40", 2, "--missions-per-day 40 missions of 45 min"},
    {"--missions-per-day 100 --flight-min 10 --idle-min 1 --charge-max-min 1 --years 100", 2, "a study may hold"},
    {"--days 7000 --csv-dir /nonexistent/never-written", 2, "--csv-dir would record"},
    {"--temperature-c 298", 2, "kelvin"},
    {"--charge-max-min 10", 3, "mission 3 of day 1"},
};

// Names the row in test listings (ctest shows it), instead of its bytes.
void PrintTo(const ExpectedExit& row, std::ostream* out) { *out << row.arguments; }

class CliDutyExitCode : public ::testing::TestWithParam<ExpectedExit> {};

TEST_P(CliDutyExitCode, FollowsTheTable) {
  const ExpectedExit& expected = GetParam();
  const CommandResult r = runCeilplan(std::string("duty ") + expected.arguments);
  EXPECT_EQ(r.exit_code, expected.exit_code) << r.err;
  EXPECT_NE(r.err.find(expected.says), std::string::npos) << r.err;
  if (expected.exit_code != 0) {
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << "raw terminal escape echoed";
  }
}

std::string testName(const std::string& arguments) {
  std::string name;
  for (const char c : arguments) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Table, CliDutyExitCode, ::testing::ValuesIn(kDutyExitCodes),
                         [](const auto& info) { return testName(info.param.arguments); });

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
  EXPECT_EQ(mission.rfind("# ceilplan ", 0), 0u) << "the provenance comment first: " << mission.substr(0, 80);
  EXPECT_NE(mission.find("\nt_s,current_a,soc,fec,fec_continuous,mode\n"), std::string::npos);
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
  for (const char* model : {"fec:", "xu:", "schmalstieg:", "woehler:"})
    EXPECT_NE(r.out.find(model), std::string::npos) << model;
  const auto j = nlohmann::json::parse(readWholeFile(dir / "duty.json"));
  const auto& ceiling_models = j["cases"][1]["ageing"];
  ASSERT_EQ(ceiling_models.size(), 4u);
  const auto& xu = ceiling_models[1];
  EXPECT_EQ(xu["model"], "xu");
  // Derived from Xu et al. 2018's constants (docs/ageing.md): Xu's cycle damage falls 18.2 %
  // with the pack kept new.
  EXPECT_NEAR(xu["wear_reduction_new_pack_pct"].get<double>(), 18.2, 0.05);
  EXPECT_NEAR(ceiling_models[0]["wear_reduction_new_pack_pct"].get<double>(), 100 * (1 - 8.0 / 9.5), 1e-6);
  for (const auto& model : ceiling_models) {
    EXPECT_GT(model["capacity_fade"].get<double>(), 0.0) << model["model"];
    EXPECT_TRUE(model["days_to_end_of_life"].is_number()) << model["model"];
    EXPECT_GT(model["fade_reduction_pct"].get<double>(), 0.0) << model["model"];
  }
  EXPECT_FALSE(xu["warnings"].empty());
}

TEST(CliDuty, OneFecTheAgeingProjectionCountsTheSameFecAsTheFirstTable) {
  // Kocer et al. 2019, eq. 3-6: FEC counts the charge moved against the nominal capacity. With the
  // fade fed back the fec model's FEC is still the first table's 274.04 / 230.77; the faded
  // pack's deeper SOC swings add up to more, printed under their own name.
  const auto dir = scratchDirectory("duty_one_fec");
  const CommandResult r = runCeilplan("duty --model fec --json " + (dir / "duty.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(readWholeFile(dir / "duty.json"));
  for (const auto& c : j["cases"]) {
    const auto& fec = c["ageing"][0];
    ASSERT_EQ(fec["model"], "fec");
    EXPECT_EQ(fec["cycle_wear_name"], "FEC");
    EXPECT_NEAR(fec["cycle_wear"].get<double>(), c["fec_total"].get<double>(), 1e-9);
    EXPECT_NEAR(fec["fec"].get<double>(), c["fec_total"].get<double>(), 1e-9);
    EXPECT_GT(fec["faded_pack_cycles"].get<double>(), 1.08 * c["fec_total"].get<double>());
  }
  const std::string ageing = r.out.substr(r.out.find("fec:"));
  EXPECT_NE(ageing.find("  FEC                                 274.04      230.77\n"), std::string::npos) << ageing;
  EXPECT_NE(ageing.find("  cycles of the faded pack"), std::string::npos) << ageing;
  // With the fade fed back, FEC falls exactly as much as with the pack kept new.
  EXPECT_NEAR(j["cases"][1]["ageing"][0]["wear_reduction_pct"].get<double>(), 100 * (1 - 8.0 / 9.5), 1e-9);
}

TEST(CliDuty, SchmalstiegCountsTheNominalChargeThroughput) {
  // Over the paper's month, counting the faded SOC swings as throughput made Schmalstieg's cycle
  // loss 4-5 % high in Q; in nominal capacities the 9.5 A case loses 0.1267 (was 0.1332).
  const auto dir = scratchDirectory("duty_schmalstieg_q");
  const CommandResult r = runCeilplan("duty --model schmalstieg --json " + (dir / "duty.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(readWholeFile(dir / "duty.json"));
  EXPECT_NEAR(j["cases"][0]["ageing"][0]["cycle_wear"].get<double>(), 0.12671, 5e-5);
}

TEST(CliDuty, YearsLabelTheTotalsWithTheRealSpan) {
  const CommandResult r = runCeilplan("duty --years 2 --model none");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("15 missions a day for 730 days (2 years)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("FEC after 730 days"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find(" 30 days"), std::string::npos) << r.out;
  const CommandResult one = runCeilplan("duty --days 1 --model none");
  EXPECT_NE(one.out.find("15 missions a day for 1 day;"), std::string::npos) << one.out;
  EXPECT_NE(one.out.find("FEC after 1 day "), std::string::npos) << one.out;
}

TEST(CliDuty, ReductionsCompareCasesOverTheDaysBothFlew) {
  // Over 5 years every model's faded packs give out, the free-flight one first. Its wear then
  // stops growing while the ceiling pack's goes on: compared at their own last days the ceiling
  // case looked 26-42 % *worse*. Over the days both flew it wears less under every model, and by
  // FEC exactly 1 - 8 / 9.5 less.
  const auto dir = scratchDirectory("duty_common_span");
  const CommandResult r = runCeilplan("duty --years 5 --json " + (dir / "duty.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(readWholeFile(dir / "duty.json"));
  const auto& free_flight = j["cases"][0]["ageing"];
  const auto& ceiling = j["cases"][1]["ageing"];
  for (std::size_t m = 0; m < ceiling.size(); ++m) {
    const int days = ceiling[m]["comparison_days"].get<int>();
    EXPECT_EQ(days, std::min(free_flight[m]["days_flown"].get<int>(), ceiling[m]["days_flown"].get<int>()))
        << ceiling[m]["model"];
    EXPECT_LT(days, 1825) << ceiling[m]["model"];
    EXPECT_GT(ceiling[m]["wear_reduction_pct"].get<double>(), 15.0) << ceiling[m]["model"];
    EXPECT_GT(ceiling[m]["fade_reduction_pct"].get<double>(), 0.0) << ceiling[m]["model"];
  }
  EXPECT_NEAR(ceiling[0]["wear_reduction_pct"].get<double>(), 100 * (1 - 8.0 / 9.5), 1e-9);
  EXPECT_NE(r.out.find("reductions the 59 days both flew"), std::string::npos) << r.out;
}

TEST(CliDuty, OneModelOverYearsWritesTheStateOfHealthSeries) {
  const auto dir = scratchDirectory("duty_years");
  const CommandResult r = runCeilplan("duty --model xu --years 2 --temperature-c 35 --dt-s 0 --json " +
                                      (dir / "d.json").string() + " --csv-dir " + (dir / "csv").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(readWholeFile(dir / "d.json"));
  EXPECT_EQ(j["scenario"]["study_days"].get<int>(), 730);
  ASSERT_EQ(j["cases"][0]["ageing"].size(), 1u);
  const std::string soh = readWholeFile(dir / "csv" / "case1_soh.csv");
  EXPECT_NE(soh.find("\nmodel,day,soh\nxu,1,"), std::string::npos) << soh.substr(0, 400);
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
                      BadInput{"--unknown-flag 3", "--unknown-flag"}, BadInput{"--temperature-c 298", "kelvin"},
                      BadInput{"--model rainbow", "--model"}, BadInput{"--eol-soh 1.2", "--eol-soh"},
                      BadInput{"--config /nonexistent/study.yaml", "/nonexistent/study.yaml"},
                      BadInput{"--dt-s 1e-9", "--dt-s"}, BadInput{"--dt-s 0.1", "--dt-s"},
                      BadInput{"--years 1e6", "--years"}, BadInput{"--missions-per-day 40", "--missions-per-day"},
                      BadInput{"--chemistry \"$(printf '\\033[31mLiPo')\"", "--chemistry"}),
    [](const auto& info) {
      std::string name;
      for (const char c : std::string(info.param.arguments))
        name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
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
  const CommandResult r = runCeilplan("duty --charge-max-min 10 --json " + (dir / "out.json").string() + " --csv-dir " +
                                      (dir / "csv").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace ceilplan::testing
