#pragma once
/// @file
/// The legs of an inspection tour: paths between ordered pairs of places (home and the stops'
/// viewpoints), found on several threads in one of three ways: one search per place over a
/// shared roadmap (every leg its own route, raw until a plan flies it), one search per unordered
/// pair (the path flown both ways, post-processed at once), or, in a tour of many places, an
/// estimate first (the straight line, scored) routed only once a plan flies it. The map index,
/// energy model and cost models are shared read-only.

#include "ceilplan/mission/pair_table.hpp"
#include "ceilplan/planner/path_evaluation.hpp"

#include <Eigen/Core>

#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace ceilplan::mission {

/// Share of a stage done, from the calling thread.
using FractionCallback = std::function<void(double)>;

/// One leg of a tour: the path between two places and its figures.
struct TourLeg {
  std::vector<Eigen::Vector3d> waypoints;  ///< from the leg's first place to its second
  planner::PathEvaluation evaluation;      ///< flown at the start SOC with the full model
  /// false: an estimate, the straight line scored without asking whether it is valid (a tour of
  /// many places estimates the legs it may fly and routes those it does).
  bool routed = true;
  bool refined = false;  ///< post-processed (shortcuts and NLopt refinement)
};
using LegTable = PairTable<TourLeg>;  ///< legs[i][j] for the pairs stored

/// Scores the path of the leg from one place to another.
using LegScorer = std::function<planner::PathEvaluation(int from, int to, const std::vector<Eigen::Vector3d>&)>;

/// One search per unordered pair: `plan(i, j)` (i < j) gives the post-processed path, flown
/// back reversed. Throws the first failure by pair order.
using PairPlanner = std::function<std::vector<Eigen::Vector3d>(int from, int to)>;
/// Plans every unordered pair with `plan`, scores both directions with `score`, on `workers` threads.
LegTable planLegsByPair(int place_count, const PairPlanner& plan, const LegScorer& score, int workers,
                        const FractionCallback& progress);

/// One search per place: `routes_from(i)` gives raw paths from place i to every place (entry i
/// unused). Throws the first failure by place order.
using RoutesFrom = std::function<std::vector<std::vector<Eigen::Vector3d>>(int from)>;
/// Plans the legs out of every place with `routes_from` and scores them with `score`, on `workers` threads.
LegTable planLegsByPlace(int place_count, const RoutesFrom& routes_from, const LegScorer& score, int workers,
                         const FractionCallback& progress);

/// Replaces the path of each leg of `which` (ordered pairs, each once, stored in `legs`) by what
/// `rework` makes of it and scores it again: routing an estimate (then `routed`) or
/// post-processing a raw leg (then `refined`).
using LegRework = std::function<std::vector<Eigen::Vector3d>(int from, int to, const std::vector<Eigen::Vector3d>&)>;
/// A post-processing rework (refineLegs).
using LegRefiner = LegRework;
/// Post-processes the legs `which` with `refine` and scores them again (then `refined`).
void refineLegs(LegTable& legs, const std::vector<std::pair<int, int>>& which, const LegRefiner& refine,
                const LegScorer& score, int workers, const FractionCallback& progress);
/// Routes the estimated legs `which` with `route` and scores them again (then `routed`).
void routeLegs(LegTable& legs, const std::vector<std::pair<int, int>>& which, const LegRework& route,
               const LegScorer& score, int workers, const FractionCallback& progress);

}  // namespace ceilplan::mission
