#include "ceilplan/planner/path_refinement.hpp"

#include <nlopt.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <unordered_map>
#include <utility>

namespace ceilplan::planner {

Waypoints shortcutPath(const Waypoints& path, const SafetyRules& rules, const FlightObjective& objective) {
  if (path.size() < 3) return path;
  std::vector<double> cost_to(path.size(), 0.0);  // cumulative cost along the input
  for (std::size_t k = 1; k < path.size(); ++k)
    cost_to[k] = cost_to[k - 1] + objective.motionCost(path[k - 1], path[k]);
  Waypoints result{path.front()};
  std::size_t i = 0;
  while (i + 1 < path.size()) {
    std::size_t next = i + 1;
    for (std::size_t j = path.size() - 1; j > i + 1; --j) {
      const double along = cost_to[j] - cost_to[i];
      // The heuristic bound rejects hopeless jumps before any map query.
      if (objective.heuristic(path[i], path[j]) >= along) continue;
      if (!rules.isMotionValid(path[i], path[j])) continue;
      if (objective.motionCost(path[i], path[j]) < along) {
        next = j;
        break;
      }
    }
    result.push_back(path[next]);
    i = next;
  }
  return result;
}

Waypoints subdivide(const Waypoints& path, double max_segment_m) {
  if (path.empty()) return path;
  Waypoints result{path.front()};
  for (std::size_t k = 1; k < path.size(); ++k) {
    const int pieces = std::max(1, static_cast<int>(std::ceil((path[k] - path[k - 1]).norm() / max_segment_m)));
    for (int p = 1; p <= pieces; ++p) result.push_back(path[k - 1] + (path[k] - path[k - 1]) * (double(p) / pieces));
  }
  return result;
}

namespace {

double pathLength(const Waypoints& path) {
  double length = 0.0;
  for (std::size_t k = 1; k < path.size(); ++k) length += (path[k] - path[k - 1]).norm();
  return length;
}

bool invalidMotion(const Eigen::Vector3d& from, const Eigen::Vector3d& to, const SafetyRules& rules) {
  return !rules.isStateValid(to) || !rules.isMotionValid(from, to);
}

int invalidMotions(const Waypoints& path, const SafetyRules& rules) {
  int invalid = 0;
  for (std::size_t k = 1; k < path.size(); ++k) invalid += invalidMotion(path[k - 1], path[k], rules);
  return invalid;
}

// The cost and validity of each segment a refinement evaluated, by its ends: BOBYQA's first
// 2n + 1 evaluations move one coordinate each, so all but two segments of such a candidate were
// costed before. The same values, summed in the same order, as pathCost and invalidMotions.
class SegmentMemo {
 public:
  SegmentMemo(const SafetyRules& rules, const FlightObjective& objective) : rules_(rules), objective_(objective) {}

  // pathCost(path) x (1 + invalidMotions(path)).
  double penalisedCost(const Waypoints& path) {
    double cost = 0.0;
    int invalid = 0;
    for (std::size_t k = 1; k < path.size(); ++k) {
      const Segment& segment = of(path[k - 1], path[k]);
      cost += segment.cost;
      invalid += segment.invalid;
    }
    return cost * (1.0 + invalid);
  }

 private:
  struct Segment {
    double cost;
    bool invalid;
  };
  using Ends = std::array<double, 6>;
  struct Hash {
    std::size_t operator()(const Ends& ends) const {
      std::size_t hash = 0;
      for (const double value : ends) hash = hash * 1000003u ^ std::hash<double>()(value);
      return hash;
    }
  };

  const Segment& of(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
    const Ends ends{from.x(), from.y(), from.z(), to.x(), to.y(), to.z()};
    auto found = segments_.find(ends);
    if (found == segments_.end())
      found = segments_.emplace(ends, Segment{objective_.motionCost(from, to), invalidMotion(from, to, rules_)}).first;
    return found->second;
  }

