#include "ceilplan/core/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

namespace ceilplan {
namespace {

std::atomic<detail::ThreadStartHook> thread_start_hook{nullptr};

constexpr std::chrono::milliseconds kProgressPeriod{100};

}  // namespace

void detail::setThreadStartHook(ThreadStartHook hook) { thread_start_hook = hook; }

void parallelFor(std::size_t count, int workers, const std::function<void(std::size_t)>& task,
                 const std::function<void(double)>& progress) {
  std::vector<std::exception_ptr> failures(count);
  std::atomic<std::size_t> next{0}, done{0};
  std::atomic<bool> failed{false};
  // `report`: the calling thread doing the work itself also reports progress, between tasks.
  const auto work = [&](bool report) {
    auto reported = std::chrono::steady_clock::now();
    for (std::size_t i = next++; i < count && !failed; i = next++) {
      try {
        task(i);
      } catch (...) {
        failures[i] = std::current_exception();  // each index is owned by one thread
        failed = true;
      }
      ++done;
      if (report && progress && std::chrono::steady_clock::now() - reported >= kProgressPeriod) {
        progress(static_cast<double>(done) / count);
        reported = std::chrono::steady_clock::now();
      }
    }
  };
  const std::size_t thread_count =
      std::clamp<std::size_t>(static_cast<std::size_t>(std::max(workers, 1)), 1, std::max<std::size_t>(count, 1));
  std::vector<std::thread> threads;
  threads.reserve(thread_count);  // a thread that starts is always kept, and joined below
  try {
    for (std::size_t t = 0; t < thread_count; ++t) {
      if (const detail::ThreadStartHook hook = thread_start_hook) hook(t);
      threads.emplace_back(work, false);
    }
  } catch (const std::system_error&) {
    // The system refused a thread: fewer threads do the work (see the header).
  }
  if (threads.empty()) work(true);
  // A progress callback that throws cancels the work (a Python callback raising, say): no new
  // task starts, and its exception is rethrown once the threads have stopped.
  std::exception_ptr cancelled;
  try {
    while (!threads.empty() && progress && done < count && !failed) {
      progress(static_cast<double>(done) / count);
      std::this_thread::sleep_for(kProgressPeriod);
    }
  } catch (...) {
    cancelled = std::current_exception();
    failed = true;
  }
  for (std::thread& thread : threads) thread.join();
  if (cancelled) std::rethrow_exception(cancelled);
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);
}

}  // namespace ceilplan
