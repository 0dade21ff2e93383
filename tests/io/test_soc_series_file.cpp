// What `ceilplan rainflow` reads (an SOC column of a CSV) and writes (its cycles as JSON), and
// the totals it prints.

#include "ceilplan/io/soc_series_file.hpp"

#include "ceilplan/core/error.hpp"

#include "input_error.hpp"
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace ceilplan::io {
namespace {

std::filesystem::path csv(const std::string& name, const std::string& text) {
  const auto file = testing::scratchDirectory("soc_series") / name;
  std::ofstream(file) << text;
  return file;
}

std::string errorOf(const std::string& text) {
  return testing::inputErrorOf([&] { readSocSeries(csv("bad.csv", text), "soc"); });
}

TEST(SocSeriesFile, ReadsTheColumnWhateverTheOthersHold) {
  EXPECT_EQ(readSocSeries(csv("duty.csv", "t_s,soc,mode\n0,0.95,discharge\n30,0.5,idle\n30,0.9,charge\n"), "soc"),
            (std::vector<double>{0.95, 0.5, 0.9}));
  EXPECT_EQ(readSocSeries(csv("no_time.csv", "soc\n1\n0\n"), "soc"), (std::vector<double>{1.0, 0.0}));
}

TEST(SocSeriesFile, RefusesSocOutsideAFractionTimeGoingBackAndTooFewSamples) {
  EXPECT_NE(errorOf("t_s,soc\n0,0.5\n1,95\n").find("line 3, column 'soc': SOC 95 is outside [0, 1]"),
            std::string::npos);
  EXPECT_NE(errorOf("t_s,soc\n5,0.5\n4,0.4\n").find("line 3, column 't_s': time goes backwards (5 s to 4 s)"),
            std::string::npos);
  EXPECT_NE(errorOf("t_s,soc\n0,0.5\n").find("has 1 data row; a rainflow count needs at least 2 samples of 'soc'"),
            std::string::npos);
  EXPECT_NE(errorOf("t_s,SOC\n0,0.5\n").find("has no column 'soc'"), std::string::npos);
}

TEST(RainflowJson, ListsEachCycleWithItsKeysInOrder) {
  const nlohmann::ordered_json json = rainflowJson({{0.6, 0.65, 1.0, 2, 5}, {0.2, 0.4, 0.5, 5, 9}});
  EXPECT_EQ(json.dump(),
            "{\"cycles\":[{\"range\":0.6,\"mean\":0.65,\"count\":1.0,\"start\":2,\"end\":5},"
            "{\"range\":0.2,\"mean\":0.4,\"count\":0.5,\"start\":5,\"end\":9}]}");
  EXPECT_EQ(rainflowJson({}).dump(), "{\"cycles\":[]}");
}

TEST(RainflowText, TitlesTheColumnAndFileThenOneRowPerCycleAndTheTotals) {
  const std::string text = rainflowText("soc", "run.csv", 10, {{0.6, 0.65, 1.0, 2, 5}, {0.2, 0.4, 0.5, 5, 9}});
  EXPECT_EQ(text,
            "Rainflow cycles (ASTM E1049-85, residue as half cycles) of column 'soc' in run.csv, 10 samples\n\n"
            "     range      mean  count       start         end\n"
            "    0.6000    0.6500    1.0           2           5\n"
            "    0.2000    0.4000    0.5           5           9\n"
            "\n2 rows: 1 full and 1 half cycles, 1.5 cycles in all; sum of count x range 0.7\n");
  EXPECT_NE(rainflowText("s\x1b[2Jc", "a.csv", 2, {}).find("column 's\\x1B[2Jc'"), std::string::npos);
}

TEST(RainflowTotals, CountHalvesAsHalfAndWeighTheRanges) {
  const battery::RainflowTotals totals =
      battery::rainflowTotals({{0.6, 0.65, 1.0, 2, 5}, {0.2, 0.4, 0.5, 5, 9}, {0.4, 0.5, 0.5, 9, 12}});
  EXPECT_EQ(totals.full_cycles, 1.0);
  EXPECT_EQ(totals.half_cycles, 2.0);
  EXPECT_EQ(totals.cycles, 2.0);
  EXPECT_DOUBLE_EQ(totals.count_weighted_range, 0.6 + 0.1 + 0.2);
}

}  // namespace
}  // namespace ceilplan::io
