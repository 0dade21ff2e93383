#include "ceilplan/mission/tour_legs.hpp"

#include "ceilplan/core/parallel_for.hpp"

namespace ceilplan::mission {

LegTable planLegsByPair(int place_count, const PairPlanner& plan, const LegScorer& score, int workers,
                        const FractionCallback& progress) {
  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i < place_count; ++i)
    for (int j = i + 1; j < place_count; ++j) pairs.emplace_back(i, j);
  LegTable legs(place_count, std::vector<TourLeg>(place_count));
  parallelFor(
      pairs.size(), workers,
      [&](std::size_t k) {
        const auto [i, j] = pairs[k];
        TourLeg there{plan(i, j), {}, true};
        there.evaluation = score(there.waypoints);
        TourLeg back{{there.waypoints.rbegin(), there.waypoints.rend()}, {}, true};
        back.evaluation = score(back.waypoints);
        legs[i][j] = std::move(there);  // each pair's cells are written by one task only
        legs[j][i] = std::move(back);
      },
      progress);
  return legs;
}

LegTable planLegsByPlace(int place_count, const RoutesFrom& routes_from, const LegScorer& score, int workers,
                         const FractionCallback& progress) {
  LegTable legs(place_count, std::vector<TourLeg>(place_count));
  parallelFor(
      static_cast<std::size_t>(place_count), workers,
      [&](std::size_t from) {
        std::vector<std::vector<Eigen::Vector3d>> routes = routes_from(static_cast<int>(from));
        for (int to = 0; to < place_count; ++to) {
          if (to == static_cast<int>(from)) continue;
          TourLeg& leg = legs[from][to];  // row `from` is written by this task only
          leg.waypoints = std::move(routes[to]);
          leg.evaluation = score(leg.waypoints);
        }
      },
      progress);
  return legs;
}

void refineLegs(LegTable& legs, const std::vector<std::pair<int, int>>& which, const LegRefiner& refine,
                const LegScorer& score, int workers, const FractionCallback& progress) {
  parallelFor(
      which.size(), workers,
      [&](std::size_t k) {
        const auto [from, to] = which[k];
        TourLeg& leg = legs[from][to];  // `which` names each leg once
        leg.waypoints = refine(from, to, leg.waypoints);
        leg.evaluation = score(leg.waypoints);
        leg.refined = true;
      },
      progress);
}

}  // namespace ceilplan::mission
