#include "ceilplan/planner/lattice_roadmap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>

#include "ceilplan/core/parallel_for.hpp"
#include "ceilplan/core/error.hpp"
#include "lattice_grid.hpp"

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

// Drops repeated points and the inner points of straight runs.
std::vector<Eigen::Vector3d> turningPoints(const std::vector<Eigen::Vector3d>& points) {
  std::vector<Eigen::Vector3d> result;
  for (const Eigen::Vector3d& p : points) {
    if (!result.empty() && (p - result.back()).norm() < 1e-9) continue;
    if (result.size() >= 2) {
      const Eigen::Vector3d a = result[result.size() - 1] - result[result.size() - 2];
      const Eigen::Vector3d b = p - result.back();
      if (a.cross(b).norm() <= 1e-9 * a.norm() * b.norm() && a.dot(b) > 0.0) result.pop_back();
    }
    result.push_back(p);
  }
  return result;
}

}  // namespace

std::optional<std::uint32_t> LatticeRoadmap::Zone::slotOf(std::uint32_t node) const {
  const auto found = std::lower_bound(nodes.begin(), nodes.end(), node);
  if (found == nodes.end() || *found != node) return std::nullopt;
  return static_cast<std::uint32_t>(found - nodes.begin());
}

LatticeRoadmap::LatticeRoadmap(const SafetyRules& rules, const FlightObjective& objective,
                               std::vector<Eigen::Vector3d> places_m, RoadmapOptions options)
    : rules_(rules),
      core_rules_(rules.withExemptions({})),
      objective_(objective),
      places_m_(std::move(places_m)),
      options_(std::move(options)) {
  if (options_.stride_voxels < 1) throw ceilplan::InputError("roadmap stride must be at least 1 voxel");
  if (options_.workers < 1) throw ceilplan::InputError("roadmap needs at least one worker thread");
  for (const Eigen::Vector3d& place : places_m_)
    if (!place.allFinite() || !rules_.environment().contains(place))
      throw ceilplan::InputError("a roadmap place lies outside the map");
  zone_radius_m_ = rules_.exemptRadius_m();
  node_count_ = detail::LatticeGrid(rules_.environment().grid().frame(), options_.stride_voxels).nodeCount();
  if (node_count_ >= kNoSlot)
    throw ceilplan::InputError("the map has too many lattice nodes: raise the roadmap stride");
  // Shares of the build time, roughly as on the shipped bridge: nodes 10 %, edges 80 %, places 10 %.
  const auto report = [this](double share) {
    if (options_.progress) options_.progress(share);
  };
  buildNodes();
  report(0.1);
  buildEdges([&](double share) { report(0.1 + 0.8 * share); });
  buildPlaces();
  report(1.0);
}

void LatticeRoadmap::buildNodes() {
  const detail::LatticeGrid lattice(rules_.environment().grid().frame(), options_.stride_voxels);
  std::vector<char> valid(node_count_, 0);
  parallelFor(node_count_, options_.workers,
              [&](std::size_t id) { valid[id] = core_rules_.isStateValid(lattice.position(id)); });
  slot_.assign(node_count_, kNoSlot);
  for (std::size_t id = 0; id < node_count_; ++id)
    if (valid[id]) {
      slot_[id] = static_cast<std::uint32_t>(valid_nodes_.size());
      valid_nodes_.push_back(static_cast<std::uint32_t>(id));
    }
}

