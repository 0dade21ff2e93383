#include "ceilplan/planner/lattice_planner.hpp"
#include "ceilplan/core/error.hpp"

#include "lattice_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <stdexcept>
#include <unordered_map>

namespace ceilplan::planner {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Map conditions at points of the cost model's sampling lattice near structure, computed once
// each and stored compactly (2 numbers per rotor, 2 more); far from structure the model answers
// without the map anyway.
class ConditionsCache {
 public:
  explicit ConditionsCache(const FlightCostModel& model)
      : model_(model), inverse_step_(1.0 / model.step_m()), rotors_(model.energy().rotorCount()) {}

  PointConditions operator()(const Eigen::Vector3d& point_m) {
    const Eigen::Vector3d scaled = point_m * inverse_step_;
    const Eigen::Vector3d rounded = scaled.array().round();
    if ((scaled - rounded).cwiseAbs().maxCoeff() > 1e-6 || model_.farFromStructure(point_m))
      return model_.conditionsAt(point_m);
    const std::uint64_t key = (static_cast<std::uint64_t>(static_cast<std::int64_t>(rounded.x()) & 0x1FFFFF) << 42) |
                              (static_cast<std::uint64_t>(static_cast<std::int64_t>(rounded.y()) & 0x1FFFFF) << 21) |
                              (static_cast<std::uint64_t>(static_cast<std::int64_t>(rounded.z()) & 0x1FFFFF));
    const std::size_t width = 2 * rotors_ + 2;
    const auto [found, inserted] = offsets_.try_emplace(key, values_.size());
    if (inserted) {
      const PointConditions conditions = model_.conditionsAt(point_m);
      for (int r = 0; r < rotors_; ++r) {
        values_.push_back(conditions.rotors[r].gap_m);
        values_.push_back(conditions.rotors[r].coverage);
      }
      values_.push_back(conditions.ground_gap_m);
      values_.push_back(conditions.nearest_ceiling_gap_m);
      return conditions;
    }
    const double* v = values_.data() + found->second;
    PointConditions conditions;
    conditions.rotor_count = rotors_;
    for (int r = 0; r < rotors_; ++r) conditions.rotors[r] = {v[2 * r], v[2 * r + 1]};
    conditions.ground_gap_m = v[width - 2];
    conditions.nearest_ceiling_gap_m = v[width - 1];
    return conditions;
  }

 private:
  const FlightCostModel& model_;
  double inverse_step_;
  int rotors_;
  std::unordered_map<std::uint64_t, std::size_t> offsets_;
  std::vector<double> values_;
};

}  // namespace

LatticePlanner::LatticePlanner(const SafetyRules& rules, const FlightObjective& objective, LatticeOptions options)
    : rules_(rules), objective_(objective), options_(std::move(options)) {
  if (options_.stride_voxels < 1) throw ceilplan::InputError("lattice stride must be at least 1 voxel");
}

std::optional<LatticeResult> LatticePlanner::plan(const Eigen::Vector3d& start_m, const Eigen::Vector3d& goal_m) {
  stopped_ = false;
  const detail::LatticeGrid lattice(rules_.environment().grid().frame(), options_.stride_voxels);
  const detail::LatticeDirections directions;
  const std::size_t node_count = lattice.nodeCount();

  // Node ids: lattice nodes, then the goal, then the start.
  const std::size_t goal_id = node_count, start_id = node_count + 1;
  enum : std::uint8_t { kUnchecked = 0, kValid = 1, kInvalid = 2, kClosed = 4 };
  std::vector<std::uint8_t> flags(node_count, kUnchecked);
  std::vector<double> cost_to(node_count + 2, kInfinity);
  std::vector<std::uint32_t> parent(node_count + 2, std::numeric_limits<std::uint32_t>::max());
  const auto nodeAt = [&](std::size_t id) {
    if (id == goal_id) return goal_m;
    if (id == start_id) return start_m;
    return lattice.position(id);
  };
  const auto nodeValid = [&](std::size_t id) {
    if (!(flags[id] & (kValid | kInvalid))) flags[id] |= rules_.isStateValid(nodeAt(id)) ? kValid : kInvalid;
    return (flags[id] & kValid) != 0;
  };

  ConditionsCache conditions(objective_.model());
  const auto edgeCost = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return objective_.weights().of(objective_.model().integrate(a, b, conditions));
  };

  using Entry = std::pair<double, std::size_t>;  // (f, id)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  const auto relax = [&](std::size_t from, std::size_t to, double g) {
    if (g < cost_to[to]) {
      cost_to[to] = g;
      parent[to] = static_cast<std::uint32_t>(from);
      open.emplace(g + objective_.heuristic(nodeAt(to), goal_m), to);
    }
  };
  std::vector<char> joins_goal(node_count, 0);
  lattice.forEachNodeNear(goal_m, [&](std::size_t id) {
    if (nodeValid(id) && rules_.isMotionValid(nodeAt(id), goal_m)) joins_goal[id] = 1;
  });

  cost_to[start_id] = 0.0;
  if (rules_.isMotionValid(start_m, goal_m)) relax(start_id, goal_id, edgeCost(start_m, goal_m));
  lattice.forEachNodeNear(start_m, [&](std::size_t id) {
    if (nodeValid(id) && rules_.isMotionValid(start_m, nodeAt(id))) relax(start_id, id, edgeCost(start_m, nodeAt(id)));
  });

  std::size_t expansions = 0;
  while (!open.empty()) {
    const auto [f, id] = open.top();
    open.pop();
    if (id == goal_id) break;
    if (flags[id] & kClosed) continue;
    flags[id] |= kClosed;
    if (++expansions > options_.max_expansions ||
        (options_.should_stop && expansions % 4096 == 0 && options_.should_stop())) {
      stopped_ = true;
      return std::nullopt;
    }
    const Eigen::Vector3d here = nodeAt(id);
    const double g = cost_to[id];
    if (joins_goal[id]) relax(id, goal_id, g + edgeCost(here, goal_m));
    const std::array<int, 3> at = lattice.indices(id);
    for (const std::array<int, 3>& offset : directions.offsets) {
      const int na = at[0] + offset[0], nb = at[1] + offset[1], nc = at[2] + offset[2];
      if (!lattice.inside(na, nb, nc)) continue;
      const std::size_t next = lattice.id(na, nb, nc);
      if ((flags[next] & kClosed) || !nodeValid(next)) continue;
      const Eigen::Vector3d there = lattice.position(na, nb, nc);
      // The lower bound g + c_min d rules out most edges before any motion check.
      if (g + objective_.heuristic(here, there) >= cost_to[next]) continue;
      if (!rules_.isMotionValid(here, there)) continue;
      relax(id, next, g + edgeCost(here, there));
    }
  }
  if (!std::isfinite(cost_to[goal_id])) return std::nullopt;
  LatticeResult result;
  result.cost = cost_to[goal_id];
  result.expansions = expansions;
  for (std::size_t id = goal_id; id != start_id; id = parent[id]) result.waypoints.push_back(nodeAt(id));
  result.waypoints.push_back(start_m);
  std::reverse(result.waypoints.begin(), result.waypoints.end());
  return result;
}

}  // namespace ceilplan::planner
