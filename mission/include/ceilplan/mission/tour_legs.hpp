#pragma once
// The legs of an inspection tour: a path between every ordered pair of places (home and the
// targets' viewpoints), found on several threads in one of two ways: one search per place over
// a shared roadmap (every leg its own route, raw until a plan flies it), or one search per
// unordered pair (the path flown both ways, post-processed at once). The map index, energy
// model and cost models are shared read-only.

#include "ceilplan/planner/path_evaluation.hpp"

#include <Eigen/Core>

#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace ceilplan::mission {

// Share of a stage done, from the calling thread.
using FractionCallback = std::function<void(double)>;

struct TourLeg {
  std::vector<Eigen::Vector3d> waypoints;  // from the leg's first place to its second
  planner::PathEvaluation evaluation;      // flown at the start SOC with the full model
  bool refined = false;                    // post-processed (shortcuts and NLopt refinement)
};
using LegTable = std::vector<std::vector<TourLeg>>;  // legs[i][j] for i != j; legs[i][i] stays empty

// Scores a path.
using LegScorer = std::function<planner::PathEvaluation(const std::vector<Eigen::Vector3d>&)>;

// One search per unordered pair: `plan(i, j)` (i < j) gives the post-processed path, flown
// back reversed. Throws the first failure by pair order.
using PairPlanner = std::function<std::vector<Eigen::Vector3d>(int from, int to)>;
LegTable planLegsByPair(int place_count, const PairPlanner& plan, const LegScorer& score, int workers,
                        const FractionCallback& progress);

// One search per place: `routes_from(i)` gives raw paths from place i to every place (entry i
// unused). Throws the first failure by place order.
using RoutesFrom = std::function<std::vector<std::vector<Eigen::Vector3d>>(int from)>;
LegTable planLegsByPlace(int place_count, const RoutesFrom& routes_from, const LegScorer& score, int workers,
                         const FractionCallback& progress);

// Post-processes the legs `which` (ordered pairs) with `refine` and scores them again.
using LegRefiner = std::function<std::vector<Eigen::Vector3d>(int from, int to, const std::vector<Eigen::Vector3d>&)>;
void refineLegs(LegTable& legs, const std::vector<std::pair<int, int>>& which, const LegRefiner& refine,
                const LegScorer& score, int workers, const FractionCallback& progress);

}  // namespace ceilplan::mission
