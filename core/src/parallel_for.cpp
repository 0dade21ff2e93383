#include "ceilplan/core/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <thread>
#include <vector>

namespace ceilplan {

void parallelFor(std::size_t count, int workers, const std::function<void(std::size_t)>& task,
                 const std::function<void(double)>& progress) {
  std::vector<std::exception_ptr> failures(count);
  std::atomic<std::size_t> next{0}, done{0};
  std::atomic<bool> failed{false};
  const auto work = [&] {
    for (std::size_t i = next++; i < count && !failed; i = next++) {
      try {
        task(i);
      } catch (...) {
        failures[i] = std::current_exception();  // each index is owned by one thread
        failed = true;
      }
      ++done;
    }
  };
  const std::size_t thread_count =
      std::clamp<std::size_t>(static_cast<std::size_t>(std::max(workers, 1)), 1, std::max<std::size_t>(count, 1));
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < thread_count; ++t) threads.emplace_back(work);
  while (progress && done < count && !failed) {
    progress(static_cast<double>(done) / count);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  for (std::thread& thread : threads) thread.join();
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);
}

}  // namespace ceilplan
