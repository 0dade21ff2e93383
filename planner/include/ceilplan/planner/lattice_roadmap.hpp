#pragma once
// One roadmap for every query between a fixed set of places (a tour's home and viewpoints).
// The lattice of LatticePlanner (voxel centres every `stride` voxels, 26-connected) with every
// node and edge checked and costed once, both directions of an edge from one pass over its
// samples, on several threads; then one Dijkstra search per place gives its cheapest lattice
// route to every other place. Deterministic: the same inputs give the same routes, whatever
// the thread count.
//
// With a standoff (free mode) the rules' exemption applies, as for a single query, around the
// route's own start and goal only: a route from A may come close to the structure near A and
// near its goal B, never near a third place C. The search runs over the lattice with A's
// approach zone and, for every goal B, over a copy of B's approach zone that the route enters
// for good. docs/planner.md, "Roadmap".

#include "ceilplan/planner/flight_objective.hpp"
#include "ceilplan/planner/safety_rules.hpp"
#include "ceilplan/core/error.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace ceilplan::planner {

struct RoadmapOptions {
  int stride_voxels = 4;                  // lattice spacing in voxels
  int workers = 2;                        // threads building the roadmap
  std::function<void(double)> progress;  // share of the build done, called from the constructing thread
};

struct RoadmapRoute {
  std::vector<Eigen::Vector3d> waypoints;  // the start place, the lattice nodes where the route turns, the goal place
  double cost = 0.0;                       // under the objective
};

class LatticeRoadmap {
 public:
  // `rules` and `objective` must outlive the roadmap; the centres `rules` exempts from its
  // standoff are replaced by each route's start and goal. Throws ceilplan::InputError for a
  // stride or worker count below 1, or a place outside the map.
  LatticeRoadmap(const SafetyRules& rules, const FlightObjective& objective, std::vector<Eigen::Vector3d> places_m,
                 RoadmapOptions options = {});

  // The cheapest roadmap route from place `from` to every place; entry `from`, and places the
  // roadmap does not join, stay empty. Safe to call from several threads at once.
  std::vector<std::optional<RoadmapRoute>> routesFrom(int from) const;

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
  // Straight motions between a place and the lattice nodes within joining reach.
  struct Join {
    std::uint32_t node;
    double cost;
  };

  void buildNodes();
  void buildEdges(const std::function<void(double)>& progress);
  void buildPlaces();
  float coreCost(std::uint32_t node, int direction) const;

  const SafetyRules& rules_;
  SafetyRules core_rules_;  // without any exemption: what holds along the way
  const FlightObjective& objective_;
  std::vector<Eigen::Vector3d> places_m_;
  RoadmapOptions options_;
  std::size_t node_count_ = 0;
  std::vector<std::uint32_t> slot_;         // lattice node -> row of core_costs_, or kNoSlot
  std::vector<std::uint32_t> valid_nodes_;  // rows of core_costs_ -> lattice node
  std::vector<float> core_costs_;           // 26 per valid node, +inf where no valid edge
  std::vector<Zone> zones_;                 // per place; empty without a standoff
  std::vector<std::vector<Join>> joins_out_, joins_in_;  // per place
  double zone_radius_m_ = 0.0;
};

}  // namespace ceilplan::planner
