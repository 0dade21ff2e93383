// A large tour's leg estimates (docs/tours.md, "Large tours"): the legs between near neighbours
// are estimated both ways at once, reading the map once for the two, and each direction must be
// the leg estimating it alone gives, to the bit: the straight line where it is valid, else the
// L or dogleg of least charge that way, else the straight line at twice its charge; each scored
// with the full model, its totals alone kept.

#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/mission/planning_context.hpp"
#include "ceilplan/mission/tour_planner.hpp"
#include "ceilplan/planner/path_evaluation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace ceilplan::mission {
namespace {

const std::filesystem::path kMaps = std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps";

// The leg from `a` to `b` as an estimate of that direction alone sees it.
std::vector<Eigen::Vector3d> estimatedAlone(const PlanningContext::Mode& planning, const Eigen::Vector3d& a,
                                            const Eigen::Vector3d& b, bool& blocked) {
  blocked = false;
  if (planning.rules->isMotionValid(a, b)) return {a, b};
  const Eigen::Vector3d middle = 0.5 * (a + b);
  const std::array<Eigen::Vector3d, 6> turns{
      Eigen::Vector3d(b.x(), b.y(), a.z()),    Eigen::Vector3d(a.x(), a.y(), b.z()),
      middle + 0.5 * Eigen::Vector3d::UnitZ(), middle - 0.5 * Eigen::Vector3d::UnitZ(),
      middle + Eigen::Vector3d::UnitZ(),       middle - Eigen::Vector3d::UnitZ()};
  std::optional<Eigen::Vector3d> best;
  double best_ah = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& turn : turns) {
    if ((turn - a).norm() < 1e-6 || (turn - b).norm() < 1e-6 || !planning.rules->isStateValid(turn) ||
        !planning.rules->isMotionValid(a, turn) || !planning.rules->isMotionValid(turn, b))
      continue;
    const double ah = planning.model->integrate(a, turn).charge_ah + planning.model->integrate(turn, b).charge_ah;
    if (ah < best_ah) best_ah = ah, best = turn;
  }
  if (best) return {a, *best, b};
  blocked = true;
  return {a, b};
}

struct Counts {
  int pairs = 0, straight = 0, turns = 0, blocked = 0;
};

// Plans `mission` in `mode` and checks every leg still as estimated (neither refined nor out of
// home) against the estimate of its direction alone.
Counts expectEstimatesAsAlone(const Mission& mission, FlightMode mode, const TourOptions& options) {
  const PlanningContext context(mission);
  const TourResult tour = planTour(mission, context, mode, options);
  const PlanningContext::Mode planning = context.mode(mode);
  std::set<std::pair<int, int>> flown;
  for (const Sortie& sortie : tour.plan.sorties)
    for (const SortieLeg& leg : sortie.legs) flown.emplace(leg.from, leg.to);
  Counts counts;
  for (int from = 1; from < tour.legs.placeCount(); ++from) {
    for (const auto& [to, leg] : tour.legs.row(from)) {
      if (to == 0 || leg.refined) continue;
      const Eigen::Vector3d &a = tour.places_m[from], &b = tour.places_m[to];
      bool blocked = false;
      const std::vector<Eigen::Vector3d> alone = estimatedAlone(planning, a, b, blocked);
      EXPECT_EQ(leg.waypoints, alone) << tour.names[from] << " -> " << tour.names[to];
      EXPECT_EQ(leg.routed, !blocked) << tour.names[from] << " -> " << tour.names[to];
      if (flown.count({from, to})) continue;                 // scored in full for the flight record
      double cap = std::numeric_limits<double>::infinity();  // photo to photo: the slower camera's speed
      if (tour.stops[from - 1].photo && tour.stops[to - 1].photo)
        for (const int place : {from, to})
          if (const std::optional<double>& speed = tour.stops[place - 1].max_speed_m_s) cap = std::min(cap, *speed);
      const planner::PathEvaluation full =
          planner::evaluatePath(context.fullModel(), context.battery().pack, tour.start_soc, alone, cap);
      // Bit for bit: EXPECT_EQ on doubles.
      EXPECT_EQ(leg.evaluation.charge_ah, blocked ? 2.0 * full.charge_ah : full.charge_ah)
          << tour.names[from] << " -> " << tour.names[to];
      EXPECT_EQ(leg.evaluation.duration_s, full.duration_s) << tour.names[from] << " -> " << tour.names[to];
      EXPECT_EQ(leg.evaluation.mean_current_a, full.mean_current_a) << tour.names[from] << " -> " << tour.names[to];
      EXPECT_EQ(leg.evaluation.length_m, full.length_m) << tour.names[from] << " -> " << tour.names[to];
      EXPECT_TRUE(leg.evaluation.samples.empty());
      if (from < to && tour.legs.contains(to, from)) ++counts.pairs;
      if (blocked) {
        ++counts.blocked;
      } else if (alone.size() == 2) {
        ++counts.straight;
      } else {
        ++counts.turns;
      }
    }
  }
  return counts;
}

// The bridge's 13 targets as a large tour: viewpoints among the girders, where near neighbours'
// straight lines are often blocked.
TEST(LegEstimates, EachDirectionOfAPairIsTheLegEstimatedAloneAmongTheGirders) {
  const Mission mission = io::readMission(kMaps / "bridge.yaml");
  TourOptions options;
  options.all_pairs_max_places = 2;  // sparse legs
  const Counts counts = expectEstimatesAsAlone(mission, FlightMode::Ceiling, options);
  EXPECT_GT(counts.pairs, 20);
  EXPECT_GT(counts.straight, 0);
  EXPECT_GT(counts.turns + counts.blocked, 0);
}

// Photos on the move (legs capped at the camera's speed) in free mode.
TEST(LegEstimates, EachDirectionOfAPairIsTheLegEstimatedAloneBetweenPhotos) {
  const Mission mission = io::readMission(kMaps / "coverage/tunnel_crown.yaml");
  const Counts counts = expectEstimatesAsAlone(mission, FlightMode::Free, TourOptions{});
  EXPECT_GT(counts.pairs, 100);
  EXPECT_GT(counts.straight, 0);
}

}  // namespace
}  // namespace ceilplan::mission
