#include "ceilplan/planner/lattice_planner.hpp"

#include <algorithm>
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
  if (options_.stride_voxels < 1) throw std::invalid_argument("lattice stride must be at least 1 voxel");
}

std::optional<LatticeResult> LatticePlanner::plan(const Eigen::Vector3d& start_m, const Eigen::Vector3d& goal_m) {
  stopped_ = false;
  const environment::GridFrame& frame = rules_.environment().grid().frame();
  const int stride = options_.stride_voxels;
  const double spacing = stride * frame.resolution_m();
  int size[3];
  for (int axis = 0; axis < 3; ++axis) size[axis] = (frame.size()[axis] + stride - 1) / stride;
  const std::size_t node_count = static_cast<std::size_t>(size[0]) * size[1] * size[2];
  const auto position = [&](int a, int b, int c) {
    return Eigen::Vector3d(frame.centreOf(0, a * stride), frame.centreOf(1, b * stride), frame.centreOf(2, c * stride));
  };
  const auto linear = [&](int a, int b, int c) { return (static_cast<std::size_t>(c) * size[1] + b) * size[0] + a; };

  // Node ids: lattice nodes, then the goal, then the start.
  const std::size_t goal_id = node_count, start_id = node_count + 1;
  enum : std::uint8_t { kUnchecked = 0, kValid = 1, kInvalid = 2, kClosed = 4 };
  std::vector<std::uint8_t> flags(node_count, kUnchecked);
  std::vector<double> cost_to(node_count + 2, kInfinity);
  std::vector<std::uint32_t> parent(node_count + 2, std::numeric_limits<std::uint32_t>::max());
  const auto nodeAt = [&](std::size_t id) {
    if (id == goal_id) return goal_m;
    if (id == start_id) return start_m;
    const int a = static_cast<int>(id % size[0]), b = static_cast<int>((id / size[0]) % size[1]);
    const int c = static_cast<int>(id / (static_cast<std::size_t>(size[0]) * size[1]));
    return position(a, b, c);
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
  // Lattice nodes within reach of a free point, for joining the start and the goal.
  const double join_radius = std::sqrt(3.0) * spacing;
  const auto nodesNear = [&](const Eigen::Vector3d& point, const std::function<void(std::size_t)>& visit) {
    int lo[3], hi[3];
    for (int axis = 0; axis < 3; ++axis) {
      const double index = (point[axis] - frame.centreOf(axis, 0)) / spacing;
      lo[axis] = std::max(0, static_cast<int>(std::floor(index)) - 1);
      hi[axis] = std::min(size[axis] - 1, static_cast<int>(std::ceil(index)) + 1);
    }
    for (int c = lo[2]; c <= hi[2]; ++c)
      for (int b = lo[1]; b <= hi[1]; ++b)
        for (int a = lo[0]; a <= hi[0]; ++a)
          if ((position(a, b, c) - point).norm() <= join_radius) visit(linear(a, b, c));
  };
  std::vector<char> joins_goal(node_count, 0);
  nodesNear(goal_m, [&](std::size_t id) {
    if (nodeValid(id) && rules_.isMotionValid(nodeAt(id), goal_m)) joins_goal[id] = 1;
  });

  cost_to[start_id] = 0.0;
  if (rules_.isMotionValid(start_m, goal_m)) relax(start_id, goal_id, edgeCost(start_m, goal_m));
  nodesNear(start_m, [&](std::size_t id) {
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
    const int a = static_cast<int>(id % size[0]), b = static_cast<int>((id / size[0]) % size[1]);
    const int c = static_cast<int>(id / (static_cast<std::size_t>(size[0]) * size[1]));
    for (int dc = -1; dc <= 1; ++dc)
      for (int db = -1; db <= 1; ++db)
        for (int da = -1; da <= 1; ++da) {
          const int na = a + da, nb = b + db, nc = c + dc;
          if ((da | db | dc) == 0 || na < 0 || nb < 0 || nc < 0 || na >= size[0] || nb >= size[1] || nc >= size[2])
            continue;
          const std::size_t next = linear(na, nb, nc);
          if ((flags[next] & kClosed) || !nodeValid(next)) continue;
          const Eigen::Vector3d there = position(na, nb, nc);
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
