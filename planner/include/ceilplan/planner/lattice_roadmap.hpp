#pragma once
/// @file
/// One roadmap for many queries, as an OMPL planner ("roadmap"): the lattice of LatticePlanner
/// (LatticeSettings::spacing_m apart, 26-connected) with each node and edge checked and costed
/// once, when a search first needs it (both directions of an edge from one pass over its
/// samples), so the cost follows the searches, not the map; the routes are the same as on the
/// lattice checked everywhere (completeGraph). Like
/// PRM it is multi-query: solve() builds it on first use for the problem's objective, and
/// clearQuery() forgets the query but keeps the roadmap. A tour builds it for a fixed set of
/// places instead (build) and searches once per place (routesFrom: one Dijkstra search gives
/// the cheapest route to every other place). The searches are lazy in the edges, as OMPL's
/// LazyPRM is: an edge waits at a lower bound of its cost and is checked and costed only if
/// the search still needs it then; the routes are those of a search that costs every edge it
/// meets, to the bit. Deterministic: the same inputs give the same routes, whatever the thread
/// count. docs/planner.md, "Roadmap".
///
/// Where the lattice leaves places apart, it refines as the lattice A* does: between the part
/// of the roadmap a place reaches and the parts the others reach, a fine search near their
/// closest points; a passage found joins the roadmap as extra vertices and edges. Places still
/// apart get a blockage saying where and by which rule the way is blocked.

#include "ceilplan/planner/flight_objective.hpp"
#include "ceilplan/planner/lattice_planner_base.hpp"
#include "ceilplan/planner/safety_rules.hpp"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace ceilplan::planner {
namespace detail {
class LazyLattice;
class ValidityCells;
class ElevationBound;
}  // namespace detail

/// A route through the roadmap between two places.
struct RoadmapRoute {
  std::vector<Eigen::Vector3d> waypoints;  ///< the start place, the lattice nodes where the route turns, the goal place
  double cost = 0.0;                       ///< under the objective
};

/// What the safety rules allow on a roadmap's lattice: each node's validity and each lattice
/// edge's, checked once, when a roadmap first needs it. Roadmaps under the same safety rules and
/// spacing may share one (LatticeRoadmap::build): a tour's two modes differ in what a motion
/// costs, not in where the vehicle may fly, so between them each node and edge is checked once.
/// Safe to use from several threads at once.
class LatticeValidity {
 public:
  /// Keeps a reference to `rules`, which must outlive it. Throws ceilplan::InputError for a
  /// spacing outside the lattice planners' range or too fine for the map.
  LatticeValidity(const SafetyRules& rules, double spacing_m);
  ~LatticeValidity();
  LatticeValidity(const LatticeValidity&) = delete;
  LatticeValidity& operator=(const LatticeValidity&) = delete;

  const SafetyRules& rules() const;      ///< the rules it checks
  double spacing_m() const;              ///< between lattice nodes, rounded to whole voxels
  std::size_t checkedEdgeCount() const;  ///< lattice edges checked so far (once for both ways)

 private:
  friend class LatticeRoadmap;
  std::unique_ptr<detail::ValidityCells> cells_;
};

/// ceilplan's lattice roadmap: one lattice searched from many places, deterministic (planner name "roadmap", the tours'
/// default).
class LatticeRoadmap : public LatticePlannerBase {
 public:
  /// The space's validity checker must be a FlightStateValidityChecker. Throws
  /// ceilplan::InputError for bad settings.
  explicit LatticeRoadmap(const ompl::base::SpaceInformationPtr& si, LatticeSettings settings = {});
  ~LatticeRoadmap() override;

  /// Builds the roadmap for `objective` (which must outlive it), joins `places_m` to it and
  /// refines it until they are joined where the map allows, reporting progress through
  /// LatticeSettings::progress. Checks only the lattice between the places unless they lie in
  /// parts of it that no lattice edge joins (then every node and edge, which the refinement
  /// needs). With `validity`, takes what it has checked and adds what this roadmap checks
  /// (null: a validity of its own). Throws ceilplan::InputError for a place outside the map, a
  /// map with too many lattice nodes for the spacing, or a `validity` made for another map,
  /// other safety rules or another spacing.
  void build(const FlightObjective& objective, std::vector<Eigen::Vector3d> places_m,
             std::shared_ptr<const LatticeValidity> validity = nullptr);
  /// Checks and costs every node and edge now, on LatticeSettings::workers threads: the routes
  /// stay the same, later searches find every edge costed.
  void completeGraph();

  /// The cheapest roadmap route from place `from` to every place; entry `from`, and places the
  /// roadmap does not join, stay empty. Safe to call from several threads at once.
  std::vector<std::optional<RoadmapRoute>> routesFrom(int from) const;
  /// The same for the places `goals` only (other entries stay empty): the search stops once it
  /// has reached them, so near goals cost a search of their neighbourhood only.
  std::vector<std::optional<RoadmapRoute>> routesFrom(int from, const std::vector<int>& goals) const;
  /// For two places the roadmap does not join: where the way between their parts of the map is
  /// blocked, and by which rule; nothing for places it joins.
  std::optional<Blockage> blockage(int from, int to) const;

