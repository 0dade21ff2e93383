#pragma once
/// @file
/// ceilplan's one way of spreading independent work over threads (index building, roadmap,
/// tour legs): indices handed out in order, progress reported from the calling thread, the first
/// failure rethrown.

#include <cstddef>
#include <functional>

namespace ceilplan {

/// Runs task(i) for every i in [0, count) on `workers` threads (at least one), each taking the
/// next index in turn. While it waits, the calling thread calls `progress` (if set) with the
/// share of tasks done, every 100 ms. After a task or `progress` throws, no new task starts; that
/// exception (a task's: the lowest failing index's) is rethrown once every thread has stopped.
/// A thread the system refuses (a limit on processes, threads or memory: ulimit -u, ulimit -v, a
/// container's pids.max) is not an error: the threads already started share the work, and if
/// none started the calling thread does it alone, reporting progress between tasks.
void parallelFor(std::size_t count, int workers, const std::function<void(std::size_t)>& task,
                 const std::function<void(double)>& progress = {});

namespace detail {

/// Test seam: when set, parallelFor calls it before starting its thread number `index` (from 0);
/// a hook that throws std::system_error stands for the system refusing that thread. Tests set it
/// while no parallelFor runs, and reset it with nullptr.
using ThreadStartHook = void (*)(std::size_t index);
void setThreadStartHook(ThreadStartHook hook);

}  // namespace detail
}  // namespace ceilplan
