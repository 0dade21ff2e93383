#include "ceilplan/planner/lattice_planner.hpp"

#include "ceilplan/core/error.hpp"

#include "conditions_cache.hpp"
#include "lattice_bridge.hpp"
#include "lattice_grid.hpp"
#include "lattice_query.hpp"

#include <ompl/base/PlannerData.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <optional>
#include <queue>

namespace ceilplan::planner {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct SearchOutcome {
  std::vector<Eigen::Vector3d> waypoints;  // empty: no path
  double cost = kInfinity;
  std::size_t expansions = 0;
  bool stopped = false;
};

// A passage the coarse lattice misses, found on the fine lattice: an extra edge of the search.
struct Bridge {
  std::size_t from = 0, to = 0;            // search node ids (lattice nodes, the start, the goal)
  std::vector<Eigen::Vector3d> waypoints;  // from `from`'s position to `to`'s
  double cost = 0.0;
};

// A* from start to goal over the coarse lattice, plus at most one bridge. Keeps what it
// learnt of the lattice for the refinement that follows a failure.
class CoarseSearch {
 public:
  CoarseSearch(const SafetyRules& rules, const FlightObjective& objective, const LatticeSettings& settings,
               const Eigen::Vector3d& start_m, const Eigen::Vector3d& goal_m)
      : rules_(rules),
        objective_(objective),
        settings_(settings),
        lattice_(rules.environment().grid().frame(), settings.spacing_m),
        node_count_(lattice_.nodeCount()),
        goal_id_(node_count_),
        start_id_(node_count_ + 1),
        start_m_(start_m),
        goal_m_(goal_m),
        flags_(node_count_, kUnchecked),
        conditions_(objective.model()) {}

  SearchOutcome run(const ompl::base::PlannerTerminationCondition& ptc, const Bridge* bridge);

  // The rim of what the last run reached (closed nodes next to an invalid node or the
  // lattice's edge), and the start.
  std::vector<Eigen::Vector3d> reachedRim() const;
  // The rim of the region the goal reaches over the lattice (a flood, valid motions), and the goal.
  std::vector<Eigen::Vector3d> goalRim(const ompl::base::PlannerTerminationCondition& ptc);

  // The node id of a position returned by the rims.
  std::size_t idOf(const Eigen::Vector3d& position_m) const;
  Eigen::Vector3d nodeAt(std::size_t id) const {
    if (id == goal_id_) return goal_m_;
    if (id == start_id_) return start_m_;
    return lattice_.position(id);
  }

 private:
  enum : std::uint8_t { kUnchecked = 0, kValid = 1, kInvalid = 2, kClosed = 4, kGoalSide = 8 };

  bool nodeValid(std::size_t id) {
    if (!(flags_[id] & (kValid | kInvalid))) flags_[id] |= rules_.isStateValid(nodeAt(id)) ? kValid : kInvalid;
    return (flags_[id] & kValid) != 0;
  }
  double edgeCost(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return objective_.weights().of(objective_.model().integrate(a, b, conditions_));
  }
  // Whether a node touches an invalid node or the lattice's edge (all neighbours checked).
  bool onRim(std::size_t id);
  template <typename Visit>
  void forEachNeighbour(std::size_t id, Visit&& visit) const {
    const std::array<int, 3> at = lattice_.indices(id);
    for (const std::array<int, 3>& offset : directions_.offsets) {
      const int a = at[0] + offset[0], b = at[1] + offset[1], c = at[2] + offset[2];
      visit(lattice_.inside(a, b, c) ? std::optional<std::size_t>(lattice_.id(a, b, c)) : std::nullopt);
    }
  }

