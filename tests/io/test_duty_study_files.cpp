// What `ceilplan duty` prints and writes of a duty study: the table, the JSON and the CSV series;
// and JSON files written whole.

#include "ceilplan/io/duty_study_files.hpp"
#include "ceilplan/io/json_values.hpp"

#include "ceilplan/core/error.hpp"

#include "run_command.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace ceilplan::io {
namespace {

battery::DutyStudyOptions shortStudy(std::vector<std::string> models) {
  battery::DutyStudyOptions options;
  options.days = 2;
  options.ageing_models = std::move(models);
  return options;
}

std::size_t lineCount(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

TEST(DutyStudyTable, ShowsThePapersFiguresPerCase) {
  const battery::DutyStudyOptions options = shortStudy({});
  const std::string table = dutyStudyTable(options, battery::runDutyStudy(options));
  EXPECT_EQ(table.rfind("Duty cycle: 15 missions a day for 2 days; each flies 20.0 min, idles 5.0 min, charges at "
                        "10.40 A for at most 20.0 min back to 95.0 % SOC; 5.20 Ah pack; 30.0 s steps\n\n",
                        0),
            0u)
      << table;
  EXPECT_NE(table.find("\n                                      case 1      case 2\n"), std::string::npos) << table;
  EXPECT_NE(table.find("\nlowest SOC [%]                          34.1        43.7\n"), std::string::npos) << table;
  EXPECT_NE(table.find("\ncharge complete [min]                  43.50       40.50\n"), std::string::npos) << table;
  EXPECT_NE(table.find("\nFEC after 2 days                       18.27       15.38\n"), std::string::npos) << table;
  EXPECT_NE(table.find("\nFEC reduction vs first [%]              0.00       15.79\n"), std::string::npos) << table;
  EXPECT_EQ(table.find("Battery ageing"), std::string::npos);  // no model, no ageing section
  EXPECT_EQ(lineCount(table), 11u);
}

TEST(DutyStudyTable, AddsEachModelsWearAndTheCasesThatStoppedEarly) {
  battery::DutyStudyOptions options = shortStudy({"fec"});
  options.days = 100;
  options.step_s = 0.0;
  const std::string table = dutyStudyTable(options, battery::runDutyStudy(options));
  EXPECT_NE(table.find("exact, event-driven\n"), std::string::npos) << table;
  EXPECT_NE(
      table.find("\nfec (a faded pack gave out before the study's end: totals cover the days each case flew, "
                 "reductions the 59 days both flew):\n  days flown                              59          89\n"),
      std::string::npos)
      << table;
  EXPECT_NE(table.find("\n  wear reduction vs first [%]           0.00       15.79\n"), std::string::npos) << table;
}

TEST(DutyStudyJson, HoldsTheScenarioAndOneObjectPerCase) {
  battery::DutyStudyOptions options = shortStudy({"fec"});
  options.years = 2.0 / 365.0;
  const nlohmann::json json = dutyStudyJson(options, battery::runDutyStudy(options));
  EXPECT_EQ(json["scenario"]["flight_min"].get<double>(), 20.0);
  EXPECT_EQ(json["scenario"]["days"].get<int>(), 2);
  EXPECT_EQ(json["scenario"]["study_days"].get<int>(), 2);
  EXPECT_NEAR(json["scenario"]["years"].get<double>(), 2.0 / 365.0, 1e-15);
  ASSERT_EQ(json["cases"].size(), 2u);
  const auto& ceiling = json["cases"][1];
  EXPECT_NEAR(ceiling["fec_total"].get<double>(), 30 * 8.0 / 3.0 / 5.2, 1e-9);
  EXPECT_NEAR(ceiling["reduction_pct"].get<double>(), 100 * (1 - 8.0 / 9.5), 1e-9);
  ASSERT_EQ(ceiling["ageing"].size(), 1u);
  EXPECT_EQ(ceiling["ageing"][0]["model"], "fec");
  EXPECT_EQ(ceiling["ageing"][0]["comparison_days"].get<int>(), 2);
  // The projection goes on past the study to the pack's end of life.
  EXPECT_NEAR(ceiling["ageing"][0]["days_to_end_of_life"].get<double>(), 39.0, 0.05);
  EXPECT_NEAR(ceiling["ageing"][0]["wear_reduction_pct"].get<double>(), 100 * (1 - 8.0 / 9.5), 1e-9);
}

TEST(DutyStudyCsv, WritesTheSeriesOfEveryCase) {
  battery::DutyStudyOptions options = shortStudy({"fec"});
  options.record_run = true;
  const auto dir = testing::scratchDirectory("duty_study_csv");
  const battery::DutyStudyResult result = battery::runDutyStudy(options);
  const Provenance provenance = Provenance::of("ceilplan duty --csv-dir out");
  writeDutyStudyCsv(dir, result, provenance);
  const std::string comment = provenance.csvComment() + "\n";  // every file's first line
  for (const char* name :
       {"case1_mission.csv", "case1_day.csv", "case1_run.csv", "case2_run.csv", "case1_soh.csv", "case2_soh.csv"})
    EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
  EXPECT_EQ(testing::readWholeFile(dir / "cases.csv"),
            comment + "case,prefix,flight_current_a\n1,case1,9.5\n2,case2,8\n");
  const std::string mission = testing::readWholeFile(dir / "case1_mission.csv");
  EXPECT_EQ(mission.rfind(comment + "t_s,current_a,soc,fec,fec_continuous,mode\n0,", 0), 0u) << mission.substr(0, 80);
  EXPECT_NE(mission.find(",charge\n"), std::string::npos);
  const std::string soh = testing::readWholeFile(dir / "case2_soh.csv");
  EXPECT_EQ(soh.rfind(comment + "model,day,soh\nfec,1,", 0), 0u) << soh;
  // One row a day of the projection, which goes on past the study to the pack's end of life.
  EXPECT_EQ(lineCount(soh), 2 + result.cases[1].ageing[0].projection.soh_by_day.size());
  EXPECT_GT(lineCount(soh), 3u);
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();  // nothing left half-written
}

TEST(JsonFile, IsIndentedWithAFinalNewlineAndKeepsAnOrderedObjectsOrder) {
  const auto dir = testing::scratchDirectory("json_file");
  writeJsonFile(dir / "plain.json", nlohmann::json{{"b", 1}, {"a", nullptr}});
  EXPECT_EQ(testing::readWholeFile(dir / "plain.json"), "{\n  \"a\": null,\n  \"b\": 1\n}\n");
  nlohmann::ordered_json ordered;
  ordered["z"] = 1;
  ordered["a"] = 2;
  writeJsonFile(dir / "ordered.json", ordered);
  EXPECT_EQ(testing::readWholeFile(dir / "ordered.json"), "{\n  \"z\": 1,\n  \"a\": 2\n}\n");
  EXPECT_THROW(writeJsonFile(dir / "plain.json" / "below_a_file.json", ordered), ceilplan::Error);
}

}  // namespace
}  // namespace ceilplan::io
