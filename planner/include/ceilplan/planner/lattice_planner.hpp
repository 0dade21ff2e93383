#pragma once
// The deterministic reference: A* over a lattice of voxel centres (every `stride` voxels,
// 26-connected) with exactly the objective's motion cost (FlightCostModel::integrate; lattice
// motions sample the half-voxel lattice, whose map conditions are cached) and the admissible,
// consistent heuristic c_min x distance. Optimal over the lattice; the quality oracle.

#include "ceilplan/planner/flight_objective.hpp"
#include "ceilplan/planner/safety_rules.hpp"
#include "ceilplan/core/error.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace ceilplan::planner {

struct LatticeOptions {
  int stride_voxels = 2;                   // lattice spacing in voxels (1 = every voxel centre)
  std::size_t max_expansions = 50'000'000;
  std::function<bool()> should_stop;       // optional: polled every few thousand expansions
};

struct LatticeResult {
  std::vector<Eigen::Vector3d> waypoints;  // start, lattice nodes, goal
  double cost = 0.0;                       // under the objective
  std::size_t expansions = 0;
};

class LatticePlanner {
 public:
  // `rules` and `objective` must outlive the planner. Throws ceilplan::InputError on a
  // stride < 1.
  LatticePlanner(const SafetyRules& rules, const FlightObjective& objective, LatticeOptions options = {});

  // The cheapest lattice path from `start_m` to `goal_m` (both joined to lattice nodes within
  // sqrt(3) strides by straight motions), or nothing if none exists (or the search was stopped:
  // see stopped()).
  std::optional<LatticeResult> plan(const Eigen::Vector3d& start_m, const Eigen::Vector3d& goal_m);
  bool stopped() const { return stopped_; }

 private:
  const SafetyRules& rules_;
  const FlightObjective& objective_;
  LatticeOptions options_;
  bool stopped_ = false;
};

}  // namespace ceilplan::planner
