#include "ceilplan/planner/lattice_roadmap.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/parallel_for.hpp"

#include "lattice_bridge.hpp"
#include "lattice_grid.hpp"
#include "lattice_query.hpp"

#include <ompl/base/PlannerData.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace ceilplan::planner {
namespace {

constexpr std::uint32_t kNoSlot = std::numeric_limits<std::uint32_t>::max();
constexpr float kNoEdge = std::numeric_limits<float>::infinity();
constexpr int kDirections = 26;
// Directions 13..25 point "forwards" (lexicographically after the node): each undirected edge
// is visited once, from its first node, and costed both ways.
constexpr int kFirstForwardDirection = 13;

std::array<int, 3> neighbour(const std::array<int, 3>& at, const std::array<int, 3>& offset) {
  return {at[0] + offset[0], at[1] + offset[1], at[2] + offset[2]};
}

}  // namespace

std::optional<std::uint32_t> LatticeRoadmap::Zone::slotOf(std::uint32_t node) const {
  const auto found = std::lower_bound(nodes.begin(), nodes.end(), node);
  if (found == nodes.end() || *found != node) return std::nullopt;
  return static_cast<std::uint32_t>(found - nodes.begin());
}

LatticeRoadmap::LatticeRoadmap(const ompl::base::SpaceInformationPtr& si, LatticeSettings settings)
    : ompl::base::Planner(si, "roadmap"),
      settings_(std::move(settings)),
      best_cost_(std::numeric_limits<double>::infinity()) {
  settings_.validate();
  specs_.optimizingPaths = true;
  specs_.directed = true;
  specs_.multithreaded = true;
  declareParam<double>("spacing_m", this, &LatticeRoadmap::setSpacing, &LatticeRoadmap::getSpacing, "0.01:0.01:2.0");
  addPlannerProgressProperty("best cost REAL", [this] { return std::to_string(best_cost_.load()); });
}

void LatticeRoadmap::setSpacing(double spacing_m) {
  LatticeSettings settings = settings_;
  settings.spacing_m = spacing_m;
  settings.validate();
  settings_ = settings;
  clear();
}

void LatticeRoadmap::clearQuery() {
  pis_.restart();  // not Planner::clearQuery(), which clears everything
  best_cost_ = std::numeric_limits<double>::infinity();
}

void LatticeRoadmap::clear() {
  ompl::base::Planner::clear();
  dropGraph();
  places_m_.clear();
  places_.clear();
  best_cost_ = std::numeric_limits<double>::infinity();
}

void LatticeRoadmap::dropGraph() {
  objective_ = nullptr;
  node_count_ = 0;
  slot_.clear();
  valid_nodes_.clear();
  core_costs_.clear();
}

void LatticeRoadmap::build(const FlightObjective& objective, std::vector<Eigen::Vector3d> places_m) {
  rules_ = &detail::rulesOf(*si_, getName());
  for (const Eigen::Vector3d& place : places_m)
    if (!place.allFinite() || !rules_->environment().contains(place))
      throw ceilplan::InputError("a roadmap place lies outside the map");
  buildGraph(objective, {});
  places_m_ = std::move(places_m);
  places_ = joinPlaces(places_m_);
  if (settings_.progress) settings_.progress(1.0);
}

