// `ceilplan` where the system refuses threads (a low ulimit -u or -v, a container's pids.max):
// pthread_create fails from a given thread on (refuse_threads.cpp, preloaded). Commands plan
// on the threads they get, or on the main thread alone, and give the unlimited run's results;
// they never abort.
#include "run_command.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

namespace ceilplan::testing {
namespace {

const std::string kBridge = std::string(CEILPLAN_SOURCE_DIR) + "/maps/bridge.bt";

// The shell prefix that runs `ceilplan` with `allowed` threads, the signal-cleanup thread among
// them; refusals are counted in `refusals`. A sanitizer's runtime must come first among the
// libraries, and the preloaded one comes before it: the order check is waived.
std::string threadLimit(int allowed, const std::filesystem::path& refusals) {
  return "CEILPLAN_TEST_THREADS_ALLOWED=" + std::to_string(allowed) +
         " CEILPLAN_TEST_REFUSALS_FILE=" + refusals.string() +
         " ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0 LD_PRELOAD=" + CEILPLAN_REFUSE_THREADS;
}

nlohmann::json planJson(const std::filesystem::path& dir) {
  return nlohmann::json::parse(readWholeFile(dir / "plan.json"));
}

std::uintmax_t refusalsIn(const std::filesystem::path& file) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  return ec ? 0 : size;
}

struct PlanCase {
  const char* name;
  int threads_allowed;  // the signal-cleanup thread is the first
  const char* flags;    // after --map, --out
};

class PlanWithoutThreads : public ::testing::TestWithParam<PlanCase> {};

TEST_P(PlanWithoutThreads, PlansWithWhatItGetsAndNeverAborts) {
  const PlanCase& c = GetParam();
  const std::filesystem::path dir = scratchDirectory(std::string("plan_") + c.name);
  const std::string flags = " --map " + kBridge + " " + c.flags + " --out ";
  const CommandResult free = runCeilplan("plan" + flags + (dir / "free").string());
  ASSERT_EQ(free.exit_code, 0) << free.err;
  const CommandResult limited =
      runCeilplan("plan" + flags + (dir / "limited").string(), threadLimit(c.threads_allowed, dir / "refusals"));
  if (refusalsIn(dir / "refusals") == 0)
    GTEST_SKIP() << "no thread was refused: pthread_create could not be interposed (a sanitizer's own?)";
  ASSERT_EQ(limited.exit_code, 0) << limited.err;
  EXPECT_EQ(limited.err.find("terminate"), std::string::npos) << limited.err;
  std::set<std::string> left;  // no staging directory left behind
  for (const auto& entry : std::filesystem::directory_iterator(dir)) left.insert(entry.path().filename().string());
  EXPECT_EQ(left, (std::set<std::string>{"free", "limited", "refusals"}));
  if (std::string(c.name) != "bitstar") {  // deterministic: the same route to the bit
    EXPECT_EQ(planJson(dir / "limited")["charge_ah"], planJson(dir / "free")["charge_ah"]);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Planners, PlanWithoutThreads,
    ::testing::Values(
        // One of the index's two workers starts (the run aborted with "terminate called without an
        // active exception" and left its staging directory behind), or none.
        PlanCase{"lattice_one_worker", 2, "--planner lattice --start 6,0.7,5.85 --goal 14,0.7,5.85"},
        PlanCase{"lattice_no_worker", 1, "--planner lattice --start 6,0.7,5.85 --goal 14,0.7,5.85"},
        // A 1 s limit: OMPL's own timed solve watched the clock from a thread.
        PlanCase{"bitstar", 1, "--planner BITstar --time-limit-s 1 --seed 1 --start -4,0,0.5 --goal 10,0,5.5"}),
    [](const ::testing::TestParamInfo<PlanCase>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace ceilplan::testing
