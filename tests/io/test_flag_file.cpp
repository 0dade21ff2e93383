// `--config FILE.yaml` (io/flag_file.hpp): flag names as keys, lists for repeated flags, a
// section per command, and every other key refused with its line.

#include "ceilplan/io/flag_file.hpp"

#include "input_error.hpp"
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace ceilplan::io {
namespace {

const std::vector<std::string> kDutyFlags{"capacity-ah", "flight-current-a", "days", "config"};

std::vector<FlagFileEntry> read(const std::string& yaml, const std::string& command = "duty") {
  std::istringstream in(yaml);
  return readFlagFile(in, kDutyFlags, command);
}

std::string errorOf(const std::string& yaml, const std::string& command = "duty") {
  return testing::inputErrorOf([&] { read(yaml, command); });
}

TEST(FlagFile, KeysAreFlagNamesListsRepeatAFlagAndTheCommandsSectionCounts) {
  const std::vector<FlagFileEntry> entries = read("capacity_ah: 5.2\nflight-current-a: [9.5, 8]\nduty:\n  days: 60\n");
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_EQ(entries[0].flag, "capacity-ah");  // '_' spelled '-'
  EXPECT_EQ(entries[0].values, std::vector<std::string>{"5.2"});
  EXPECT_EQ(entries[1].flag, "flight-current-a");
  EXPECT_EQ(entries[1].values, (std::vector<std::string>{"9.5", "8"}));
  EXPECT_EQ(entries[2].flag, "days");
  EXPECT_EQ(entries[2].values, std::vector<std::string>{"60"});
  EXPECT_TRUE(read("").empty());
  EXPECT_TRUE(read("# only a comment\n").empty());
}

TEST(FlagFile, RefusesUnknownKeysWithTheirLineAndTheClosestFlag) {
  EXPECT_EQ(errorOf("days: 3\ncapacity-ahh: 5\n"),
            "config file line 2: unknown key 'capacity-ahh' for 'duty'; did you mean 'capacity-ah'?");
  EXPECT_EQ(errorOf("plan:\n  days: 3\n").rfind("config file line 1: unknown key 'plan' for 'duty'", 0), 0u);
  EXPECT_EQ(errorOf("days: 3\n", "").rfind("(no error)", 0), 0u);
  EXPECT_EQ(errorOf("zzz: 3\n", "").rfind("config file line 1: unknown key 'zzz'", 0), 0u);
  EXPECT_EQ(errorOf("zzz: 3\n", "").find(" for '"), std::string::npos);
}

TEST(FlagFile, RefusesWhatIsNotAFlatMapOfValues) {
  EXPECT_EQ(errorOf("- days\n"), "config file must be a YAML map of flag names to values");
  EXPECT_EQ(errorOf("? [a, b]\n: 1\n"), "config file line 1: a key must be a flag name");
  EXPECT_EQ(errorOf("days:\n  x: 1\n"), "config key 'days' holds a map; give a value or a list");
  EXPECT_EQ(errorOf("flight-current-a: [[1, 2]]\n"),
            "config key 'flight-current-a' holds a nested list; use a flat list");
  EXPECT_EQ(errorOf("days:\n"), "config key 'days' has no value");
  EXPECT_EQ(errorOf("days: [1\n").rfind("malformed YAML config at line ", 0), 0u);
}

// yaml-cpp keeps both entries of a repeated key and CLI11 would let the last win: one value
// would be dropped without a word. Both spellings of a name are one flag, in or out of the
// command's section; a second YAML document would be ignored.
TEST(FlagFile, RefusesAFlagGivenTwiceAndASecondDocument) {
  const struct {
    std::string yaml, says;
  } rows[] = {
      {"days: 3\ndays: 4\n",
       "config file line 2: 'days' gives flag 'days' again (first on line 1); give each flag once, a list for a "
       "repeated flag"},
      {"capacity-ah: 5\ncapacity_ah: 6\n",
       "config file line 2: 'capacity_ah' gives flag 'capacity-ah' again (first on line 1)"},
      {"days: 3\nduty:\n  days: 4\n", "config file line 3: 'days' gives flag 'days' again (first on line 1)"},
      {"duty:\n  days: 4\ndays: 3\n", "config file line 3: 'days' gives flag 'days' again (first on line 2)"},
      {"days: 3\n---\ndays: 4\n",
       "config file holds 2 YAML documents (split by '---'); give one map of flag names to values"},
      {"days: 3\n---\n", "config file holds 2 YAML documents"},
  };
  for (const auto& row : rows)
    EXPECT_EQ(errorOf(row.yaml).rfind(row.says, 0), 0u) << row.yaml << "\n" << errorOf(row.yaml);
  // One document, even with its start marked, and a list for a repeated flag, pass.
  EXPECT_EQ(read("---\ndays: 3\n").size(), 1u);
  EXPECT_EQ(read("flight-current-a: [9.5, 8]\n").size(), 1u);
}

TEST(FlagFile, AFileThatIsNotARegularFileIsRefusedBeforeItIsOpened) {
  const auto dir = testing::scratchDirectory("flag_file_kinds");
  EXPECT_EQ(testing::inputErrorOf([&] { requireFlagFile(dir); }),
            dir.string() + ": is a directory, not a config file; give a regular file");
  EXPECT_EQ(testing::inputErrorOf([&] { requireFlagFile(dir / "none.yaml"); }),
            (dir / "none.yaml").string() + ": no such config file");
  EXPECT_EQ(testing::inputErrorOf([] { requireFlagFile("/dev/zero"); }),
            "/dev/zero: is a device, not a config file; give a regular file");
}

}  // namespace
}  // namespace ceilplan::io