void LatticeRoadmap::buildEdges(const std::function<void(double)>& progress) {
  const detail::LatticeGrid lattice(rules_.environment().grid().frame(), options_.stride_voxels);
  const detail::LatticeDirections directions;
  const FlightCostModel& model = objective_.model();
  core_costs_.assign(valid_nodes_.size() * kDirections, kNoEdge);
  // Each (node, direction) cell is written by the one task that owns its edge's first node.
  parallelFor(
      valid_nodes_.size(), options_.workers,
      [&](std::size_t row) {
        const std::uint32_t id = valid_nodes_[row];
        const std::array<int, 3> at = lattice.indices(id);
        const Eigen::Vector3d here = lattice.position(id);
        for (int d = kFirstForwardDirection; d < kDirections; ++d) {
          const std::array<int, 3> to = neighbour(at, directions.offsets[d]);
          if (!lattice.inside(to[0], to[1], to[2])) continue;
          const std::uint32_t other = slot_[lattice.id(to[0], to[1], to[2])];
          if (other == kNoSlot) continue;
          const Eigen::Vector3d there = lattice.position(to[0], to[1], to[2]);
          if (!core_rules_.isMotionValid(here, there)) continue;
          const auto [forth, back] = model.integrateBothWays(
              here, there, [&model](const Eigen::Vector3d& p) { return model.conditionsAt(p); });
          core_costs_[row * kDirections + d] = static_cast<float>(objective_.weights().of(forth));
          core_costs_[static_cast<std::size_t>(other) * kDirections + directions.opposite[d]] =
              static_cast<float>(objective_.weights().of(back));
        }
      },
      progress);
}

float LatticeRoadmap::coreCost(std::uint32_t node, int direction) const {
  const std::uint32_t row = slot_[node];
  return row == kNoSlot ? kNoEdge : core_costs_[static_cast<std::size_t>(row) * kDirections + direction];
}

void LatticeRoadmap::buildPlaces() {
  const detail::LatticeGrid lattice(rules_.environment().grid().frame(), options_.stride_voxels);
  const detail::LatticeDirections directions;
  const std::size_t places = places_m_.size();
  const bool zoned = rules_.hasStandoff();
  if (zoned) zones_.resize(places);
  joins_out_.resize(places);
  joins_in_.resize(places);
  const FlightCostModel& model = objective_.model();
  const auto conditions = [&model](const Eigen::Vector3d& p) { return model.conditionsAt(p); };
  const auto cost = [&](const MotionTotals& totals) { return objective_.weights().of(totals); };

  parallelFor(places, options_.workers, [&](std::size_t place) {
    const Eigen::Vector3d& centre = places_m_[place];
    // What a route starting or ending here may do (free mode: come close to the structure).
    const SafetyRules near = rules_.withExemptions({centre});
    if (zoned) {
      Zone& zone = zones_[place];
      int lo[3], hi[3];
      for (int axis = 0; axis < 3; ++axis) {
        const double origin = lattice.position(0, 0, 0)[axis];
        lo[axis] =
            std::max(0, static_cast<int>(std::floor((centre[axis] - zone_radius_m_ - origin) / lattice.spacing_m())));
        hi[axis] =
            std::min(lattice.size(axis) - 1,
                     static_cast<int>(std::ceil((centre[axis] + zone_radius_m_ - origin) / lattice.spacing_m())));
      }
      for (int c = lo[2]; c <= hi[2]; ++c)
        for (int b = lo[1]; b <= hi[1]; ++b)
          for (int a = lo[0]; a <= hi[0]; ++a) {
            const Eigen::Vector3d p = lattice.position(a, b, c);
            if ((p - centre).norm() <= zone_radius_m_ && near.isStateValid(p))
              zone.nodes.push_back(static_cast<std::uint32_t>(lattice.id(a, b, c)));
          }
      std::sort(zone.nodes.begin(), zone.nodes.end());
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
      const bool valid = zoned ? zones_[place].slotOf(node).has_value() : slot_[id] != kNoSlot;
      const Eigen::Vector3d p = lattice.position(id);
      if (!valid || !near.isMotionValid(centre, p)) return;
      const auto totals = model.integrateBothWays(centre, p, conditions);
      joins_out_[place].push_back({node, cost(totals.first)});
      joins_in_[place].push_back({node, cost(totals.second)});
    });
  });
}

std::size_t LatticeRoadmap::edgeCount() const {
  return static_cast<std::size_t>(
      std::count_if(core_costs_.begin(), core_costs_.end(), [](float c) { return c != kNoEdge; }));
}