  /// OMPL: builds the roadmap on first use (or for a new objective; `ptc` may stop the build:
  /// TIMEOUT), joins start and goal (a GoalState), refining where needed, and returns the
  /// cheapest route, or the straight motion where valid and cheaper, as the lattice A* does
  /// (EXACT_SOLUTION), or ABORT when they stay apart (lastBlockage() says where).
  ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition& ptc) override;
  using ompl::base::Planner::solve;
  void clearQuery() override;  ///< keeps the roadmap and the places
  void clear() override;       ///< forgets everything
  /// OMPL: the roadmap as planner data.
  void getPlannerData(ompl::base::PlannerData& data) const override;

  /// Whether the roadmap has been built.
  bool built() const { return objective_ != nullptr; }
  /// The places joined to it.
  const std::vector<Eigen::Vector3d>& places() const { return places_m_; }
  /// Lattice nodes over the map.
  std::size_t nodeCount() const { return node_count_; }
  std::size_t validNodeCount() const;  ///< lattice nodes checked so far and valid (by any roadmap sharing its validity)
  std::size_t edgeCount() const;       ///< directed lattice edges costed so far
  std::size_t bridgeVertexCount() const { return bridge_positions_m_.size(); }  ///< added by refinement
  /// Memory held, bytes.
  std::size_t memoryBytes() const;

 private:
  /// Search states: lattice nodes [0, node count), then the vertices refinement added.
  /// A straight motion between a place and a state: a lattice node within joining reach, or a
  /// vertex a refinement put on the place.
  struct Join {
    std::uint32_t state;
    double cost;
  };
  /// What the search needs of a place: its joins both ways.
  struct Place {
    std::vector<Join> out, in;
  };
  /// A directed edge refinement added.
  struct Arc {
    std::uint32_t to;
    float cost;
  };

  /// Starts the lattice for `objective`, nothing costed yet, with `validity` (null: its own).
  void startGraph(const FlightObjective& objective, std::shared_ptr<const LatticeValidity> validity);
  /// Every node and edge; false when `abandon` stopped it (what was checked stays).
  bool checkEverything(const std::function<bool()>& abandon);
  void dropGraph();
  /// Checked on first use, from any thread: a node's validity, the cost of the edge out of
  /// `node` in `direction` (+inf where there is none).
  bool nodeValid(std::uint32_t node) const;
  float edgeCost(std::uint32_t node, int direction) const;
  void costEdge(std::uint32_t node, int direction) const;  ///< both ways, from a valid node
  /// Whether each place's first join lies in the part of the lattice place 0's first join lies
  /// in: what the refinement's partition finds before it adds anything.
  bool placesJoined(const std::vector<Place>& places) const;
  std::vector<Place> joinPlaces(const std::vector<Eigen::Vector3d>& places_m) const;
  /// Refines until every place is joined to the others where the map allows; the blockage of
  /// each place left apart (nothing for the others).
  std::vector<std::optional<Blockage>> connect(const std::vector<Eigen::Vector3d>& places_m, std::vector<Place>& places,
                                               const ompl::base::PlannerTerminationCondition& ptc);
  /// Adds a passage (turning points) between two states, or a place (then a vertex on it).
  void addBridge(const std::vector<Eigen::Vector3d>& waypoints, std::optional<std::uint32_t> from_state,
                 std::optional<std::uint32_t> to_state, Place* from_place, Place* to_place);
  std::uint32_t addVertex(const Eigen::Vector3d& position_m);
  Eigen::Vector3d statePosition(std::uint32_t state) const;
  /// From place `from` to `goals` (every other place when empty).
  std::vector<std::optional<RoadmapRoute>> search(const std::vector<Eigen::Vector3d>& places_m,
                                                  const std::vector<Place>& places, int from,
                                                  const std::vector<int>& goals = {}) const;

  void settingsChanged() override { clear(); }

  const SafetyRules* rules_ = nullptr;          ///< behind the space's validity checker
  const FlightObjective* objective_ = nullptr;  ///< the roadmap's costs; null until built
  std::size_t node_count_ = 0;
  std::unique_ptr<detail::LazyLattice> lattice_;          ///< what is costed so far
  std::shared_ptr<const LatticeValidity> validity_;       ///< what is checked so far, maybe shared
  std::unique_ptr<detail::ElevationBound> bound_;         ///< the searches' heuristic, for objective_
  std::array<double, 26> edge_bounds_{};                  ///< its value along each lattice direction
  std::vector<std::uint32_t> valid_nodes_;                ///< every valid node, once checkEverything ran
  bool complete_ = false;                                 ///< checkEverything ran
  std::vector<Eigen::Vector3d> bridge_positions_m_;       ///< vertices refinement added
  std::vector<std::vector<Arc>> bridge_arcs_;             ///< out of each of them
  std::vector<std::pair<std::uint32_t, Arc>> node_arcs_;  ///< out of lattice nodes, sorted by node
  std::vector<Eigen::Vector3d> places_m_;                 ///< build()'s places
  std::vector<Place> places_;
  std::vector<std::optional<Blockage>> place_blockages_;  ///< of build()'s places left apart
};

}  // namespace ceilplan::planner
