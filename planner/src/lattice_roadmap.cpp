#include "ceilplan/planner/lattice_roadmap.hpp"
#include "ceilplan/core/format.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/parallel_for.hpp"

#include "elevation_bound.hpp"
#include "lattice_bridge.hpp"
#include "lattice_grid.hpp"
#include "lattice_query.hpp"

#include <ompl/base/PlannerData.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <queue>

namespace ceilplan::planner {
namespace {

constexpr float kNoEdge = std::numeric_limits<float>::infinity();
constexpr float kUncosted = -1.0f;  // no cost is negative
constexpr int kDirections = 26;
// Directions 13..25 point "forwards" (lexicographically after the node): each undirected edge
// is costed from its first node, both ways at once.
constexpr int kFirstForwardDirection = 13;
constexpr std::uint8_t kUnchecked = 0, kInvalid = 1, kValid = 2;

std::array<int, 3> neighbour(const std::array<int, 3>& at, const std::array<int, 3>& offset) {
  return {at[0] + offset[0], at[1] + offset[1], at[2] + offset[2]};
}

// The node next to `node` in `direction`, none at the lattice's edge.
std::optional<std::uint32_t> neighbourNode(const detail::LatticeGrid& lattice,
                                           const detail::LatticeDirections& directions, std::uint32_t node,
                                           int direction) {
  const std::array<int, 3> to = neighbour(lattice.indices(node), directions.offsets[direction]);
  if (!lattice.inside(to[0], to[1], to[2])) return std::nullopt;
  return static_cast<std::uint32_t>(lattice.id(to[0], to[1], to[2]));
}

}  // namespace

namespace detail {

// Chunks of `per_node` atomic cells for consecutive nodes, each allocated, filled with
// `initial`, when a node in it is first asked for, from any thread.
template <typename T>
class LazyCells {
 public:
  static constexpr std::size_t kChunkNodes = 256;

  LazyCells(std::size_t node_count, int per_node, T initial)
      : per_node_(per_node),
        initial_(initial),
        chunk_count_((node_count + kChunkNodes - 1) / kChunkNodes),
        chunks_(new std::atomic<std::atomic<T>*>[chunk_count_]) {
    for (std::size_t c = 0; c < chunk_count_; ++c) chunks_[c].store(nullptr, std::memory_order_relaxed);
  }
  ~LazyCells() {
    for (std::size_t c = 0; c < chunk_count_; ++c) delete[] chunks_[c].load(std::memory_order_relaxed);
  }
  LazyCells(const LazyCells&) = delete;
  LazyCells& operator=(const LazyCells&) = delete;

  std::atomic<T>& at(std::size_t node, int k) const {
    std::atomic<std::atomic<T>*>& slot = chunks_[node / kChunkNodes];
    std::atomic<T>* chunk = slot.load(std::memory_order_acquire);
    if (!chunk) {
      const std::size_t cells = kChunkNodes * per_node_;
      auto* fresh = new std::atomic<T>[cells];
      for (std::size_t c = 0; c < cells; ++c) fresh[c].store(initial_, std::memory_order_relaxed);
      if (slot.compare_exchange_strong(chunk, fresh, std::memory_order_acq_rel, std::memory_order_acquire)) {
        chunk = fresh;
      } else {
        delete[] fresh;  // another thread's chunk won
      }
    }
    return chunk[(node % kChunkNodes) * per_node_ + k];
  }
  // Calls visit(value) for every cell no longer at its initial value.
  template <typename Visit>
  void forEachSet(Visit&& visit) const {
    for (std::size_t c = 0; c < chunk_count_; ++c)
      if (const std::atomic<T>* chunk = chunks_[c].load(std::memory_order_acquire))
        for (std::size_t k = 0; k < kChunkNodes * per_node_; ++k) {
          const T value = chunk[k].load(std::memory_order_relaxed);
          if (value != initial_) visit(value);
        }
  }
  std::size_t memoryBytes() const {
    std::size_t chunks = 0;
    for (std::size_t c = 0; c < chunk_count_; ++c) chunks += chunks_[c].load(std::memory_order_relaxed) != nullptr;
    return chunk_count_ * sizeof(void*) + chunks * kChunkNodes * per_node_ * sizeof(T);
  }

 private:
  std::size_t per_node_;
  T initial_;
  std::size_t chunk_count_;
  std::unique_ptr<std::atomic<std::atomic<T>*>[]> chunks_;
};

// The lattice's costs so far, shared by the searches' threads: the 26 outgoing costs of each
// node. Every value is the same whichever thread computes it, so a race only computes one twice.
class LazyLattice {
 public:
  LazyLattice(const environment::GridFrame& frame, double spacing_m)
      : grid(frame, spacing_m), costs_(grid.nodeCount(), kDirections, kUncosted) {}

  std::atomic<float>& cost(std::size_t node, int direction) const { return costs_.at(node, direction); }
  // The node's 26 outgoing costs, in direction order.
  std::atomic<float>* costsOf(std::size_t node) const { return &costs_.at(node, 0); }
  template <typename Visit>
  void forEachCost(Visit&& visit) const {
    costs_.forEachSet(visit);
  }
  std::size_t memoryBytes() const { return costs_.memoryBytes(); }

