// `--config FILE.yaml` (io/flag_file.hpp): flag names as keys, lists for repeated flags, a
// section per command, and every other key refused with its line.

#include "ceilplan/io/flag_file.hpp"

#include "input_error.hpp"

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
  const std::vector<FlagFileEntry> entries =
      read("capacity_ah: 5.2\nflight-current-a: [9.5, 8]\nduty:\n  days: 60\n");
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
  EXPECT_EQ(errorOf("flight-current-a: [[1, 2]]\n"), "config key 'flight-current-a' holds a nested list; use a flat list");
  EXPECT_EQ(errorOf("days:\n"), "config key 'days' has no value");
  EXPECT_EQ(errorOf("days: [1\n").rfind("malformed YAML config at line ", 0), 0u);
}

}  // namespace
}  // namespace ceilplan::io