  const SafetyRules& rules_;
  const FlightObjective& objective_;
  const LatticeSettings& settings_;
  const detail::LatticeGrid lattice_;
  const detail::LatticeDirections directions_;
  const std::size_t node_count_, goal_id_, start_id_;
  const Eigen::Vector3d start_m_, goal_m_;
  std::vector<std::uint8_t> flags_;
  detail::ConditionsCache conditions_;
};

SearchOutcome CoarseSearch::run(const ompl::base::PlannerTerminationCondition& ptc, const Bridge* bridge) {
  // Node ids: lattice nodes, then the goal, then the start.
  for (std::uint8_t& flag : flags_) flag &= static_cast<std::uint8_t>(~kClosed);
  std::vector<double> cost_to(node_count_ + 2, kInfinity);
  std::vector<std::uint32_t> parent(node_count_ + 2, std::numeric_limits<std::uint32_t>::max());
  bool bridged = false;  // the goal side of the bridge was last reached over it

  using Entry = std::pair<double, std::size_t>;  // (f, id)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  const auto relax = [&](std::size_t from, std::size_t to, double g, bool over_bridge = false) {
    if (g < cost_to[to]) {
      cost_to[to] = g;
      parent[to] = static_cast<std::uint32_t>(from);
      if (bridge && to == bridge->to) bridged = over_bridge;
      open.emplace(g + objective_.heuristic(nodeAt(to), goal_m_), to);
    }
  };
  const auto crossBridge = [&](std::size_t id, double g) {
    if (bridge && id == bridge->from) relax(id, bridge->to, g + bridge->cost, true);
  };
  std::vector<char> joins_goal(node_count_, 0);
  lattice_.forEachNodeNear(goal_m_, [&](std::size_t id) {
    if (nodeValid(id) && rules_.isMotionValid(nodeAt(id), goal_m_)) joins_goal[id] = 1;
  });

  cost_to[start_id_] = 0.0;
  if (rules_.isMotionValid(start_m_, goal_m_)) relax(start_id_, goal_id_, edgeCost(start_m_, goal_m_));
  lattice_.forEachNodeNear(start_m_, [&](std::size_t id) {
    if (nodeValid(id) && rules_.isMotionValid(start_m_, nodeAt(id)))
      relax(start_id_, id, edgeCost(start_m_, nodeAt(id)));
  });
  crossBridge(start_id_, 0.0);

  SearchOutcome outcome;
  std::size_t& expansions = outcome.expansions;
  while (!open.empty()) {
    const auto [f, id] = open.top();
    open.pop();
    if (id == goal_id_) break;
    if (flags_[id] & kClosed) continue;
    flags_[id] |= kClosed;
    if (++expansions > settings_.max_expansions || (expansions % 4096 == 0 && ptc())) {
      outcome.stopped = true;
      return outcome;
    }
    const Eigen::Vector3d here = nodeAt(id);
    const double g = cost_to[id];
    if (joins_goal[id]) relax(id, goal_id_, g + edgeCost(here, goal_m_));
    crossBridge(id, g);
    const std::array<int, 3> at = lattice_.indices(id);
    for (const std::array<int, 3>& offset : directions_.offsets) {
      const int na = at[0] + offset[0], nb = at[1] + offset[1], nc = at[2] + offset[2];
      if (!lattice_.inside(na, nb, nc)) continue;
      const std::size_t next = lattice_.id(na, nb, nc);
      if ((flags_[next] & kClosed) || !nodeValid(next)) continue;
      const Eigen::Vector3d there = lattice_.position(na, nb, nc);
      // The lower bound g + c_min d rules out most edges before any motion check.
      if (g + objective_.heuristic(here, there) >= cost_to[next]) continue;
      if (!rules_.isMotionValid(here, there)) continue;
      relax(id, next, g + edgeCost(here, there));
    }
  }
  if (!std::isfinite(cost_to[goal_id_])) return outcome;
  outcome.cost = cost_to[goal_id_];
  std::vector<Eigen::Vector3d> backwards;
  for (std::size_t id = goal_id_; id != start_id_; id = parent[id]) {
    if (bridge && bridged && id == bridge->to)
      backwards.insert(backwards.end(), bridge->waypoints.rbegin(), bridge->waypoints.rend() - 1);
    else
      backwards.push_back(nodeAt(id));
  }
  backwards.push_back(start_m_);
  outcome.waypoints.assign(backwards.rbegin(), backwards.rend());
  return outcome;
}

bool CoarseSearch::onRim(std::size_t id) {
  bool rim = false;
  forEachNeighbour(id, [&](std::optional<std::size_t> next) { rim = rim || !next || !nodeValid(*next); });
  return rim;
}

std::vector<Eigen::Vector3d> CoarseSearch::reachedRim() const {
  std::vector<Eigen::Vector3d> rim{start_m_};
  for (std::size_t id = 0; id < node_count_; ++id) {
    if (!(flags_[id] & kClosed)) continue;
    bool touches = false;
    forEachNeighbour(id, [&](std::optional<std::size_t> next) {
      touches = touches || !next || (flags_[*next] & kInvalid);  // every neighbour of a closed node was checked
    });
    if (touches) rim.push_back(lattice_.position(id));
  }
  return rim;
}