  const SafetyRules& rules_;
  const FlightObjective& objective_;
  std::unordered_map<Ends, Segment, Hash> segments_;
};

// `refined` where every motion of it is valid and it costs less than `path`, else `path`.
Waypoints validAndCheaper(const Waypoints& refined, const Waypoints& path, const SafetyRules& rules,
                          const FlightObjective& objective) {
  if (invalidMotions(refined, rules) > 0 || !rules.isStateValid(refined.front())) return path;
  return objective.pathCost(refined) < objective.pathCost(path) ? refined : path;
}

// BOBYQA over the inner waypoints of the whole path (refinePath).
Waypoints refineWhole(const Waypoints& path, const SafetyRules& rules, const FlightObjective& objective,
                      const RefinementOptions& options) {
  if (path.size() < 2) return path;
  // Enough inner waypoints to bend the path, few enough for a derivative-free local method.
  const int segments = std::max(2, options.max_waypoints - 1);
  const Waypoints start = subdivide(path, std::max(pathLength(path) / segments, 1e-3));
  const std::size_t inner = start.size() - 2;
  if (inner == 0) return path;
  const Eigen::AlignedBox3d box = rules.environment().grid().frame().bounds();

  std::vector<double> x(3 * inner), lower(3 * inner), upper(3 * inner);
  for (std::size_t w = 0; w < inner; ++w)
    for (int axis = 0; axis < 3; ++axis) {
      const double value = start[w + 1][axis];
      x[3 * w + axis] = value;
      lower[3 * w + axis] = std::max(box.min()[axis], value - options.max_move_m);
      upper[3 * w + axis] = std::min(box.max()[axis], value + options.max_move_m);
      if (upper[3 * w + axis] <= lower[3 * w + axis]) upper[3 * w + axis] = lower[3 * w + axis] + 1e-6;
    }
  const auto toPath = [&](const double* values) {
    Waypoints candidate = start;
    for (std::size_t w = 0; w < inner; ++w)
      candidate[w + 1] = Eigen::Vector3d(values[3 * w], values[3 * w + 1], values[3 * w + 2]);
    return candidate;
  };
  SegmentMemo memo(rules, objective);
  const auto penalised = [&](const Waypoints& candidate) {
    for (const Eigen::Vector3d& p : candidate)
      if (!box.contains(p)) return 1e30;
    return memo.penalisedCost(candidate);
  };
  const std::function<double(const double*)> evaluate = [&](const double* values) { return penalised(toPath(values)); };

  nlopt::opt optimiser(nlopt::LN_BOBYQA, static_cast<unsigned>(x.size()));
  optimiser.set_lower_bounds(lower);
  optimiser.set_upper_bounds(upper);
  optimiser.set_maxeval(options.max_evaluations);
  optimiser.set_xtol_abs(0.2 * rules.environment().grid().frame().resolution_m());
  optimiser.set_initial_step(0.25 * options.max_move_m);
  optimiser.set_min_objective(
      [](unsigned, const double* values, double*, void* data) {
        return (*static_cast<const std::function<double(const double*)>*>(data))(values);
      },
      const_cast<std::function<double(const double*)>*>(&evaluate));
  double best = 0.0;
  try {
    optimiser.optimize(x, best);
  } catch (const std::exception&) {
    // NLopt gives up (roundoff, forced stop): whatever x holds is re-checked below.
  }
  return validAndCheaper(shortcutPath(toPath(x.data()), rules, objective), path, rules, objective);
}

// The path cut `at_m` along it: the part before the cut, ending there, and the part after,
// starting there.
std::pair<Waypoints, Waypoints> cutAt(const Waypoints& path, double at_m) {
  double walked_m = 0.0;
  for (std::size_t k = 1; k < path.size(); ++k) {
    const double step_m = (path[k] - path[k - 1]).norm();
    if (walked_m + step_m >= at_m) {
      const auto next = path.begin() + static_cast<std::ptrdiff_t>(k);
      std::pair<Waypoints, Waypoints> parts{Waypoints(path.begin(), next), Waypoints(next, path.end())};
      const Eigen::Vector3d cut_m =
          walked_m + step_m == at_m
              ? path[k]
              : Eigen::Vector3d(path[k - 1] + (path[k] - path[k - 1]) * ((at_m - walked_m) / step_m));
      if (cut_m != parts.first.back()) parts.first.push_back(cut_m);
      if (cut_m != parts.second.front()) parts.second.insert(parts.second.begin(), cut_m);
      return parts;
    }
    walked_m += step_m;
  }
  return {path, Waypoints{path.back()}};
}

}  // namespace

Waypoints refinePath(const Waypoints& path, const SafetyRules& rules, const FlightObjective& objective,
                     const RefinementOptions& options) {
  const double window_m = options.end_window_m;
  const double length_m = pathLength(path);
  if (!(window_m > 0.0) || length_m <= 3.0 * window_m) return refineWhole(path, rules, objective, options);
  // A long leg's middle is the roadmap's route along the structure, optimal on its lattice: the
  // waypoints resampled over all of it would lie tens of metres apart, each moved at most
  // max_move_m, and every evaluation would cost the whole leg. Each end is refined on its own
  // instead, where the leg leaves and meets the structure, at the same cost however long the leg.
  const auto [head, rest] = cutAt(path, window_m);
  const auto [middle, tail] = cutAt(rest, pathLength(rest) - window_m);
  Waypoints joined = refineWhole(head, rules, objective, options);
  joined.insert(joined.end(), middle.begin() + 1, middle.end() - 1);  // its ends are the parts'
  const Waypoints refined_tail = refineWhole(tail, rules, objective, options);
  joined.insert(joined.end(), refined_tail.begin(), refined_tail.end());
  return validAndCheaper(shortcutPath(joined, rules, objective), path, rules, objective);
}

}  // namespace ceilplan::planner
