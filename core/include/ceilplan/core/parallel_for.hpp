#pragma once
// ceilplan's one way of spreading independent work over threads (index building, roadmap,
// tour legs): indices handed out in order, progress reported from the calling thread, the first
// failure rethrown.

#include <cstddef>
#include <functional>

namespace ceilplan {

// Runs task(i) for every i in [0, count) on `workers` threads (at least one), each taking the
// next index in turn. While it waits, the calling thread calls `progress` (if set) with the
// share of tasks done, every 100 ms. After a task throws, no new task starts; the exception of
// the lowest failing index is rethrown once every thread has stopped.
void parallelFor(std::size_t count, int workers, const std::function<void(std::size_t)>& task,
                 const std::function<void(double)>& progress = {});

}  // namespace ceilplan
