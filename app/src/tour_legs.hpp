#pragma once
// The legs of an inspection tour: a path between every pair of places (home and the targets'
// viewpoints), planned once per unordered pair on several threads and flown both ways, since
// climbing costs more charge than descending. The map index, energy model and cost models are
// shared read-only; each query builds its own planner objects.

#include "output.hpp"

#include "ceilplan/planner/path_evaluation.hpp"

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

namespace ceilplan::app {

struct TourLeg {
  std::vector<Eigen::Vector3d> waypoints;  // from the leg's first place to its second
  planner::PathEvaluation evaluation;      // flown at the start SOC with the full model
};

// Plans a path between places `from` and `to` (indices, from < to); throws naming the places.
using LegPathPlanner = std::function<std::vector<Eigen::Vector3d>(int from, int to)>;
// Scores a path, either direction.
using LegScorer = std::function<planner::PathEvaluation(const std::vector<Eigen::Vector3d>&)>;

// legs[i][j] for i != j over `place_count` places; legs[i][i] stays empty. Runs `workers`
// threads over the pairs (in a fixed order, so the result does not depend on scheduling when
// the planner is deterministic). The first failure, by pair order, is rethrown after the others
// stop. `progress` is updated from the calling thread only.
std::vector<std::vector<TourLeg>> planTourLegs(int place_count, const LegPathPlanner& plan, const LegScorer& score,
                                               int workers, Progress& progress);

}  // namespace ceilplan::app
