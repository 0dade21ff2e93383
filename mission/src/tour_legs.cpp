#include "ceilplan/mission/tour_legs.hpp"

#include "ceilplan/core/parallel_for.hpp"

namespace ceilplan::mission {
namespace {

enum class Rework { Route, Refine };

void rework(LegTable& legs, const std::vector<std::pair<int, int>>& which, const LegRework& make,
            const LegScorer& score, int workers, const FractionCallback& progress, Rework kind) {
  std::vector<TourLeg*> cells;
  cells.reserve(which.size());
  for (const auto& [from, to] : which) cells.push_back(&legs(from, to));  // stored before the threads start
  parallelFor(
      which.size(), workers,
      [&](std::size_t k) {
        const auto [from, to] = which[k];
        TourLeg& leg = *cells[k];  // `which` names each leg once
        leg.waypoints = make(from, to, leg.waypoints);
        leg.evaluation = score(from, to, leg.waypoints);
        leg.routed = true;
        if (kind == Rework::Refine) leg.refined = true;
      },
      progress);
}

}  // namespace

LegTable planLegsByPair(int place_count, const PairPlanner& plan, const LegScorer& score, int workers,
                        const FractionCallback& progress) {
  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i < place_count; ++i)
    for (int j = i + 1; j < place_count; ++j) pairs.emplace_back(i, j);
  LegTable legs(place_count);
  std::vector<std::pair<TourLeg*, TourLeg*>> cells;
  cells.reserve(pairs.size());
  for (const auto& [i, j] : pairs) cells.emplace_back(&legs(i, j), &legs(j, i));  // stored before the threads start
  parallelFor(
      pairs.size(), workers,
      [&](std::size_t k) {
        const auto [i, j] = pairs[k];
        TourLeg there{plan(i, j), {}, true, true};
        there.evaluation = score(i, j, there.waypoints);
        TourLeg back{{there.waypoints.rbegin(), there.waypoints.rend()}, {}, true, true};
        back.evaluation = score(j, i, back.waypoints);
        *cells[k].first = std::move(there);  // each pair's cells are written by one task only
        *cells[k].second = std::move(back);
      },
      progress);
  return legs;
}

LegTable planLegsByPlace(int place_count, const RoutesFrom& routes_from, const LegScorer& score, int workers,
                         const FractionCallback& progress) {
  LegTable legs(place_count);
  for (int from = 0; from < place_count; ++from)
    for (int to = 0; to < place_count; ++to)
      if (to != from) legs(from, to);  // stored before the threads start
  parallelFor(
      static_cast<std::size_t>(place_count), workers,
      [&](std::size_t from) {
        std::vector<std::vector<Eigen::Vector3d>> routes = routes_from(static_cast<int>(from));
        for (int to = 0; to < place_count; ++to) {
          if (to == static_cast<int>(from)) continue;
          TourLeg& leg = *legs.find(static_cast<int>(from), to);  // row `from` is written by this task only
          leg.waypoints = std::move(routes[to]);
          leg.evaluation = score(static_cast<int>(from), to, leg.waypoints);
        }
      },
      progress);
  return legs;
}

void refineLegs(LegTable& legs, const std::vector<std::pair<int, int>>& which, const LegRefiner& refine,
                const LegScorer& score, int workers, const FractionCallback& progress) {
  rework(legs, which, refine, score, workers, progress, Rework::Refine);
}

void routeLegs(LegTable& legs, const std::vector<std::pair<int, int>>& which, const LegRework& route,
               const LegScorer& score, int workers, const FractionCallback& progress) {
  rework(legs, which, route, score, workers, progress, Rework::Route);
}

}  // namespace ceilplan::mission