  const LatticeGrid grid;
  const LatticeDirections directions;

 private:
  LazyCells<float> costs_;
};

// What the safety rules allow on the lattice so far: a byte per node and per edge (from its
// first node, in the 13 forward directions): unchecked, invalid or valid.
class ValidityCells {
 public:
  ValidityCells(const SafetyRules& rules, double spacing_m)
      : rules(rules),
        grid(rules.environment().grid().frame(), spacing_m),
        nodes_(new std::atomic<std::uint8_t>[grid.nodeCount()]),
        edges_(grid.nodeCount(), kDirections - kFirstForwardDirection, kUnchecked) {
    for (std::size_t n = 0; n < grid.nodeCount(); ++n) nodes_[n].store(kUnchecked, std::memory_order_relaxed);
  }

  bool nodeValid(std::size_t node) const {
    std::atomic<std::uint8_t>& cell = nodes_[node];
    std::uint8_t state = cell.load(std::memory_order_relaxed);
    if (state == kUnchecked) {
      state = rules.isStateValid(grid.position(node)) ? kValid : kInvalid;
      cell.store(state, std::memory_order_relaxed);
    }
    return state == kValid;
  }
  // The straight motion from `first` to its neighbour `second` in forward direction `direction`.
  bool edgeValid(std::size_t first, std::size_t second, int direction) const {
    std::atomic<std::uint8_t>& cell = edges_.at(first, direction - kFirstForwardDirection);
    std::uint8_t state = cell.load(std::memory_order_relaxed);
    if (state == kUnchecked) {
      state = rules.isMotionValid(grid.position(first), grid.position(second)) ? kValid : kInvalid;
      cell.store(state, std::memory_order_relaxed);
    }
    return state == kValid;
  }
  std::size_t validCount() const {
    std::size_t count = 0;
    for (std::size_t n = 0; n < grid.nodeCount(); ++n) count += nodes_[n].load(std::memory_order_relaxed) == kValid;
    return count;
  }
  std::size_t checkedEdgeCount() const {
    std::size_t count = 0;
    edges_.forEachSet([&count](std::uint8_t) { ++count; });
    return count;
  }
  std::size_t memoryBytes() const { return grid.nodeCount() + edges_.memoryBytes(); }

  const SafetyRules& rules;
  const LatticeGrid grid;

