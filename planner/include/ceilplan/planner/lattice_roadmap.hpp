#pragma once
// One roadmap for many queries, as an OMPL planner ("roadmap"): the lattice of LatticePlanner
// (LatticeSettings::spacing_m apart, 26-connected) with every node and edge checked and costed
// once, both directions of an edge from one pass over its samples, on several threads. Like
// PRM it is multi-query: solve() builds it on first use for the problem's objective, and
// clearQuery() forgets the query but keeps the roadmap. A tour builds it for a fixed set of
// places instead (build) and searches once per place (routesFrom: one Dijkstra search gives
// the cheapest route to every other place). Deterministic: the same inputs give the same
// routes, whatever the thread count.
//
// With a standoff (free mode) the rules' exemption applies, as for a single query, around the
// route's own start and goal only: a route from A may come close to the structure near A and
// near its goal B, never near a third place C. The search runs over the lattice with A's
// approach zone and, for every goal B, over a copy of B's approach zone that the route enters
// for good. docs/planner.md, "Roadmap".

#include "ceilplan/planner/flight_objective.hpp"
#include "ceilplan/planner/lattice_settings.hpp"
#include "ceilplan/planner/safety_rules.hpp"

#include <Eigen/Core>
#include <ompl/base/Planner.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace ceilplan::planner {

struct RoadmapRoute {
  std::vector<Eigen::Vector3d> waypoints;  // the start place, the lattice nodes where the route turns, the goal place
  double cost = 0.0;                       // under the objective
};

class LatticeRoadmap : public ompl::base::Planner {
 public:
  // The space's validity checker must be a FlightStateValidityChecker; the centres its rules
  // exempt from a standoff are replaced by each route's start and goal. Throws
  // ceilplan::InputError for bad settings.
  explicit LatticeRoadmap(const ompl::base::SpaceInformationPtr& si, LatticeSettings settings = {});

  // Builds the roadmap for `objective` (which must outlive it) and joins `places_m` to it,
  // reporting progress through LatticeSettings::progress. Throws ceilplan::InputError for a
  // place outside the map, or a map with too many lattice nodes for the spacing.
  void build(const FlightObjective& objective, std::vector<Eigen::Vector3d> places_m);

  // The cheapest roadmap route from place `from` to every place; entry `from`, and places the
  // roadmap does not join, stay empty. Safe to call from several threads at once.
  std::vector<std::optional<RoadmapRoute>> routesFrom(int from) const;

  // OMPL: builds the roadmap on first use (or for a new objective; `ptc` may stop the build:
  // TIMEOUT), joins start and goal (a GoalState) and returns the cheapest route
  // (EXACT_SOLUTION) or ABORT when the roadmap does not join them.
  ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition& ptc) override;
  using ompl::base::Planner::solve;
  void clearQuery() override;  // keeps the roadmap and the places
  void clear() override;       // forgets everything
  void getPlannerData(ompl::base::PlannerData& data) const override;

  const LatticeSettings& settings() const { return settings_; }
  void setSpacing(double spacing_m);
  double getSpacing() const { return settings_.spacing_m; }

  bool built() const { return objective_ != nullptr; }
  const std::vector<Eigen::Vector3d>& places() const { return places_m_; }
  std::size_t nodeCount() const { return node_count_; }
  std::size_t validNodeCount() const { return valid_nodes_.size(); }
  std::size_t edgeCount() const;  // directed lattice edges valid everywhere
  std::size_t memoryBytes() const;

 private:
  // A place's approach zone (free mode): the lattice nodes near it that are valid under the
  // rules exempting it, with their edges under those rules.
  struct Zone {
    std::vector<std::uint32_t> nodes;  // lattice node ids, ascending
    std::vector<float> costs;          // 26 per node, +inf where no valid edge
    std::optional<std::uint32_t> slotOf(std::uint32_t node) const;
  };
  // A straight motion between a place and a lattice node within joining reach.
  struct Join {
    std::uint32_t node;
    double cost;
  };
  // What the search needs of a place: its zone and its joins both ways.
  struct Place {
    Zone zone;
    std::vector<Join> out, in;
  };

  // Checks and costs every node and edge; false when `abandon` stopped it (nothing kept).
  bool buildGraph(const FlightObjective& objective, const std::function<bool()>& abandon);
  void dropGraph();
  std::vector<Place> joinPlaces(const std::vector<Eigen::Vector3d>& places_m) const;
  float coreCost(std::uint32_t node, int direction) const;
  std::vector<std::optional<RoadmapRoute>> search(const std::vector<Eigen::Vector3d>& places_m,
                                                  const std::vector<Place>& places, int from) const;

  LatticeSettings settings_;
  const SafetyRules* rules_ = nullptr;           // behind the space's validity checker
  std::optional<SafetyRules> core_rules_;        // without any exemption: what holds along the way
  const FlightObjective* objective_ = nullptr;   // the roadmap's costs; null until built
  std::size_t node_count_ = 0;
  std::vector<std::uint32_t> slot_;         // lattice node -> row of core_costs_, or kNoSlot
  std::vector<std::uint32_t> valid_nodes_;  // rows of core_costs_ -> lattice node
  std::vector<float> core_costs_;           // 26 per valid node, +inf where no valid edge
  std::vector<Eigen::Vector3d> places_m_;   // build()'s places
  std::vector<Place> places_;
  std::atomic<double> best_cost_;
};

}  // namespace ceilplan::planner
