// parallelFor when the system refuses threads (a low ulimit -u or -v, a container's pids.max):
// the threads that started do the work, or the calling thread alone; never an abort.
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/parallel_for.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <system_error>
#include <thread>
#include <vector>

namespace ceilplan::testing {
namespace {

std::atomic<std::size_t> threads_allowed{0};
std::atomic<int> refused{0};

void refuseBeyondAllowance(std::size_t index) {
  if (index >= threads_allowed) {
    ++refused;
    throw std::system_error(std::make_error_code(std::errc::resource_unavailable_try_again));
  }
}

// Lets `allowed` threads of each parallelFor start and refuses the rest, for one test.
class ThreadLimit {
 public:
  explicit ThreadLimit(std::size_t allowed) {
    threads_allowed = allowed;
    refused = 0;
    detail::setThreadStartHook(refuseBeyondAllowance);
  }
  ~ThreadLimit() { detail::setThreadStartHook(nullptr); }
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;
};

// Runs `count` tasks on `workers` threads; returns the threads that ran them, each task's runs.
struct TaskRun {
  std::set<std::thread::id> threads;
  std::vector<int> runs;
};
TaskRun runTasks(std::size_t count, int workers, std::chrono::milliseconds task_time = {}) {
  TaskRun run;
  run.runs.assign(count, 0);
  std::mutex mutex;
  parallelFor(count, workers, [&](std::size_t i) {
    std::this_thread::sleep_for(task_time);
    const std::lock_guard<std::mutex> lock(mutex);
    run.threads.insert(std::this_thread::get_id());
    ++run.runs[i];
  });
  return run;
}

TEST(ParallelFor, RunsEveryTaskOnceOnTheWorkersAsked) {
  const TaskRun run = runTasks(64, 3, std::chrono::milliseconds(2));
  EXPECT_EQ(run.runs, std::vector<int>(64, 1));
  EXPECT_EQ(run.threads.count(std::this_thread::get_id()), 0u);
  EXPECT_GE(run.threads.size(), 2u);  // 2 ms tasks: more than one of the three takes some
}

TEST(ParallelFor, ARefusedThreadLeavesTheWorkToTheThreadsThatStarted) {
  const ThreadLimit limit(1);
  const TaskRun run = runTasks(64, 4, std::chrono::milliseconds(1));
  EXPECT_EQ(run.runs, std::vector<int>(64, 1));
  EXPECT_EQ(refused, 1);  // no further thread is tried after a refusal
  ASSERT_EQ(run.threads.size(), 1u);
  EXPECT_NE(*run.threads.begin(), std::this_thread::get_id());
}

TEST(ParallelFor, NoThreadAtAllLeavesTheWorkToTheCallingThreadWithProgress) {
  const ThreadLimit limit(0);
  std::vector<int> runs(30, 0);
  std::vector<double> shares;
  const std::thread::id caller = std::this_thread::get_id();
  parallelFor(
      runs.size(), 2,
      [&](std::size_t i) {
        EXPECT_EQ(std::this_thread::get_id(), caller);
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        ++runs[i];
      },
      [&](double share) { shares.push_back(share); });
  EXPECT_EQ(runs, std::vector<int>(30, 1));
  EXPECT_EQ(refused, 1);
  ASSERT_FALSE(shares.empty());  // 300 ms of work, reported every 100 ms
  for (std::size_t k = 0; k < shares.size(); ++k) {
    EXPECT_GT(shares[k], 0.0);
    EXPECT_LE(shares[k], 1.0);
    if (k > 0) {
      EXPECT_GT(shares[k], shares[k - 1]);
    }
  }
}

TEST(ParallelFor, OnTheCallingThreadAFailureStopsTheWorkAndIsRethrown) {
  const ThreadLimit limit(0);
  std::vector<int> runs(20, 0);
  EXPECT_THROW(parallelFor(runs.size(), 4,
                           [&](std::size_t i) {
                             ++runs[i];
                             if (i == 5) throw InputError("task 5 failed");
                           }),
               InputError);
  // One thread takes the indices in order: none after the failing one starts.
  EXPECT_EQ(std::vector<int>(runs.begin(), runs.begin() + 6), std::vector<int>(6, 1));
  EXPECT_EQ(std::vector<int>(runs.begin() + 6, runs.end()), std::vector<int>(14, 0));
}

TEST(ParallelFor, AProgressCallbackThatThrowsCancelsTheWorkAndIsRethrown) {
  // A Python progress callback that raises arrives here as an exception from `progress`: the
  // threads stop taking tasks and are joined (never std::terminate), and the exception comes out.
  std::atomic<int> started{0};
  EXPECT_THROW(parallelFor(
                   1000, 2,
                   [&](std::size_t) {
                     ++started;
                     std::this_thread::sleep_for(std::chrono::milliseconds(5));
                   },
                   [](double) { throw InputError("cancelled by the callback"); }),
               InputError);
  EXPECT_LT(started, 1000);
}

TEST(ParallelFor, TheCallingThreadRunsTheTasksItselfOnlyWhenNoThreadStarts) {
  {
    const ThreadLimit limit(0);
    const TaskRun run = runTasks(8, 2);
    EXPECT_EQ(run.threads, std::set<std::thread::id>{std::this_thread::get_id()});
  }
  const TaskRun run = runTasks(8, 2);  // the hook reset: threads again
  EXPECT_EQ(run.threads.count(std::this_thread::get_id()), 0u);
}

}  // namespace
}  // namespace ceilplan::testing