 private:
  std::unique_ptr<std::atomic<std::uint8_t>[]> nodes_;
  LazyCells<std::uint8_t> edges_;
};

}  // namespace detail

LatticeValidity::LatticeValidity(const SafetyRules& rules, double spacing_m) {
  LatticeSettings settings;
  settings.spacing_m = spacing_m;
  settings.validate();
  const detail::LatticeGrid lattice(rules.environment().grid().frame(), spacing_m);
  if (lattice.nodeCount() >= std::numeric_limits<std::uint32_t>::max())
    throw ceilplan::InputError("the map has too many lattice nodes for a " + formatNumber(lattice.spacing_m()) +
                               " m spacing: raise the spacing");
  cells_ = std::make_unique<detail::ValidityCells>(rules, spacing_m);
}

LatticeValidity::~LatticeValidity() = default;

const SafetyRules& LatticeValidity::rules() const { return cells_->rules; }

double LatticeValidity::spacing_m() const { return cells_->grid.spacing_m(); }

std::size_t LatticeValidity::checkedEdgeCount() const { return cells_->checkedEdgeCount(); }

LatticeRoadmap::LatticeRoadmap(const ompl::base::SpaceInformationPtr& si, LatticeSettings settings)
    : LatticePlannerBase(si, "roadmap", std::move(settings)) {
  specs_.multithreaded = true;
}

LatticeRoadmap::~LatticeRoadmap() = default;

void LatticeRoadmap::clearQuery() {
  pis_.restart();  // not Planner::clearQuery(), which clears everything
  forgetResult();
}

void LatticeRoadmap::clear() {
  ompl::base::Planner::clear();
  dropGraph();
  places_m_.clear();
  places_.clear();
  place_blockages_.clear();
  forgetResult();
}

void LatticeRoadmap::dropGraph() {
  objective_ = nullptr;
  node_count_ = 0;
  lattice_.reset();
  validity_.reset();
  bound_.reset();
  valid_nodes_.clear();
  complete_ = false;
  bridge_positions_m_.clear();
  bridge_arcs_.clear();
  node_arcs_.clear();
}

void LatticeRoadmap::build(const FlightObjective& objective, std::vector<Eigen::Vector3d> places_m,
                           std::shared_ptr<const LatticeValidity> validity) {
  rules_ = &detail::rulesOf(*si_, getName());
  for (const Eigen::Vector3d& place : places_m)
    if (!place.allFinite() || !rules_->environment().contains(place))
      throw ceilplan::InputError("a roadmap place lies outside the map");
  startGraph(objective, std::move(validity));
  places_m_ = std::move(places_m);
  places_ = joinPlaces(places_m_);
  place_blockages_ = connect(places_m_, places_, ompl::base::plannerNonTerminatingCondition());
  if (settings_.progress) settings_.progress(1.0);
}

void LatticeRoadmap::startGraph(const FlightObjective& objective, std::shared_ptr<const LatticeValidity> validity) {
  dropGraph();
  rules_ = &detail::rulesOf(*si_, getName());
  if (!validity) {
    validity = std::make_shared<const LatticeValidity>(*rules_, settings_.spacing_m);
  } else if (&validity->rules().environment() != &rules_->environment() ||
             validity->rules().minCeilingGap_m() != rules_->minCeilingGap_m() ||
             detail::strideVoxels(rules_->environment().grid().frame(), validity->spacing_m()) !=
                 detail::strideVoxels(rules_->environment().grid().frame(), settings_.spacing_m)) {
    throw ceilplan::InputError(
        "a shared lattice validity must be made for the roadmap's map, safety rules and spacing");
  }
  validity_ = std::move(validity);
  const detail::LatticeGrid& lattice = validity_->cells_->grid;
  lattice_ = std::make_unique<detail::LazyLattice>(rules_->environment().grid().frame(), settings_.spacing_m);
  node_count_ = lattice.nodeCount();
  objective_ = &objective;
  bound_ = std::make_unique<detail::ElevationBound>(objective);
  for (int d = 0; d < kDirections; ++d) {
    const std::array<int, 3>& offset = lattice_->directions.offsets[d];
    const Eigen::Vector3d edge_m = lattice.spacing_m() * Eigen::Vector3d(offset[0], offset[1], offset[2]);
    // At least c_min x length, so the A* heuristic (c_min x distance) stays consistent with it.
    edge_bounds_[d] =
        std::max((*bound_)(Eigen::Vector3d::Zero(), edge_m), objective.heuristic(Eigen::Vector3d::Zero(), edge_m));
  }
}

void LatticeRoadmap::completeGraph() {
  if (!built()) throw ceilplan::Error("the roadmap is not built: call build() first");
  checkEverything({});
}

bool LatticeRoadmap::checkEverything(const std::function<bool()>& abandon) {
  if (complete_) return true;
  // Shares of the time, roughly as on the shipped bridge: nodes 10 %, edges 90 %.
  std::atomic<bool> stop{false};
  const auto report = [&](double share) {
    if (settings_.progress) settings_.progress(share);
    if (abandon && abandon()) stop = true;
  };
  parallelFor(
      node_count_, settings_.workers,
      [&](std::size_t id) {
        if (!stop) nodeValid(static_cast<std::uint32_t>(id));
      },
      [&](double share) { report(0.1 * share); });
  if (stop) return false;
  std::vector<std::uint32_t> valid;
  for (std::size_t id = 0; id < node_count_; ++id)
    if (nodeValid(static_cast<std::uint32_t>(id))) valid.push_back(static_cast<std::uint32_t>(id));
  parallelFor(
      valid.size(), settings_.workers,
      [&](std::size_t row) {
        if (stop) return;
        for (int d = kFirstForwardDirection; d < kDirections; ++d) edgeCost(valid[row], d);
      },
      [&](double share) { report(0.1 + 0.9 * share); });
  if (stop) return false;
  valid_nodes_ = std::move(valid);
  complete_ = true;
  return true;
}

bool LatticeRoadmap::nodeValid(std::uint32_t node) const { return validity_->cells_->nodeValid(node); }

float LatticeRoadmap::edgeCost(std::uint32_t node, int direction) const {
  if (!nodeValid(node)) return kNoEdge;
  const std::atomic<float>& cell = lattice_->cost(node, direction);
  float cost = cell.load(std::memory_order_relaxed);
  if (cost == kUncosted) {
    costEdge(node, direction);
    cost = cell.load(std::memory_order_relaxed);
  }
  return cost;
}

void LatticeRoadmap::costEdge(std::uint32_t node, int direction) const {
  const detail::LatticeGrid& lattice = lattice_->grid;
  const detail::LatticeDirections& directions = lattice_->directions;
  std::atomic<float>& cell = lattice_->cost(node, direction);
  const std::optional<std::uint32_t> neighbour_node = neighbourNode(lattice, directions, node, direction);
  if (!neighbour_node || !nodeValid(*neighbour_node)) {
    cell.store(kNoEdge, std::memory_order_relaxed);
    return;
  }
  const std::uint32_t other = *neighbour_node;
  // Costed from the edge's first node, both ways at once, so the values are the same to the bit
  // however the lattice is explored.
  const bool forward = direction >= kFirstForwardDirection;
  const std::uint32_t first = forward ? node : other, second = forward ? other : node;
  const int first_direction = forward ? direction : directions.opposite[direction];
  const Eigen::Vector3d here = lattice.position(first), there = lattice.position(second);
  float forth = kNoEdge, back = kNoEdge;
  if (validity_->cells_->edgeValid(first, second, first_direction)) {
    const FlightCostModel& model = objective_->model();
    const auto [forth_totals, back_totals] = model.integrateBothWays(here, there);
    forth = static_cast<float>(objective_->weights().of(forth_totals));
    back = static_cast<float>(objective_->weights().of(back_totals));
  }
  lattice_->cost(first, first_direction).store(forth, std::memory_order_relaxed);
  lattice_->cost(second, directions.opposite[first_direction]).store(back, std::memory_order_relaxed);
}

bool LatticeRoadmap::placesJoined(const std::vector<Place>& places) const {
  if (places.empty()) return true;
  for (const Place& place : places)
    if (place.out.empty()) return false;
  const detail::LatticeGrid& lattice = lattice_->grid;
  // Nodes known to lie in place 0's part; from each other place, a walk towards it (nearest to
  // place 0's join first) over the edges it costs on the way, until it meets that part.
  std::vector<char> joined(node_count_, 0), seen(node_count_, 0);
  const std::uint32_t home = places.front().out.front().state;
  const Eigen::Vector3d home_m = lattice.position(home);
  joined[home] = 1;
  using Entry = std::pair<double, std::uint32_t>;
  for (std::size_t p = 1; p < places.size(); ++p) {
    const std::uint32_t start = places[p].out.front().state;
    if (joined[start]) continue;
    std::vector<std::uint32_t> walked{start};
    seen[start] = 1;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
    open.emplace(0.0, start);
    bool met = false;
    while (!open.empty() && !met) {
      const std::uint32_t node = open.top().second;
      open.pop();
      const std::array<int, 3> at = lattice.indices(node);
      for (int d = 0; d < kDirections && !met; ++d) {
        if (edgeCost(node, d) == kNoEdge) continue;
        const std::array<int, 3> to = neighbour(at, lattice_->directions.offsets[d]);
        const auto next = static_cast<std::uint32_t>(lattice.id(to[0], to[1], to[2]));
        if (joined[next]) met = true;
        if (seen[next]) continue;
        seen[next] = 1;
        walked.push_back(next);
        open.emplace((lattice.position(next) - home_m).squaredNorm(), next);
      }
    }
    if (!met) return false;
    for (const std::uint32_t node : walked) joined[node] = 1;
  }
  return true;
}

std::vector<LatticeRoadmap::Place> LatticeRoadmap::joinPlaces(const std::vector<Eigen::Vector3d>& places_m) const {
  const detail::LatticeGrid& lattice = lattice_->grid;
  const FlightCostModel& model = objective_->model();
  const auto cost = [&](const MotionTotals& totals) { return objective_->weights().of(totals); };
  std::vector<Place> places(places_m.size());
  parallelFor(places_m.size(), settings_.workers, [&](std::size_t index) {
    const Eigen::Vector3d& centre = places_m[index];
    lattice.forEachNodeNear(centre, [&](std::size_t id) {
      const Eigen::Vector3d p = lattice.position(id);
      if (!nodeValid(static_cast<std::uint32_t>(id)) || !rules_->isMotionValid(centre, p)) return;
      const auto totals = model.integrateBothWays(centre, p);
      places[index].out.push_back({static_cast<std::uint32_t>(id), cost(totals.first)});
      places[index].in.push_back({static_cast<std::uint32_t>(id), cost(totals.second)});
    });
  });
  return places;
}

std::uint32_t LatticeRoadmap::addVertex(const Eigen::Vector3d& position_m) {
  bridge_positions_m_.push_back(position_m);
  bridge_arcs_.emplace_back();
  return static_cast<std::uint32_t>(node_count_ + bridge_positions_m_.size() - 1);
}

Eigen::Vector3d LatticeRoadmap::statePosition(std::uint32_t state) const {
  if (state < node_count_) return lattice_->grid.position(state);
  return bridge_positions_m_[state - node_count_];
}

void LatticeRoadmap::addBridge(const std::vector<Eigen::Vector3d>& waypoints, std::optional<std::uint32_t> from_state,
                               std::optional<std::uint32_t> to_state, Place* from_place, Place* to_place) {
  const auto addArc = [&](std::uint32_t from, std::uint32_t to, double cost) {
    const Arc arc{to, static_cast<float>(cost)};
    if (from < node_count_)
      node_arcs_.emplace_back(from, arc);
    else
      bridge_arcs_[from - node_count_].push_back(arc);
  };
  // A place at an end gets a vertex on it, joined at no cost. A search ends at a place, so the
  // vertex also takes the place's joins: routes between other places pass through it.
  const auto endState = [&](std::optional<std::uint32_t> state, Place* place, const Eigen::Vector3d& position_m) {
    if (state) return *state;
    const std::uint32_t vertex = addVertex(position_m);
    for (const Join& join : place->out) addArc(vertex, join.state, join.cost);
    for (const Join& join : place->in) addArc(join.state, vertex, join.cost);
    place->out.push_back({vertex, 0.0});
    place->in.push_back({vertex, 0.0});
    return vertex;
  };
  std::vector<std::uint32_t> states{endState(from_state, from_place, waypoints.front())};
  for (std::size_t k = 1; k + 1 < waypoints.size(); ++k) states.push_back(addVertex(waypoints[k]));
  states.push_back(endState(to_state, to_place, waypoints.back()));
  const FlightCostModel& model = objective_->model();
  for (std::size_t k = 0; k + 1 < states.size(); ++k) {
    const auto [forth, back] = model.integrateBothWays(waypoints[k], waypoints[k + 1]);
    addArc(states[k], states[k + 1], objective_->weights().of(forth));
    addArc(states[k + 1], states[k], objective_->weights().of(back));
  }
  std::stable_sort(node_arcs_.begin(), node_arcs_.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
}

std::vector<std::optional<Blockage>> LatticeRoadmap::connect(const std::vector<Eigen::Vector3d>& places_m,
                                                             std::vector<Place>& places,
                                                             const ompl::base::PlannerTerminationCondition& ptc) {
  const std::size_t place_count = places_m.size();
  std::vector<std::optional<Blockage>> blockages(place_count);
  // Usually one part of the lattice holds every place: nothing to refine, and no need to check
  // the rest of the map. Otherwise the partition below needs every node and edge.
  if (node_arcs_.empty() && bridge_positions_m_.empty() && placesJoined(places)) return blockages;
  if (!checkEverything([&ptc] { return ptc(); })) return blockages;
  const detail::LatticeGrid& lattice = lattice_->grid;
  const detail::LatticeDirections& directions = lattice_->directions;
  // Parts of the roadmap: lattice nodes, refinement's vertices, then the places.
  std::vector<std::uint32_t> parent;
  const auto root = [&parent](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  const auto unite = [&](std::uint32_t a, std::uint32_t b) { parent[root(a)] = root(b); };
  const auto placeElement = [&](std::size_t p) {
    return static_cast<std::uint32_t>(node_count_ + bridge_positions_m_.size() + p);
  };
  const auto partition = [&] {
    parent.resize(node_count_ + bridge_positions_m_.size() + place_count);
    for (std::uint32_t x = 0; x < parent.size(); ++x) parent[x] = x;
    for (const std::uint32_t node : valid_nodes_) {
      const std::array<int, 3> at = lattice.indices(node);
      for (int d = kFirstForwardDirection; d < kDirections; ++d)
        if (edgeCost(node, d) != kNoEdge) {
          const std::array<int, 3> to = neighbour(at, directions.offsets[d]);
          unite(node, static_cast<std::uint32_t>(lattice.id(to[0], to[1], to[2])));
        }
    }
    for (const auto& [node, arc] : node_arcs_) unite(node, arc.to);
    for (std::size_t v = 0; v < bridge_arcs_.size(); ++v)
      for (const Arc& arc : bridge_arcs_[v]) unite(static_cast<std::uint32_t>(node_count_ + v), arc.to);
    // A search ends at a place, never passes through it: a place joined to two parts (in a
    // doorway, say) must not make them one, or the parts would stay apart for the search with
    // no refinement between them. It counts with the part of its first join; the others are
    // then refined towards it.
    for (std::size_t p = 0; p < place_count; ++p)
      if (!places[p].out.empty()) unite(placeElement(p), places[p].out.front().state);
  };
  // Lattice nodes missing an edge: where a part of the roadmap ends.
  std::vector<std::uint32_t> rim;
  for (const std::uint32_t node : valid_nodes_) {
    int edges = 0;
    for (int d = 0; d < kDirections; ++d) edges += edgeCost(node, d) != kNoEdge;
    if (edges < kDirections) rim.push_back(node);
  }

  std::vector<char> apart(place_count, 0);  // left apart after a failed refinement
  for (;;) {
    partition();
    const std::uint32_t main = root(placeElement(0));
    std::size_t lone = place_count;
    for (std::size_t p = 0; p < place_count && lone == place_count; ++p)
      if (!apart[p] && root(placeElement(p)) != main) lone = p;
    if (lone == place_count || ptc()) break;
    // One side: the part `lone` reaches; the other: every other part holding a place.
    const std::uint32_t part = root(placeElement(lone));
    std::vector<char> other_part(parent.size(), 0);
    for (std::size_t p = 0; p < place_count; ++p)
      if (!apart[p] && root(placeElement(p)) != part) other_part[root(placeElement(p))] = 1;
    std::vector<Eigen::Vector3d> side_a, side_b;
    std::vector<std::pair<bool, std::uint32_t>> what_a, what_b;  // (place?, index or node)
    for (std::size_t p = 0; p < place_count; ++p) {
      const std::uint32_t r = root(placeElement(p));
      if (r == part)
        side_a.push_back(places_m[p]), what_a.emplace_back(true, p);
      else if (other_part[r])
        side_b.push_back(places_m[p]), what_b.emplace_back(true, p);
    }
    for (const std::uint32_t node : rim) {
      const std::uint32_t r = root(node);
      if (r == part)
        side_a.push_back(lattice.position(node)), what_a.emplace_back(false, node);
      else if (other_part[r])
        side_b.push_back(lattice.position(node)), what_b.emplace_back(false, node);
    }
    const detail::BridgeOutcome found = detail::findBridge(*rules_, side_a, side_b, ptc);
    if (found.waypoints.empty()) {
      for (std::size_t p = 0; p < place_count; ++p)
        if (root(placeElement(p)) == part) {
          apart[p] = 1;
          blockages[p] = found.blockage;
        }
      continue;
    }
    const auto [a_is_place, a] = what_a[found.from];
    const auto [b_is_place, b] = what_b[found.to];
    addBridge(found.waypoints, a_is_place ? std::nullopt : std::optional<std::uint32_t>(a),
              b_is_place ? std::nullopt : std::optional<std::uint32_t>(b), a_is_place ? &places[a] : nullptr,
              b_is_place ? &places[b] : nullptr);
  }
  return blockages;
}

std::optional<Blockage> LatticeRoadmap::blockage(int from, int to) const {
  const int places = static_cast<int>(places_m_.size());
  if (from < 0 || from >= places || to < 0 || to >= places)
    throw ceilplan::InputError("roadmap place index out of range");
  if (from == to) return std::nullopt;
  // Joined places have no blockage; of two apart, one has (the one apart from the first place).
  if (!place_blockages_[from] && !place_blockages_[to]) return std::nullopt;
  if (search(places_m_, places_, from)[to]) return std::nullopt;
  return place_blockages_[from] ? place_blockages_[from] : place_blockages_[to];
}

std::size_t LatticeRoadmap::validNodeCount() const { return validity_ ? validity_->cells_->validCount() : 0; }

std::size_t LatticeRoadmap::edgeCount() const {
  std::size_t edges = 0;
  if (lattice_) lattice_->forEachCost([&edges](float cost) { edges += cost != kNoEdge; });
  return edges;
}

std::size_t LatticeRoadmap::memoryBytes() const {
  std::size_t bytes = (lattice_ ? lattice_->memoryBytes() : 0) + (validity_ ? validity_->cells_->memoryBytes() : 0) +
                      valid_nodes_.size() * sizeof(std::uint32_t);
  for (const Place& place : places_) bytes += (place.out.size() + place.in.size()) * sizeof(Join);
  bytes += bridge_positions_m_.size() * sizeof(Eigen::Vector3d) + node_arcs_.size() * sizeof(node_arcs_[0]);
  for (const std::vector<Arc>& arcs : bridge_arcs_) bytes += arcs.size() * sizeof(Arc);
  return bytes;
}

std::vector<std::optional<RoadmapRoute>> LatticeRoadmap::routesFrom(int from) const {
  if (!built()) throw ceilplan::Error("the roadmap is not built: call build() first");
  if (from < 0 || from >= static_cast<int>(places_m_.size()))
    throw ceilplan::InputError("roadmap place index out of range");
  return search(places_m_, places_, from);
}

std::vector<std::optional<RoadmapRoute>> LatticeRoadmap::routesFrom(int from, const std::vector<int>& goals) const {
  if (!built()) throw ceilplan::Error("the roadmap is not built: call build() first");
  const int places = static_cast<int>(places_m_.size());
  if (from < 0 || from >= places) throw ceilplan::InputError("roadmap place index out of range");
  std::vector<int> targets;
  for (int goal : goals) {
    if (goal < 0 || goal >= places) throw ceilplan::InputError("roadmap place index out of range");
    if (goal != from) targets.push_back(goal);
  }
  std::sort(targets.begin(), targets.end());
  targets.erase(std::unique(targets.begin(), targets.end()), targets.end());
  if (targets.empty()) return std::vector<std::optional<RoadmapRoute>>(places);
  return search(places_m_, places_, from, targets);
}

std::vector<std::optional<RoadmapRoute>> LatticeRoadmap::search(const std::vector<Eigen::Vector3d>& places_m,
                                                                const std::vector<Place>& place_data, int from,
                                                                const std::vector<int>& goals) const {
  const int places = static_cast<int>(places_m.size());
  std::vector<int> targets = goals;
  if (targets.empty())
    for (int goal = 0; goal < places; ++goal)
      if (goal != from) targets.push_back(goal);
  const detail::LatticeGrid& lattice = lattice_->grid;
  const detail::LatticeDirections& directions = lattice_->directions;

  // States: lattice nodes, refinement's vertices, then the places themselves.
  const std::size_t place_offset = node_count_ + bridge_positions_m_.size();
  const std::size_t state_count = place_offset + places;
  constexpr std::uint32_t kStart = std::numeric_limits<std::uint32_t>::max();
  // The search's state, kept per thread between searches and reset where it was touched: a
  // tour of many places runs thousands of short searches over a large lattice.
  struct Buffers {
    std::vector<double> cost_to;
    std::vector<std::uint32_t> parent;
    std::vector<char> closed;
    std::vector<char> joins;  // whether a join into a goal leaves from the state
    std::vector<std::uint32_t> touched;
  };
  thread_local Buffers buffers;
  if (buffers.cost_to.size() < state_count) {
    buffers.cost_to.resize(state_count, std::numeric_limits<double>::infinity());
    buffers.parent.resize(state_count, kStart);
    buffers.closed.resize(state_count, 0);
    buffers.joins.resize(state_count, 0);
  }
  struct Reset {
    Buffers& b;
    ~Reset() {
      for (std::uint32_t state : b.touched) {
        b.cost_to[state] = std::numeric_limits<double>::infinity();
        b.parent[state] = kStart;
        b.closed[state] = 0;
      }
      b.touched.clear();
    }
  } reset{buffers};
  std::vector<double>& cost_to = buffers.cost_to;
  std::vector<std::uint32_t>& parent = buffers.parent;
  std::vector<char>& closed = buffers.closed;
  // A few goals named: A* towards the nearest of them (c_min x distance is admissible and
  // consistent), so a search between near places stays near them. Every place: Dijkstra.
  const bool guided = !goals.empty() && targets.size() <= 8;
  const auto heuristic = [&](std::size_t state) {
    if (!guided || state >= place_offset) return 0.0;
    const Eigen::Vector3d at = statePosition(static_cast<std::uint32_t>(state));
    double h = std::numeric_limits<double>::infinity();
    for (int goal : targets) h = std::min(h, objective_->heuristic(at, places_m[goal]));
    return h;
  };
  // Lazy in the lattice's edges, as LazyPRM is in its roadmap's: an edge not costed yet waits in
  // the queue at its lower bound (edge_bounds_: climbing costs more than descending) and is
  // costed only if it comes off the queue still able to improve its end. Around a search's
  // front, most edges lead where a cheaper way already reached.
  struct Entry {
    double key;
    std::uint32_t state;
    int direction;  // >= 0: the uncosted lattice edge out of `state` (a closed node) this way
    bool operator>(const Entry& other) const {
      if (key != other.key) return key > other.key;
      if (state != other.state) return state > other.state;
      return direction > other.direction;
    }
  };
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  // Closed states leave the queue in (key, state) order; of the states that reach another at
  // the same least cost, its parent is the first of them in that order, whichever order the
  // lazy edges are costed in: the routes are those of the search that costs every edge. A
  // closed state keeps its parent (a zero-cost join back to it must not make a cycle).
  const auto closesBefore = [&](std::uint32_t a, std::uint32_t b) {
    if (b == kStart) return false;
    if (a == kStart) return true;
    const double key_a = cost_to[a] + heuristic(a), key_b = cost_to[b] + heuristic(b);
    return key_a != key_b ? key_a < key_b : a < b;
  };
  const auto relax = [&](std::size_t state, std::uint32_t from_state, double g) {
    if (g < cost_to[state]) {
      if (cost_to[state] == std::numeric_limits<double>::infinity())
        buffers.touched.push_back(static_cast<std::uint32_t>(state));
      cost_to[state] = g;
      parent[state] = from_state;
      open.push({g + heuristic(state), static_cast<std::uint32_t>(state), -1});
    } else if (g == cost_to[state] && !closed[state] && closesBefore(from_state, parent[state])) {
      parent[state] = from_state;
    }
  };
  // The joins into the goals by the state they leave from, in the order of the goals and of each
  // goal's joins: a closed state looks up its own joins instead of asking every goal (a search
  // from home to every photo of a long structure closes the whole lattice, for thousands of goals).
  // A lattice node's joins are those within the join radius (joinPlaces), a vertex's those of its
  // place (addBridge).
  struct GoalJoin {
    std::uint32_t state;
    int goal;
    double cost;
  };
  std::vector<GoalJoin> goal_joins;
  for (int goal : targets)
    for (const Join& join : place_data[goal].in) goal_joins.push_back({join.state, goal, join.cost});
  std::stable_sort(goal_joins.begin(), goal_joins.end(),
                   [](const GoalJoin& a, const GoalJoin& b) { return a.state < b.state; });
  // Marked for the search's states, so that the many states without joins skip the lookup.
  struct Marks {
    std::vector<char>& joins;
    const std::vector<GoalJoin>& goal_joins;
    ~Marks() {
      for (const GoalJoin& join : goal_joins) joins[join.state] = 0;
    }
  } marks{buffers.joins, goal_joins};
  for (const GoalJoin& join : goal_joins) marks.joins[join.state] = 1;
  const auto joinsFrom = [&](std::uint32_t state) {
    if (!marks.joins[state]) return std::make_pair(goal_joins.end(), goal_joins.end());
    const auto first = std::lower_bound(goal_joins.begin(), goal_joins.end(), state,
                                        [](const GoalJoin& join, std::uint32_t s) { return join.state < s; });
    auto last = first;
    while (last != goal_joins.end() && last->state == state) ++last;
    return std::make_pair(first, last);
  };
  const auto arrive = [&](std::uint32_t state, double g) {
    const auto [first, last] = joinsFrom(state);
    for (auto join = first; join != last; ++join) relax(place_offset + join->goal, state, g + join->cost);
  };

  // Each direction's step in node ids.
  std::array<std::int64_t, kDirections> id_steps{};
  for (int d = 0; d < kDirections; ++d) {
    const std::array<int, 3>& offset = directions.offsets[d];
    id_steps[d] = (static_cast<std::int64_t>(offset[2]) * lattice.size(1) + offset[1]) * lattice.size(0) + offset[0];
  }

  for (const Join& join : place_data[from].out) relax(join.state, kStart, join.cost);
  int goals_left = static_cast<int>(targets.size());
  while (!open.empty() && goals_left > 0) {
    const Entry entry = open.top();
    open.pop();
    if (entry.direction >= 0) {
      const std::uint32_t node = entry.state;
      // Such an entry is pushed only for a neighbour inside the lattice.
      const std::uint32_t next = static_cast<std::uint32_t>(node + id_steps[entry.direction]);
      const double g = cost_to[node];
      if (closed[next] || g + edge_bounds_[entry.direction] >= cost_to[next]) continue;
      const float c = edgeCost(node, entry.direction);
      if (c != kNoEdge) relax(next, node, g + c);
      continue;
    }
    const std::uint32_t state = entry.state;
    if (closed[state]) continue;
    closed[state] = 1;
    const double g = cost_to[state];
    if (state >= place_offset) {
      --goals_left;
      continue;
    }
    if (state >= node_count_) {  // a vertex refinement added
      for (const Arc& arc : bridge_arcs_[state - node_count_]) relax(arc.to, state, g + arc.cost);
      arrive(state, g);
      continue;
    }
    const std::uint32_t node = state;  // valid: reached by an edge or a join
    // The node's indices once for its 26 neighbours (each a division), which lie inside the
    // lattice unless the node is on its boundary.
    const std::array<int, 3> at = lattice.indices(node);
    const bool interior = at[0] > 0 && at[1] > 0 && at[2] > 0 && at[0] + 1 < lattice.size(0) &&
                          at[1] + 1 < lattice.size(1) && at[2] + 1 < lattice.size(2);
    const std::atomic<float>* const costs = lattice_->costsOf(node);
    for (int d = 0; d < kDirections; ++d) {
      const std::array<int, 3>& offset = directions.offsets[d];
      if (!interior && !lattice.inside(at[0] + offset[0], at[1] + offset[1], at[2] + offset[2])) continue;
      const std::uint32_t next = static_cast<std::uint32_t>(node + id_steps[d]);
      if (closed[next]) continue;
      const float c = costs[d].load(std::memory_order_relaxed);
      if (c == kUncosted) {
        // Below the key its end gets through this edge, and no lower than this node's own.
        if (g + edge_bounds_[d] < cost_to[next]) open.push({g + edge_bounds_[d] + heuristic(next), node, d});
      } else if (c != kNoEdge) {
        relax(next, node, g + c);
      }
    }
    if (!node_arcs_.empty()) {
      const auto first = std::lower_bound(node_arcs_.begin(), node_arcs_.end(), node,
                                          [](const auto& arc, std::uint32_t n) { return arc.first < n; });
      for (auto it = first; it != node_arcs_.end() && it->first == node; ++it)
        relax(it->second.to, state, g + it->second.cost);
    }
    arrive(node, g);
  }

  std::vector<std::optional<RoadmapRoute>> routes(places);
  for (int goal : targets) {
    const std::size_t state = place_offset + goal;
    if (!std::isfinite(cost_to[state])) continue;
    std::vector<Eigen::Vector3d> backwards{places_m[goal]};
    for (std::uint32_t s = parent[state]; s != kStart; s = parent[s]) backwards.push_back(statePosition(s));
    backwards.push_back(places_m[from]);
    RoadmapRoute route;
    route.waypoints = detail::turningPoints({backwards.rbegin(), backwards.rend()});
    route.cost = cost_to[state];
    routes[goal] = std::move(route);
  }
  return routes;
}

ompl::base::PlannerStatus LatticeRoadmap::solve(const ompl::base::PlannerTerminationCondition& ptc) {
  checkValidity();
  const FlightObjective& objective = detail::objectiveOf(*pdef_, getName());
  ompl::base::PlannerStatus failure;
  const std::optional<detail::LatticeQuery> query = detail::readQuery(*pdef_, failure);
  if (!query) return failure;
  if (objective_ != &objective) {
    startGraph(objective, nullptr);
    places_ = joinPlaces(places_m_);
  }
  blockage_.reset();
  const std::vector<Eigen::Vector3d> ends{query->start_m, query->goal_m};
  std::vector<Place> ends_data = joinPlaces(ends);
  std::vector<std::optional<RoadmapRoute>> routes = search(ends, ends_data, 0);
  if (!routes[1]) {
    blockage_ = connect(ends, ends_data, ptc)[1];
    routes = search(ends, ends_data, 0);
  }
  // As the lattice A* does, the straight motion when it is valid and cheaper.
  if (rules_->isMotionValid(query->start_m, query->goal_m)) {
    const double direct = objective.motionCost(query->start_m, query->goal_m);
    if (!routes[1] || direct < routes[1]->cost) routes[1] = RoadmapRoute{{query->start_m, query->goal_m}, direct};
  }
  if (!routes[1]) return ptc() ? ompl::base::PlannerStatus::TIMEOUT : ompl::base::PlannerStatus::ABORT;
  blockage_.reset();
  best_cost_ = routes[1]->cost;
  detail::addSolution(*this, routes[1]->waypoints, routes[1]->cost);
  return ompl::base::PlannerStatus::EXACT_SOLUTION;
}

void LatticeRoadmap::getPlannerData(ompl::base::PlannerData& data) const {
  ompl::base::Planner::getPlannerData(data);
  data.properties["valid nodes INTEGER"] = std::to_string(validNodeCount());
  data.properties["edges INTEGER"] = std::to_string(edgeCount());
}

}  // namespace ceilplan::planner