std::vector<Eigen::Vector3d> CoarseSearch::goalRim(const ompl::base::PlannerTerminationCondition& ptc) {
  std::vector<Eigen::Vector3d> rim{goal_m_};
  std::deque<std::size_t> queue;
  lattice_.forEachNodeNear(goal_m_, [&](std::size_t id) {
    if (nodeValid(id) && rules_.isMotionValid(nodeAt(id), goal_m_)) {
      flags_[id] |= kGoalSide;
      queue.push_back(id);
    }
  });
  std::size_t visits = 0;
  while (!queue.empty()) {
    if (++visits % 4096 == 0 && ptc()) break;
    const std::size_t id = queue.front();
    queue.pop_front();
    if (onRim(id)) rim.push_back(lattice_.position(id));
    forEachNeighbour(id, [&](std::optional<std::size_t> next) {
      if (!next || (flags_[*next] & kGoalSide) || !nodeValid(*next)) return;
      if (!rules_.isMotionValid(lattice_.position(*next), lattice_.position(id))) return;
      flags_[*next] |= kGoalSide;
      queue.push_back(*next);
    });
  }
  return rim;
}

std::size_t CoarseSearch::idOf(const Eigen::Vector3d& position_m) const {
  if (position_m == start_m_) return start_id_;
  if (position_m == goal_m_) return goal_id_;
  std::size_t found = node_count_;
  lattice_.forEachNodeWithin(position_m, 1e-6, [&](std::size_t id) { found = id; });
  return found;
}

}  // namespace

LatticePlanner::LatticePlanner(const ompl::base::SpaceInformationPtr& si, LatticeSettings settings)
    : LatticePlannerBase(si, "lattice", std::move(settings)) {}

void LatticePlanner::clear() {
  ompl::base::Planner::clear();
  expansions_ = 0;
  forgetResult();
}

ompl::base::PlannerStatus LatticePlanner::solve(const ompl::base::PlannerTerminationCondition& ptc) {
  checkValidity();
  forgetResult();
  const SafetyRules& rules = detail::rulesOf(*si_, getName());
  const FlightObjective& objective = detail::objectiveOf(*pdef_, getName());
  ompl::base::PlannerStatus failure;
  const std::optional<detail::LatticeQuery> query = detail::readQuery(*pdef_, failure);
  if (!query) return failure;
  CoarseSearch search(rules, objective, settings_, query->start_m, query->goal_m);
  SearchOutcome outcome = search.run(ptc, nullptr);
  expansions_ = outcome.expansions;
  if (outcome.stopped) return ompl::base::PlannerStatus::TIMEOUT;
  if (outcome.waypoints.empty()) {
    // Refinement: a passage between what the start and the goal reach on the lattice.
    const std::vector<Eigen::Vector3d> start_side = search.reachedRim();
    const std::vector<Eigen::Vector3d> goal_side = search.goalRim(ptc);
    if (ptc()) return ompl::base::PlannerStatus::TIMEOUT;
    const detail::BridgeOutcome found = detail::findBridge(rules, start_side, goal_side, ptc);
    if (found.waypoints.empty()) {
      if (!found.blockage) return ompl::base::PlannerStatus::TIMEOUT;
      blockage_ = found.blockage;
      detail::nameEnclosedEnd(*blockage_, rules.environment().grid(), query->start_m, query->goal_m);
      return ompl::base::PlannerStatus::ABORT;
    }
    Bridge bridge{search.idOf(start_side[found.from]), search.idOf(goal_side[found.to]), found.waypoints,
                  objective.pathCost(found.waypoints)};
    outcome = search.run(ptc, &bridge);
    expansions_ += outcome.expansions;
    if (outcome.stopped) return ompl::base::PlannerStatus::TIMEOUT;
    if (outcome.waypoints.empty())
      throw ceilplan::Error("the lattice search lost its bridge (a bug: please report it)");
  }
  best_cost_ = outcome.cost;
  detail::addSolution(*this, outcome.waypoints, outcome.cost);
  return ompl::base::PlannerStatus::EXACT_SOLUTION;
}

void LatticePlanner::getPlannerData(ompl::base::PlannerData& data) const {
  ompl::base::Planner::getPlannerData(data);
  data.properties["expansions INTEGER"] = std::to_string(expansions_);
}

}  // namespace ceilplan::planner
