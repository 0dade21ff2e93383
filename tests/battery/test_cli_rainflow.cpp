// `ceilplan rainflow`, run as a user would.
#include "run_command.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

using ceilplan::testing::readWholeFile;
using ceilplan::testing::runCeilplan;
using ceilplan::testing::scratchDirectory;

namespace {

std::filesystem::path writeFile(const std::filesystem::path& dir, const std::string& name,
                                const std::string& text) {
  const auto path = dir / name;
  std::ofstream(path) << text;
  return path;
}

// ASTM E1049-85's example [-2, 1, -3, 5, -1, 3, -4, 4, -2] mapped to SOC by (x + 4) / 10.
const std::string kAstmSoc =
    "t_s,soc\n0,0.2\n10,0.5\n20,0.1\n30,0.9\n40,0.3\n50,0.7\n60,0.0\n70,0.8\n80,0.2\n";

}  // namespace

TEST(CliRainflow, PrintsAndWritesTheAstmExample) {
  const auto dir = scratchDirectory("astm");
  const auto csv = writeFile(dir, "soc.csv", kAstmSoc);
  const auto json_path = dir / "out" / "cycles.json";
  const auto result =
      runCeilplan("rainflow --csv " + csv.string() + " --column soc --json " + json_path.string());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("4 cycles in all"), std::string::npos) << result.out;
  const auto json = nlohmann::json::parse(readWholeFile(json_path));
  std::map<long, double> counts;  // range in tenths -> count
  for (const auto& c : json.at("cycles")) {
    counts[std::lround(10.0 * c.at("range").get<double>())] += c.at("count").get<double>();
    EXPECT_LT(c.at("start").get<long>(), c.at("end").get<long>());
    EXPECT_TRUE(c.contains("mean"));
  }
  const std::map<long, double> expected{{3, 0.5}, {4, 1.5}, {6, 0.5}, {8, 1.0}, {9, 0.5}};
  EXPECT_EQ(counts, expected);
}

TEST(CliRainflow, MissingColumnNamesTheColumnsAvailable) {
  const auto dir = scratchDirectory("missing_column");
  const auto csv = writeFile(dir, "soc.csv", kAstmSoc);
  const auto result = runCeilplan("rainflow --csv " + csv.string() + " --column SOC");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("no column 'SOC'; columns: t_s, soc"), std::string::npos) << result.err;
}

TEST(CliRainflow, BadValuesGiveOneClearLineAndNoOutputFile) {
  const std::map<std::string, std::pair<std::string, std::string>> cases{
      {"nan", {"t_s,soc\n0,0.5\n10,nan\n", "line 3, column 'soc': 'nan' is not a finite number"}},
      {"text", {"t_s,soc\n0,0.5\n10,high\n", "line 3, column 'soc': 'high' is not a number"}},
      {"above_one", {"t_s,soc\n0,0.5\n10,1.2\n", "line 3, column 'soc': SOC 1.2 is outside [0, 1]"}},
      {"percent", {"t_s,soc\n0,95\n", "SOC 95 is outside [0, 1]; give SOC as a fraction"}},
      {"backwards", {"t_s,soc\n0,0.5\n10,0.4\n5,0.3\n", "line 4, column 't_s': time goes backwards"}},
      {"short_row", {"t_s,soc\n0,0.5\n10\n", "line 3: 1 fields, but the header names 2 columns"}},
      {"twice", {"soc,soc\n0.5,0.5\n", "column 'soc' appears twice"}},
      {"empty", {"", "is empty; expected a header row"}},
  };
  for (const auto& [name, input] : cases) {
    const auto dir = scratchDirectory("bad_" + name);
    const auto csv = writeFile(dir, "soc.csv", input.first);
    const auto json_path = dir / "cycles.json";
    const auto result =
        runCeilplan("rainflow --csv " + csv.string() + " --column soc --json " + json_path.string());
    EXPECT_EQ(result.exit_code, 1) << name;
    EXPECT_NE(result.err.find(input.second), std::string::npos) << name << ": " << result.err;
    EXPECT_EQ(result.err.find('\n'), result.err.size() - 1) << name << ": more than one line";
    EXPECT_FALSE(std::filesystem::exists(json_path)) << name;
  }
}

TEST(CliRainflow, MissingFileAndMissingFlags) {
  const auto dir = scratchDirectory("missing_file");
  const auto missing = runCeilplan("rainflow --csv " + (dir / "nope.csv").string() + " --column soc");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("cannot open"), std::string::npos) << missing.err;
  EXPECT_EQ(runCeilplan("rainflow --csv x.csv").exit_code, 2);
}

TEST(CliRainflow, AFileWithoutTimeColumnAndWithCommentsAndBlankLines) {
  const auto dir = scratchDirectory("no_time");
  const auto csv = writeFile(dir, "soc.csv", "# logged SOC\n\"soc\"\n0.9\n\n0.3\n 0.9 \n");
  const auto result = runCeilplan("rainflow --csv " + csv.string() + " --column soc");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("1 cycles in all"), std::string::npos) << result.out;
}
