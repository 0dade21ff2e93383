#include "ceilplan/planner/lattice_planner.hpp"

#include "ceilplan/core/error.hpp"

#include "conditions_cache.hpp"
#include "lattice_grid.hpp"
#include "lattice_query.hpp"

#include <ompl/base/PlannerData.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
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

SearchOutcome latticeSearch(const SafetyRules& rules, const FlightObjective& objective, const LatticeSettings& settings,
                            const Eigen::Vector3d& start_m, const Eigen::Vector3d& goal_m,
                            const ompl::base::PlannerTerminationCondition& ptc) {
  const detail::LatticeGrid lattice(rules.environment().grid().frame(), settings.spacing_m);
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
    if (!(flags[id] & (kValid | kInvalid))) flags[id] |= rules.isStateValid(nodeAt(id)) ? kValid : kInvalid;
    return (flags[id] & kValid) != 0;
  };

  detail::ConditionsCache conditions(objective.model());
  const auto edgeCost = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return objective.weights().of(objective.model().integrate(a, b, conditions));
  };

  using Entry = std::pair<double, std::size_t>;  // (f, id)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  const auto relax = [&](std::size_t from, std::size_t to, double g) {
    if (g < cost_to[to]) {
      cost_to[to] = g;
      parent[to] = static_cast<std::uint32_t>(from);
      open.emplace(g + objective.heuristic(nodeAt(to), goal_m), to);
    }
  };
  std::vector<char> joins_goal(node_count, 0);
  lattice.forEachNodeNear(goal_m, [&](std::size_t id) {
    if (nodeValid(id) && rules.isMotionValid(nodeAt(id), goal_m)) joins_goal[id] = 1;
  });

  cost_to[start_id] = 0.0;
  if (rules.isMotionValid(start_m, goal_m)) relax(start_id, goal_id, edgeCost(start_m, goal_m));
  lattice.forEachNodeNear(start_m, [&](std::size_t id) {
    if (nodeValid(id) && rules.isMotionValid(start_m, nodeAt(id))) relax(start_id, id, edgeCost(start_m, nodeAt(id)));
  });

  SearchOutcome outcome;
  std::size_t& expansions = outcome.expansions;
  while (!open.empty()) {
    const auto [f, id] = open.top();
    open.pop();
    if (id == goal_id) break;
    if (flags[id] & kClosed) continue;
    flags[id] |= kClosed;
    if (++expansions > settings.max_expansions || (expansions % 4096 == 0 && ptc())) {
      outcome.stopped = true;
      return outcome;
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
      if (g + objective.heuristic(here, there) >= cost_to[next]) continue;
      if (!rules.isMotionValid(here, there)) continue;
      relax(id, next, g + edgeCost(here, there));
    }
  }
  if (!std::isfinite(cost_to[goal_id])) return outcome;
  outcome.cost = cost_to[goal_id];
  for (std::size_t id = goal_id; id != start_id; id = parent[id]) outcome.waypoints.push_back(nodeAt(id));
  outcome.waypoints.push_back(start_m);
  std::reverse(outcome.waypoints.begin(), outcome.waypoints.end());
  return outcome;
}

}  // namespace

void LatticeSettings::validate() const {
  if (!(std::isfinite(spacing_m) && spacing_m > 0.0))
    throw ceilplan::InputError("lattice spacing must be a positive number of metres");
  if (workers < 1) throw ceilplan::InputError("the lattice planners need at least one worker thread");
}

LatticePlanner::LatticePlanner(const ompl::base::SpaceInformationPtr& si, LatticeSettings settings)
    : ompl::base::Planner(si, "lattice"), settings_(std::move(settings)), best_cost_(kInfinity) {
  settings_.validate();
  specs_.optimizingPaths = true;
  specs_.directed = true;
  declareParam<double>("spacing_m", this, &LatticePlanner::setSpacing, &LatticePlanner::getSpacing, "0.01:0.01:2.0");
  addPlannerProgressProperty("best cost REAL", [this] { return std::to_string(best_cost_.load()); });
}

void LatticePlanner::setSpacing(double spacing_m) {
  LatticeSettings settings = settings_;
  settings.spacing_m = spacing_m;
  settings.validate();
  settings_ = settings;
}

void LatticePlanner::clear() {
  ompl::base::Planner::clear();
  expansions_ = 0;
  best_cost_ = kInfinity;
}

ompl::base::PlannerStatus LatticePlanner::solve(const ompl::base::PlannerTerminationCondition& ptc) {
  checkValidity();
  const SafetyRules& rules = detail::rulesOf(*si_, getName());
  const FlightObjective& objective = detail::objectiveOf(*pdef_, getName());
  ompl::base::PlannerStatus failure;
  const std::optional<detail::LatticeQuery> query = detail::readQuery(*pdef_, failure);
  if (!query) return failure;
  const SearchOutcome outcome = latticeSearch(rules, objective, settings_, query->start_m, query->goal_m, ptc);
  expansions_ = outcome.expansions;
  if (outcome.stopped) return ompl::base::PlannerStatus::TIMEOUT;
  if (outcome.waypoints.empty()) return ompl::base::PlannerStatus::ABORT;
  best_cost_ = outcome.cost;
  detail::addSolution(*this, outcome.waypoints, outcome.cost);
  return ompl::base::PlannerStatus::EXACT_SOLUTION;
}

void LatticePlanner::getPlannerData(ompl::base::PlannerData& data) const {
  ompl::base::Planner::getPlannerData(data);
  data.properties["expansions INTEGER"] = std::to_string(expansions_);
}

}  // namespace ceilplan::planner