bool LatticeRoadmap::buildGraph(const FlightObjective& objective, const std::function<bool()>& abandon) {
  dropGraph();
  rules_ = &detail::rulesOf(*si_, getName());
  core_rules_.emplace(rules_->withExemptions({}));
  const detail::LatticeGrid lattice(rules_->environment().grid().frame(), settings_.spacing_m);
  node_count_ = lattice.nodeCount();
  if (node_count_ >= kNoSlot)
    throw ceilplan::InputError("the map has too many lattice nodes for a " + std::to_string(lattice.spacing_m()) +
                               " m spacing: raise the spacing");
  // Shares of the build time, roughly as on the shipped bridge: nodes 10 %, edges 80 %, places 10 %.
  std::atomic<bool> stop{false};
  const auto report = [&](double share) {
    if (settings_.progress) settings_.progress(share);
    if (abandon && abandon()) stop = true;
  };

  std::vector<char> valid(node_count_, 0);
  parallelFor(
      node_count_, settings_.workers,
      [&](std::size_t id) {
        if (!stop) valid[id] = core_rules_->isStateValid(lattice.position(id));
      },
      [&](double share) { report(0.1 * share); });
  report(0.1);
  if (stop) {
    dropGraph();
    return false;
  }
  slot_.assign(node_count_, kNoSlot);
  for (std::size_t id = 0; id < node_count_; ++id)
    if (valid[id]) {
      slot_[id] = static_cast<std::uint32_t>(valid_nodes_.size());
      valid_nodes_.push_back(static_cast<std::uint32_t>(id));
    }

  const detail::LatticeDirections directions;
  const FlightCostModel& model = objective.model();
  core_costs_.assign(valid_nodes_.size() * kDirections, kNoEdge);
  // Each (node, direction) cell is written by the one task that owns its edge's first node.
  parallelFor(
      valid_nodes_.size(), settings_.workers,
      [&](std::size_t row) {
        if (stop) return;
        const std::uint32_t id = valid_nodes_[row];
        const std::array<int, 3> at = lattice.indices(id);
        const Eigen::Vector3d here = lattice.position(id);
        for (int d = kFirstForwardDirection; d < kDirections; ++d) {
          const std::array<int, 3> to = neighbour(at, directions.offsets[d]);
          if (!lattice.inside(to[0], to[1], to[2])) continue;
          const std::uint32_t other = slot_[lattice.id(to[0], to[1], to[2])];
          if (other == kNoSlot) continue;
          const Eigen::Vector3d there = lattice.position(to[0], to[1], to[2]);
          if (!core_rules_->isMotionValid(here, there)) continue;
          const auto [forth, back] = model.integrateBothWays(
              here, there, [&model](const Eigen::Vector3d& p) { return model.conditionsAt(p); });
          core_costs_[row * kDirections + d] = static_cast<float>(objective.weights().of(forth));
          core_costs_[static_cast<std::size_t>(other) * kDirections + directions.opposite[d]] =
              static_cast<float>(objective.weights().of(back));
        }
      },
      [&](double share) { report(0.1 + 0.8 * share); });
  if (stop) {
    dropGraph();
    return false;
  }
  objective_ = &objective;
  report(0.9);
  return true;
}

float LatticeRoadmap::coreCost(std::uint32_t node, int direction) const {
  const std::uint32_t row = slot_[node];
  return row == kNoSlot ? kNoEdge : core_costs_[static_cast<std::size_t>(row) * kDirections + direction];
}

std::vector<LatticeRoadmap::Place> LatticeRoadmap::joinPlaces(const std::vector<Eigen::Vector3d>& places_m) const {
  const detail::LatticeGrid lattice(rules_->environment().grid().frame(), settings_.spacing_m);
  const detail::LatticeDirections directions;
  const bool zoned = rules_->hasStandoff();
  const double zone_radius_m = rules_->exemptRadius_m();
  const FlightCostModel& model = objective_->model();
  const auto conditions = [&model](const Eigen::Vector3d& p) { return model.conditionsAt(p); };
  const auto cost = [&](const MotionTotals& totals) { return objective_->weights().of(totals); };

  std::vector<Place> places(places_m.size());
  parallelFor(places_m.size(), settings_.workers, [&](std::size_t index) {
    const Eigen::Vector3d& centre = places_m[index];
    Place& place = places[index];
    // What a route starting or ending here may do (free mode: come close to the structure).
    const SafetyRules near = rules_->withExemptions({centre});
    if (zoned) {
      Zone& zone = place.zone;
      lattice.forEachNodeWithin(centre, zone_radius_m, [&](std::size_t id) {
        if (near.isStateValid(lattice.position(id))) zone.nodes.push_back(static_cast<std::uint32_t>(id));
      });
      zone.costs.assign(zone.nodes.size() * kDirections, kNoEdge);
      for (std::size_t slot = 0; slot < zone.nodes.size(); ++slot) {
        const std::uint32_t id = zone.nodes[slot];
        const std::array<int, 3> at = lattice.indices(id);
        for (int d = kFirstForwardDirection; d < kDirections; ++d) {
          const std::array<int, 3> to = neighbour(at, directions.offsets[d]);
          if (!lattice.inside(to[0], to[1], to[2])) continue;
          const std::uint32_t next = static_cast<std::uint32_t>(lattice.id(to[0], to[1], to[2]));
          const std::optional<std::uint32_t> other = zone.slotOf(next);
          if (!other) continue;
          float forth = coreCost(id, d), back = coreCost(next, directions.opposite[d]);
          if (forth == kNoEdge) {  // invalid with the standoff: perhaps valid without it
            const Eigen::Vector3d here = lattice.position(id), there = lattice.position(next);
            if (!near.isMotionValid(here, there)) continue;
            const auto totals = model.integrateBothWays(here, there, conditions);
            forth = static_cast<float>(cost(totals.first));
            back = static_cast<float>(cost(totals.second));
          }
          zone.costs[slot * kDirections + d] = forth;
          zone.costs[*other * kDirections + directions.opposite[d]] = back;
        }
      }
    }
    // Joins: to lattice nodes valid near the place (in its zone, with a standoff).
    lattice.forEachNodeNear(centre, [&](std::size_t id) {
      const auto node = static_cast<std::uint32_t>(id);
      const bool valid = zoned ? place.zone.slotOf(node).has_value() : slot_[id] != kNoSlot;
      const Eigen::Vector3d p = lattice.position(id);
      if (!valid || !near.isMotionValid(centre, p)) return;
      const auto totals = model.integrateBothWays(centre, p, conditions);
      place.out.push_back({node, cost(totals.first)});
      place.in.push_back({node, cost(totals.second)});
    });
  });
  return places;
}