std::size_t LatticeRoadmap::memoryBytes() const {
  std::size_t bytes = slot_.size() * sizeof(std::uint32_t) + valid_nodes_.size() * sizeof(std::uint32_t) +
                      core_costs_.size() * sizeof(float);
  for (const Zone& zone : zones_)
    bytes += zone.nodes.size() * sizeof(std::uint32_t) + zone.costs.size() * sizeof(float);
  for (std::size_t p = 0; p < joins_out_.size(); ++p)
    bytes += (joins_out_[p].size() + joins_in_[p].size()) * sizeof(Join);
  return bytes;
}

std::vector<std::optional<RoadmapRoute>> LatticeRoadmap::routesFrom(int from) const {
  const int places = static_cast<int>(places_m_.size());
  if (from < 0 || from >= places) throw ceilplan::InputError("roadmap place index out of range");
  const detail::LatticeGrid lattice(rules_.environment().grid().frame(), options_.stride_voxels);
  const detail::LatticeDirections directions;
  const bool zoned = !zones_.empty();

  // States: lattice nodes (on the way), then each goal's zone nodes (its final approach), then
  // the places themselves.
  const std::size_t lattice_states = node_count_;
  std::vector<std::size_t> zone_offset(places, lattice_states);
  std::size_t next_offset = lattice_states;
  for (int p = 0; p < places && zoned; ++p) {
    zone_offset[p] = next_offset;
    next_offset += zones_[p].nodes.size();
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
  const auto nodeOf = [&](std::size_t state) -> std::uint32_t {
    if (state < lattice_states) return static_cast<std::uint32_t>(state);
    const int p =
        static_cast<int>(std::upper_bound(zone_offset.begin(), zone_offset.end(), state) - zone_offset.begin()) - 1;
    return zones_[p].nodes[state - zone_offset[p]];
  };
  const auto arrive = [&](int goal, std::uint32_t node, std::size_t state, double g) {
    if (goal == from || (places_m_[goal] - lattice.position(node)).norm() > lattice.joinRadius_m()) return;
    for (const Join& join : joins_in_[goal])
      if (join.node == node) relax(place_offset + goal, static_cast<std::uint32_t>(state), g + join.cost);
  };

  for (const Join& join : joins_out_[from]) relax(join.node, kStart, join.cost);
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
      const std::optional<std::uint32_t> start_slot = zoned ? zones_[from].slotOf(node) : std::nullopt;
      for (int d = 0; d < kDirections; ++d) {
        const std::array<int, 3> to = neighbour(at, directions.offsets[d]);
        if (!lattice.inside(to[0], to[1], to[2])) continue;
        float c = coreCost(node, d);
        if (c == kNoEdge && start_slot) c = zones_[from].costs[*start_slot * kDirections + d];
        if (c != kNoEdge) relax(lattice.id(to[0], to[1], to[2]), state, g + c);
      }
      for (int goal = 0; goal < places; ++goal) {
        if (!zoned) {
          arrive(goal, node, state, g);
        } else if (goal != from && (places_m_[goal] - here).norm() <= zone_radius_m_) {
          if (const auto slot = zones_[goal].slotOf(node)) relax(zone_offset[goal] + *slot, state, g);
        }
      }
    } else {
      // The final approach to one goal, inside its zone.
      const int goal =
          static_cast<int>(std::upper_bound(zone_offset.begin(), zone_offset.end(), state) - zone_offset.begin()) - 1;
      const Zone& zone = zones_[goal];
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
    std::vector<Eigen::Vector3d> backwards{places_m_[goal]};
    for (std::uint32_t s = parent[state]; s != kStart; s = parent[s]) backwards.push_back(lattice.position(nodeOf(s)));
    backwards.push_back(places_m_[from]);
    RoadmapRoute route;
    route.waypoints = turningPoints({backwards.rbegin(), backwards.rend()});
    route.cost = cost_to[state];
    routes[goal] = std::move(route);
  }
  return routes;
}

}  // namespace ceilplan::planner
