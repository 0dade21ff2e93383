#include "tour_legs.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>

namespace ceilplan::app {

std::vector<std::vector<TourLeg>> planTourLegs(int place_count, const LegPathPlanner& plan, const LegScorer& score,
                                               int workers, Progress& progress) {
  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i < place_count; ++i)
    for (int j = i + 1; j < place_count; ++j) pairs.emplace_back(i, j);
  std::vector<std::vector<TourLeg>> legs(place_count, std::vector<TourLeg>(place_count));
  std::vector<std::exception_ptr> failures(pairs.size());
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> done{0};
  std::atomic<bool> failed{false};

  const auto work = [&] {
    for (std::size_t k = next++; k < pairs.size() && !failed; k = next++) {
      const auto [i, j] = pairs[k];
      try {
        TourLeg there;
        there.waypoints = plan(i, j);
        there.evaluation = score(there.waypoints);
        TourLeg back;
        back.waypoints.assign(there.waypoints.rbegin(), there.waypoints.rend());
        back.evaluation = score(back.waypoints);
        legs[i][j] = std::move(there);  // each pair's cells are written by one thread only
        legs[j][i] = std::move(back);
      } catch (...) {
        failures[k] = std::current_exception();
        failed = true;
      }
      ++done;
    }
  };
  std::vector<std::thread> threads;
  const int count = std::max(1, std::min<int>(workers, static_cast<int>(pairs.size())));
  for (int t = 0; t < count; ++t) threads.emplace_back(work);
  while (done < pairs.size() && !failed) {
    progress.update(pairs.empty() ? 1.0 : static_cast<double>(done) / pairs.size());
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  for (std::thread& thread : threads) thread.join();
  progress.finish();
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);
  return legs;
}

}  // namespace ceilplan::app
