// `ceilplan rainflow`, run as a user would.
#include "run_command.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <random>
#include <string>
#include <thread>
#include <vector>

using ceilplan::testing::readWholeFile;
using ceilplan::testing::runCeilplan;
using ceilplan::testing::scratchDirectory;

namespace {

std::filesystem::path writeFile(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
  const auto path = dir / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// ASTM E1049-85's example [-2, 1, -3, 5, -1, 3, -4, 4, -2] mapped to SOC by (x + 4) / 10.
const std::string kAstmSoc = "t_s,soc\n0,0.2\n10,0.5\n20,0.1\n30,0.9\n40,0.3\n50,0.7\n60,0.0\n70,0.8\n80,0.2\n";

// ---- Exit codes (docs/cli.md): 0 success, 1 runtime failure, 2 bad input or usage. ----------
struct ExpectedExit {
  const char* name;
  const char* csv;  // the file's bytes
  int exit_code;
  const char* says;  // a fragment of the one-line message
};

const ExpectedExit kRainflowExitCodes[] = {
    {"astm", "t_s,soc\n0,0.2\n10,0.5\n20,0.1\n30,0.9\n", 0, ""},
    {"bom_and_crlf", "\xEF\xBB\xBFsoc,t_s\r\n0.9,0\r\n0.3,1\r\n0.8,2\r\n", 0, ""},
    {"quoted_text_column", "t_s,soc,note\n0,0.9,\"take-off, north\"\n1,0.3,\"say \"\"low\"\"\"\n", 0, ""},
    {"missing_column", "t_s,SOC\n0,0.9\n1,0.3\n", 2, "no column 'soc'; columns: t_s, SOC"},
    {"garbage_row", "t_s,soc\n0,0.9\n1,0.3,7,?\n", 2, "line 3: 4 fields, but the header names 2 columns"},
    {"garbage_value", "t_s,soc\n0,0.9\n1,0.3x\n", 2, "line 3, column 'soc': '0.3x' is not a number"},
    {"terminal_escape",
     "t_s,soc\n0,0.9\n1,\x1b[31m\x07\x9b"
     "2J\n",
     2, "'\\x1B[31m\\x07\\x9B2J' is not a number"},
    {"binary",
     "\x7f"
     "ELF\x02\x01\x01\x03,\x04\n\x05",
     2, "line 1: the header holds control characters ('\\x7FELF"},
    {"one_row", "t_s,soc\n0,0.9\n", 2, "has 1 data row; a rainflow count needs at least 2 samples"},
    {"header_only", "t_s,soc\n", 2, "has 0 data rows"},
    {"nan_row", "t_s,soc\n0,0.9\n1,NaN\n2,0.5\n", 2, "line 3, column 'soc': 'NaN' is not a finite number"},
    {"empty", "", 2, "is empty; expected a header row"},
};

// Names the row in test listings (ctest shows it), instead of its bytes.
void PrintTo(const ExpectedExit& row, std::ostream* out) { *out << row.name; }

class CliRainflowExitCode : public ::testing::TestWithParam<ExpectedExit> {};

TEST_P(CliRainflowExitCode, FollowsTheTableWithOneEscapedLineAndNoOutput) {
  const ExpectedExit& expected = GetParam();
  const auto dir = scratchDirectory(std::string("exit_") + expected.name);
  const auto csv = writeFile(dir, "in.csv", expected.csv);
  const auto json_path = dir / "out" / "cycles.json";
  const auto r = runCeilplan("rainflow --csv " + csv.string() + " --column soc --json " + json_path.string());
  EXPECT_EQ(r.exit_code, expected.exit_code) << r.err;
  EXPECT_NE(r.err.find(expected.says), std::string::npos) << r.err;
  if (expected.exit_code == 0) {
    EXPECT_TRUE(std::filesystem::exists(json_path));
    return;
  }
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(std::none_of(r.err.begin(), r.err.end(), [](char c) {
    return (c >= 0 && c < 0x20 && c != '\n') || c == 0x7f || c == '\x9b';
  })) << "raw control bytes echoed";
  EXPECT_FALSE(std::filesystem::exists(dir / "out")) << "output written for bad input";
}

INSTANTIATE_TEST_SUITE_P(Table, CliRainflowExitCode, ::testing::ValuesIn(kRainflowExitCodes),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace

TEST(CliRainflow, ReadsTheSeriesThatDutyWrites) {
  // `ceilplan duty --csv-dir` writes t_s,current_a,soc,fec,fec_continuous,mode; the text `mode`
  // column is not the SOC's business. A day of the paper's 15 missions at 9.5 A swings
  // 0.95 -> 0.341 -> 0.95 fifteen times: 30 half cycles of depth 0.6090.
  const auto dir = scratchDirectory("from_duty");
  ASSERT_EQ(runCeilplan("duty --days 1 --model none --csv-dir " + (dir / "duty").string()).exit_code, 0);
  const auto series = dir / "duty" / "case1_day.csv";
  ASSERT_NE(readWholeFile(series).find(",discharge\n"), std::string::npos);
  const auto r = runCeilplan("rainflow --csv " + series.string() + " --column soc --json " + (dir / "c.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("30 rows: 0 full and 30 half cycles, 15 cycles in all"), std::string::npos) << r.out;
  const nlohmann::json cycles = nlohmann::json::parse(readWholeFile(dir / "c.json"));
  for (const auto& c : cycles.at("cycles")) EXPECT_NEAR(c.at("range").get<double>(), 9.5 / 3.0 / 5.2, 1e-9);
}

// Starts `ceilplan rainflow` on a large file, sends `signal_number` once its temporary JSON file
// exists, and returns how it ended. Sets `saw_temporary` if the signal hit while writing.
int interruptWhileWriting(const std::filesystem::path& dir, int signal_number, bool& saw_temporary) {
  const auto csv = dir / "big.csv";
  {
    std::ofstream out(csv);
    out << "t_s,soc,mode\n";
    std::mt19937 rng(2019);  // seed printed by the test's name: fixed
    std::uniform_real_distribution<double> soc(0.0, 1.0);
    for (int i = 0; i < 600000; ++i) out << i << ',' << soc(rng) << ",flight\n";
  }
  const std::string json = (dir / "out" / "cycles.json").string();
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    ::execl(CEILPLAN_EXE, CEILPLAN_EXE, "rainflow", "--csv", csv.c_str(), "--column", "soc", "--json", json.c_str(),
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  saw_temporary = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  int status = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    if (::waitpid(pid, &status, WNOHANG) == pid) return status;  // finished before the temporary was seen
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir / "out", ec))
      saw_temporary |= entry.path().filename().string().find(".tmp") != std::string::npos;
    if (saw_temporary) break;
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
  ::kill(pid, signal_number);
  ::waitpid(pid, &status, 0);
  return status;
}

TEST(CliRainflow, AnInterruptionLeavesNoTemporaryFileAndNoPartialOutput) {
  for (const int signal_number : {SIGINT, SIGTERM}) {
    const auto dir = scratchDirectory("interrupted_" + std::to_string(signal_number));
    bool saw_temporary = false;
    const int status = interruptWhileWriting(dir, signal_number, saw_temporary);
    ASSERT_TRUE(saw_temporary) << "the run ended before its output was being written; make the input larger";
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number)
        << "ended by the signal, as a shell expects (status " << status << ")";
    // The run created out/: it is gone (removed with the temporary), or holds the whole JSON.
    std::vector<std::string> left;
    std::error_code absent;
    for (const auto& entry : std::filesystem::directory_iterator(dir / "out", absent))
      left.push_back(entry.path().filename());
    // All or nothing: no temporary; the JSON only if it was renamed into place, whole, first.
    for (const std::string& name : left) {
      EXPECT_EQ(name.find(".tmp"), std::string::npos) << name << " left behind";
      if (name == "cycles.json") {
        EXPECT_NO_THROW(nlohmann::json::parse(readWholeFile(dir / "out" / name)));
      }
    }
  }
}

TEST(CliRainflow, PrintsAndWritesTheAstmExample) {
  const auto dir = scratchDirectory("astm");
  const auto csv = writeFile(dir, "soc.csv", kAstmSoc);
  const auto json_path = dir / "out" / "cycles.json";
  const auto result = runCeilplan("rainflow --csv " + csv.string() + " --column soc --json " + json_path.string());
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
  EXPECT_NE(result.exit_code, 0);  // 2 per docs/cli.md: kRainflowExitCodes, "missing_column"
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
    const auto result = runCeilplan("rainflow --csv " + csv.string() + " --column soc --json " + json_path.string());
    EXPECT_NE(result.exit_code, 0) << name;  // 2 per docs/cli.md: kRainflowExitCodes
    EXPECT_NE(result.err.find(input.second), std::string::npos) << name << ": " << result.err;
    EXPECT_EQ(result.err.find('\n'), result.err.size() - 1) << name << ": more than one line";
    EXPECT_FALSE(std::filesystem::exists(json_path)) << name;
  }
}

TEST(CliRainflow, MissingFileAndMissingFlags) {
  const auto dir = scratchDirectory("missing_file");
  const auto missing = runCeilplan("rainflow --csv " + (dir / "nope.csv").string() + " --column soc");
  EXPECT_NE(missing.exit_code, 0);  // 2 per docs/cli.md: MissingFileIsBadInput below
  EXPECT_NE(missing.err.find((dir / "nope.csv").string() + ": no such CSV file"), std::string::npos) << missing.err;
  EXPECT_EQ(runCeilplan("rainflow --csv x.csv").exit_code, 2);
}

TEST(CliRainflow, AFileWithoutTimeColumnAndWithCommentsAndBlankLines) {
  const auto dir = scratchDirectory("no_time");
  const auto csv = writeFile(dir, "soc.csv", "# logged SOC\n\"soc\"\n0.9\n\n0.3\n 0.9 \n");
  const auto result = runCeilplan("rainflow --csv " + csv.string() + " --column soc");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("1 cycles in all"), std::string::npos) << result.out;
}

TEST(CliRainflow, MissingFileOrDirectoryIsBadInput) {
  const auto dir = scratchDirectory("missing_file_code");
  EXPECT_EQ(runCeilplan("rainflow --csv " + (dir / "nope.csv").string() + " --column soc").exit_code, 2);
  const auto r = runCeilplan("rainflow --csv " + dir.string() + " --column soc");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("is a directory, not a CSV file; give a regular file"), std::string::npos) << r.err;
  const auto csv = writeFile(dir, "soc.csv", kAstmSoc);
  const auto j = runCeilplan("rainflow --csv " + csv.string() + " --column soc --json " + dir.string());
  EXPECT_EQ(j.exit_code, 2);
  EXPECT_NE(j.err.find("--json " + dir.string() + " is a directory"), std::string::npos) << j.err;
}

TEST(CliRainflow, ADirectoryIsRefusedInOneLine) {
  const auto dir = scratchDirectory("directory");
  const auto r = runCeilplan("rainflow --csv " + dir.string() + " --column soc");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(r.err, "ceilplan: error: " + dir.string() + ": is a directory, not a CSV file; give a regular file\n");
}