std::size_t LatticeRoadmap::edgeCount() const {
  return static_cast<std::size_t>(
      std::count_if(core_costs_.begin(), core_costs_.end(), [](float c) { return c != kNoEdge; }));
}

std::size_t LatticeRoadmap::memoryBytes() const {
  std::size_t bytes = slot_.size() * sizeof(std::uint32_t) + valid_nodes_.size() * sizeof(std::uint32_t) +
                      core_costs_.size() * sizeof(float);
  for (const Place& place : places_)
    bytes += place.zone.nodes.size() * sizeof(std::uint32_t) + place.zone.costs.size() * sizeof(float) +
             (place.out.size() + place.in.size()) * sizeof(Join);
  return bytes;
}

std::vector<std::optional<RoadmapRoute>> LatticeRoadmap::routesFrom(int from) const {
  if (!built()) throw ceilplan::Error("the roadmap is not built: call build() first");
  if (from < 0 || from >= static_cast<int>(places_m_.size()))
    throw ceilplan::InputError("roadmap place index out of range");
  return search(places_m_, places_, from);
}

std::vector<std::optional<RoadmapRoute>> LatticeRoadmap::search(const std::vector<Eigen::Vector3d>& places_m,
                                                                const std::vector<Place>& place_data,
                                                                int from) const {
  const int places = static_cast<int>(places_m.size());
  const detail::LatticeGrid lattice(rules_->environment().grid().frame(), settings_.spacing_m);
  const detail::LatticeDirections directions;
  const bool zoned = rules_->hasStandoff();
  const double zone_radius_m = rules_->exemptRadius_m();

  // States: lattice nodes (on the way), then each goal's zone nodes (its final approach), then
  // the places themselves.
  const std::size_t lattice_states = node_count_;
  std::vector<std::size_t> zone_offset(places, lattice_states);
  std::size_t next_offset = lattice_states;
  for (int p = 0; p < places && zoned; ++p) {
    zone_offset[p] = next_offset;
    next_offset += place_data[p].zone.nodes.size();
  }
  const std::size_t place_offset = next_offset;
  const std::size_t state_count = place_offset + places;
  constexpr std::uint32_t kStart = std::numeric_limits<std::uint32_t>::max();
  std::vector<double> cost_to(state_count, std::numeric_limits<double>::infinity());
  std::vector<std::uint32_t> parent(state_count, kStart);
  std::vector<char> closed(state_count, 0);
  using Entry = std::pair<double, std::uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  const auto relax = [&](std::size_t state, std::uint32_t from_state, double g) {
    if (g < cost_to[state]) {
      cost_to[state] = g;
      parent[state] = from_state;
      open.emplace(g, static_cast<std::uint32_t>(state));
    }
  };
  const auto zoneOf = [&](std::size_t state) {
    return static_cast<int>(std::upper_bound(zone_offset.begin(), zone_offset.end(), state) - zone_offset.begin()) - 1;
  };
  const auto nodeOf = [&](std::size_t state) -> std::uint32_t {
    if (state < lattice_states) return static_cast<std::uint32_t>(state);
    const int p = zoneOf(state);
    return place_data[p].zone.nodes[state - zone_offset[p]];
  };
  const auto arrive = [&](int goal, std::uint32_t node, std::size_t state, double g) {
    if (goal == from || (places_m[goal] - lattice.position(node)).norm() > lattice.joinRadius_m()) return;
    for (const Join& join : place_data[goal].in)
      if (join.node == node) relax(place_offset + goal, static_cast<std::uint32_t>(state), g + join.cost);
  };

  for (const Join& join : place_data[from].out) relax(join.node, kStart, join.cost);
  int goals_left = places - 1;
  while (!open.empty() && goals_left > 0) {
    const auto [g, state] = open.top();
    open.pop();
    if (closed[state]) continue;
    closed[state] = 1;
    if (state >= place_offset) {
      --goals_left;
      continue;
    }
    const std::uint32_t node = nodeOf(state);
    const std::array<int, 3> at = lattice.indices(node);
    const Eigen::Vector3d here = lattice.position(node);
    if (state < lattice_states) {
      // On the way: edges valid everywhere, and those of the start's own approach zone.
      const Zone& start_zone = place_data[from].zone;
      const std::optional<std::uint32_t> start_slot = zoned ? start_zone.slotOf(node) : std::nullopt;
      for (int d = 0; d < kDirections; ++d) {
        const std::array<int, 3> to = neighbour(at, directions.offsets[d]);
        if (!lattice.inside(to[0], to[1], to[2])) continue;
        float c = coreCost(node, d);
        if (c == kNoEdge && start_slot) c = start_zone.costs[*start_slot * kDirections + d];
        if (c != kNoEdge) relax(lattice.id(to[0], to[1], to[2]), state, g + c);
      }
      for (int goal = 0; goal < places; ++goal) {
        if (!zoned) {
          arrive(goal, node, state, g);
        } else if (goal != from && (places_m[goal] - here).norm() <= zone_radius_m) {
          if (const auto slot = place_data[goal].zone.slotOf(node)) relax(zone_offset[goal] + *slot, state, g);
        }
      }
    } else {
      // The final approach to one goal, inside its zone.
      const int goal = zoneOf(state);
      const Zone& zone = place_data[goal].zone;
      const std::size_t slot = state - zone_offset[goal];
      for (int d = 0; d < kDirections; ++d) {
        const float c = zone.costs[slot * kDirections + d];
        if (c == kNoEdge) continue;
        const std::array<int, 3> to = neighbour(at, directions.offsets[d]);
        relax(zone_offset[goal] + *zone.slotOf(static_cast<std::uint32_t>(lattice.id(to[0], to[1], to[2]))), state,
              g + c);
      }
      arrive(goal, node, state, g);
    }
  }

  std::vector<std::optional<RoadmapRoute>> routes(places);
  for (int goal = 0; goal < places; ++goal) {
    const std::size_t state = place_offset + goal;
    if (goal == from || !std::isfinite(cost_to[state])) continue;
    std::vector<Eigen::Vector3d> backwards{places_m[goal]};
    for (std::uint32_t s = parent[state]; s != kStart; s = parent[s]) backwards.push_back(lattice.position(nodeOf(s)));
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
    if (!buildGraph(objective, [&ptc] { return ptc(); })) return ompl::base::PlannerStatus::TIMEOUT;
    places_ = joinPlaces(places_m_);
  }
  const std::vector<Eigen::Vector3d> ends{query->start_m, query->goal_m};
  const std::vector<std::optional<RoadmapRoute>> routes = search(ends, joinPlaces(ends), 0);
  if (!routes[1]) return ompl::base::PlannerStatus::ABORT;
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
