// planTours: the tours of several modes at once over one shared context, handed over in order.

#include "ceilplan/mission/tour_planner.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/parallel_for.hpp"

#include <atomic>
#include <deque>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>

namespace ceilplan::mission {
namespace {

// Thrown into a mode's work at its next progress report once it is no longer wanted (an earlier
// mode failed, or the front end stopped); the failure that stopped it is the one rethrown.
class Abandoned : public Error {
 public:
  Abandoned() : Error("tour abandoned") {}
};

// The modes' progress, queued by their threads and forwarded from the calling thread.
class ProgressRelay {
 public:
  explicit ProgressRelay(ProgressCallback forward) : forward_(std::move(forward)) {}

  void report(const std::string& stage, double fraction) {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      // A stage's newer fraction replaces the one still waiting; its end (1) is always forwarded.
      if (!queue_.empty() && queue_.back().first == stage && queue_.back().second < 1.0)
        queue_.back().second = fraction;
      else
        queue_.emplace_back(stage, fraction);
    }
    if (std::this_thread::get_id() == caller_) forward();
  }

  // From the calling thread: what was queued, in order.
  void forward() {
    std::deque<std::pair<std::string, double>> reports;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      reports.swap(queue_);
    }
    for (const auto& [stage, fraction] : reports) forward_(stage, fraction);
  }

 private:
  ProgressCallback forward_;
  std::thread::id caller_ = std::this_thread::get_id();
  std::mutex mutex_;
  std::deque<std::pair<std::string, double>> queue_;
};

}  // namespace

std::vector<TourResult> planTours(const Mission& mission, const PlanningContext& context,
                                  const std::vector<FlightMode>& modes, const TourOptions& options,
                                  const TourPlanned& planned) {
  options.validate();
  const std::size_t count = modes.size();
  std::vector<std::unique_ptr<TourResult>> tours(count);
  std::unique_ptr<std::atomic<bool>[]> done(new std::atomic<bool>[count]);
  for (std::size_t k = 0; k < count; ++k) done[k] = false;
  std::atomic<std::size_t> first_failed{count};  // the lowest mode that failed
  std::atomic<bool> stopped{false};              // `planned` or the progress callback threw
  ProgressRelay relay(options.progress);
  std::size_t handed = 0;
  // The tours planned, in order, up to the first not planned (or `limit`).
  const auto handOver = [&](std::size_t limit) {
    if (options.progress) relay.forward();
    for (; handed < limit && done[handed]; ++handed)
      if (planned) planned(*tours[handed]);
  };
  // Modes planned at once, each on its thread, share their candidate views' covers.
  const int threads = options.workers >= 2 ? static_cast<int>(count) : 1;
  const std::shared_ptr<SharedCovers> shared_covers =
      threads >= 2 && count >= 2 ? std::make_shared<SharedCovers>(modes) : options.shared_covers;
  const auto plan = [&](std::size_t k) {
    TourOptions mode_options = options;
    mode_options.shared_covers = shared_covers;
    if (options.progress)
      mode_options.progress = [&, k](const std::string& stage, double fraction) {
        if (stopped || first_failed < k) throw Abandoned();
        relay.report(stage, fraction);
      };
    try {
      tours[k] = std::make_unique<TourResult>(planTour(mission, context, modes[k], mode_options));
    } catch (...) {
      for (std::size_t failed = first_failed; k < failed && !first_failed.compare_exchange_weak(failed, k);) {
      }
      throw;
    }
    tours[k]->options.progress = options.progress;  // the caller's, not the relay's
    done[k] = true;
  };
  try {
    parallelFor(count, threads, plan, [&](double) {
      try {
        handOver(count);
      } catch (...) {
        stopped = true;
        throw;
      }
    });
  } catch (...) {
    // As one mode after the other: the tours before the first that failed are handed over.
    if (!stopped) handOver(first_failed);
    throw;
  }
  handOver(count);
  std::vector<TourResult> results;
  results.reserve(count);
  for (std::unique_ptr<TourResult>& tour : tours) results.push_back(std::move(*tour));
  return results;
}

}  // namespace ceilplan::mission
