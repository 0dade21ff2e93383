#include "ceilplan/mission/tour_order.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>

namespace ceilplan::mission {

namespace {

constexpr const char* kHeuristicName = "nearest-neighbour+2-opt+or-opt";

// A move must gain more than this (relative to the tour's cost) to count, so rounding noise
// cannot make the local search cycle.
constexpr double kRelativeGain = 1e-12;

int targetCount(const CostMatrix& costs) { return static_cast<int>(costs.rows()) - 1; }

// The tour as a closed walk: home, the targets, home. Prefix sums of the walk's leg costs
// forwards and backwards make the cost change of any 2-opt or Or-opt move O(1), reversed
// stretches included (asymmetric costs).
class Walk {
 public:
  Walk(const CostMatrix& costs, const std::vector<int>& targets) : costs_(&costs) {
    nodes_.reserve(targets.size() + 2);
    nodes_.push_back(0);
    nodes_.insert(nodes_.end(), targets.begin(), targets.end());
    nodes_.push_back(0);
    refresh();
  }

  double cost() const { return forward_.back(); }
  std::vector<int> targets() const { return {nodes_.begin() + 1, nodes_.end() - 1}; }

  // Local search to a local optimum under both neighbourhoods.
  void improve() {
    bool improved = true;
    while (improved) improved = twoOpt() || orOpt();
  }

  // Double bridge: cuts the target sequence into parts A B C D (B and C not empty; home closes
  // the tour, so A or D may be) and makes it A C B D.
  void kick(std::mt19937_64& random) {
    const int n = static_cast<int>(nodes_.size()) - 2;
    if (n < 3) return;
    std::uniform_int_distribution<int> cut(0, n);
    int c[3];
    do {
      for (int& value : c) value = cut(random);
      std::sort(c, c + 3);
    } while (c[0] == c[1] || c[1] == c[2]);
    std::vector<int> t = targets();
    std::vector<int> kicked(t.begin(), t.begin() + c[0]);
    kicked.insert(kicked.end(), t.begin() + c[1], t.begin() + c[2]);
    kicked.insert(kicked.end(), t.begin() + c[0], t.begin() + c[1]);
    kicked.insert(kicked.end(), t.begin() + c[2], t.end());
    std::copy(kicked.begin(), kicked.end(), nodes_.begin() + 1);
    refresh();
  }

 private:
  // Cost between two nodes, and between the nodes at two positions of the walk.
  double leg(int from_node, int to_node) const { return (*costs_)(from_node, to_node); }
  double legAt(int from, int to) const { return leg(nodes_[from], nodes_[to]); }
  // Cost of walking positions i..j forwards, or backwards (j..i).
  double along(int i, int j) const { return forward_[j] - forward_[i]; }
  double against(int i, int j) const { return backward_[j] - backward_[i]; }
  double threshold() const { return kRelativeGain * std::max(1.0, cost()); }

  void refresh() {
    const int legs = static_cast<int>(nodes_.size()) - 1;
    forward_.assign(legs + 1, 0.0);
    backward_.assign(legs + 1, 0.0);
    for (int k = 0; k < legs; ++k) {
      forward_[k + 1] = forward_[k] + legAt(k, k + 1);
      backward_[k + 1] = backward_[k] + legAt(k + 1, k);
    }
  }

  // Reverses positions i..j (1 <= i < j <= n) if that lowers the cost.
  bool twoOpt() {
    const int n = static_cast<int>(nodes_.size()) - 2;
    for (int i = 1; i < n; ++i)
      for (int j = i + 1; j <= n; ++j) {
        const double before = legAt(i - 1, i) + along(i, j) + legAt(j, j + 1);
        const double after = legAt(i - 1, j) + against(i, j) + legAt(i, j + 1);
        if (after < before - threshold()) {
          std::reverse(nodes_.begin() + i, nodes_.begin() + j + 1);
          refresh();
          return true;
        }
      }
    return false;
  }

  // Moves a stretch of 1 to 3 targets (positions i..i+length-1) between two other neighbours,
  // in either direction, if that lowers the cost.
  bool orOpt() {
    const int n = static_cast<int>(nodes_.size()) - 2;
    for (int length = 1; length <= 3; ++length)
      for (int i = 1; i + length - 1 <= n; ++i) {
        const int last = i + length - 1;
        const int first_node = nodes_[i], last_node = nodes_[last];
        const double removal = legAt(i - 1, last + 1) - legAt(i - 1, i) - legAt(last, last + 1);
        for (int p = 0; p <= n; ++p) {
          if (p >= i - 1 && p <= last) continue;  // an edge touching the stretch: no move
          const int a = nodes_[p], b = nodes_[p + 1];
          const double gap = -leg(a, b);
          const double kept = removal + gap + leg(a, first_node) + leg(last_node, b);
          const double reversed = removal + gap + leg(a, last_node) + leg(first_node, b) +
                                  against(i, last) - along(i, last);
          const bool reverse = reversed < kept;
          if (std::min(kept, reversed) < -threshold()) {
            std::vector<int> stretch(nodes_.begin() + i, nodes_.begin() + last + 1);
            if (reverse) std::reverse(stretch.begin(), stretch.end());
            std::vector<int> moved;
            moved.reserve(nodes_.size());
            for (int k = 0; k < static_cast<int>(nodes_.size()); ++k) {
              if (k >= i && k <= last) continue;
              moved.push_back(nodes_[k]);
              if (k == p) moved.insert(moved.end(), stretch.begin(), stretch.end());
            }
            nodes_ = std::move(moved);
            refresh();
            return true;
          }
        }
      }
    return false;
  }

  const CostMatrix* costs_;
  std::vector<int> nodes_;
  std::vector<double> forward_;
  std::vector<double> backward_;
};

std::vector<int> nearestNeighbour(const CostMatrix& costs) {
  const int n = targetCount(costs);
  std::vector<bool> visited(n + 1, false);
  std::vector<int> order;
  int at = 0;
  for (int step = 0; step < n; ++step) {
    int best = -1;
    for (int j = 1; j <= n; ++j)
      if (!visited[j] && (best < 0 || costs(at, j) < costs(at, best))) best = j;
    visited[best] = true;
    order.push_back(best);
    at = best;
  }
  return order;
}

}  // namespace

void validateCostMatrix(const CostMatrix& costs) {
  if (costs.rows() < 1 || costs.rows() != costs.cols())
    throw ceilplan::InputError("the tour's cost matrix must be square with home at index 0, got " +
                                std::to_string(costs.rows()) + " x " + std::to_string(costs.cols()));
  for (Eigen::Index i = 0; i < costs.rows(); ++i)
    for (Eigen::Index j = 0; j < costs.cols(); ++j)
      if (!std::isfinite(costs(i, j)) || costs(i, j) < 0.0)
        throw ceilplan::InputError("tour cost from " + std::to_string(i) + " to " + std::to_string(j) +
                                    " must be finite and non-negative, got " + formatNumber(costs(i, j)));
}

double tourCost(const CostMatrix& costs, const std::vector<int>& targets) {
  double cost = 0.0;
  int at = 0;
  for (int target : targets) {
    cost += costs(at, target);
    at = target;
  }
  return cost + costs(at, 0);
}

TourOrder heldKarpTour(const CostMatrix& costs) {
  validateCostMatrix(costs);
  const int n = targetCount(costs);
  if (n > kHeldKarpMaxTargets)
    throw ceilplan::InputError("exact tour ordering (Held-Karp) takes at most " + std::to_string(kHeldKarpMaxTargets) +
                                " targets, got " + std::to_string(n) + ": use the heuristic");
  TourOrder result;
  result.method = "held-karp";
  if (n == 0) {
    result.cost = 0.0;
    return result;
  }
  // best[set][k]: cheapest walk from home through exactly the targets in `set`, ending at
  // target k + 1 (bit k of `set`).
  const std::size_t subsets = std::size_t{1} << n;
  const double infinity = std::numeric_limits<double>::infinity();
  std::vector<double> best(subsets * n, infinity);
  std::vector<signed char> previous(subsets * n, -1);
  for (int k = 0; k < n; ++k) best[(std::size_t{1} << k) * n + k] = costs(0, k + 1);
  for (std::size_t set = 1; set < subsets; ++set)
    for (int k = 0; k < n; ++k) {
      if (!(set & (std::size_t{1} << k))) continue;
      const double here = best[set * n + k];
      if (here == infinity) continue;
      for (int next = 0; next < n; ++next) {
        if (set & (std::size_t{1} << next)) continue;
        const std::size_t grown = set | (std::size_t{1} << next);
        const double candidate = here + costs(k + 1, next + 1);
        if (candidate < best[grown * n + next]) {
          best[grown * n + next] = candidate;
          previous[grown * n + next] = static_cast<signed char>(k);
        }
      }
    }
  const std::size_t all = subsets - 1;
  int last = 0;
  double cost = infinity;
  for (int k = 0; k < n; ++k) {
    const double candidate = best[all * n + k] + costs(k + 1, 0);
    if (candidate < cost) {
      cost = candidate;
      last = k;
    }
  }
  std::vector<int> order;
  for (std::size_t set = all; last >= 0;) {
    order.push_back(last + 1);
    const int before = previous[set * n + last];
    set &= ~(std::size_t{1} << last);
    last = before;
  }
  std::reverse(order.begin(), order.end());
  result.targets = std::move(order);
  result.cost = cost;
  return result;
}

TourOrder heuristicTour(const CostMatrix& costs, std::uint64_t seed, int restarts) {
  validateCostMatrix(costs);
  if (restarts < 0) throw ceilplan::InputError("the heuristic's restart count must be >= 0, got " + std::to_string(restarts));
  Walk best(costs, nearestNeighbour(costs));
  best.improve();
  std::mt19937_64 random(seed);
  for (int round = 0; round < restarts; ++round) {
    Walk trial = best;
    trial.kick(random);
    trial.improve();
    if (trial.cost() < best.cost()) best = trial;
  }
  TourOrder result;
  result.targets = best.targets();
  result.cost = tourCost(costs, result.targets);
  result.method = kHeuristicName;
  result.seed = seed;
  return result;
}

TourOrder orderTour(const CostMatrix& costs, const TourOrderOptions& options) {
  validateCostMatrix(costs);
  if (options.exact_max_targets > kHeldKarpMaxTargets)
    throw ceilplan::InputError("exact tour ordering (Held-Karp) takes at most " + std::to_string(kHeldKarpMaxTargets) +
                                " targets, asked for up to " + std::to_string(options.exact_max_targets));
  if (targetCount(costs) <= options.exact_max_targets) return heldKarpTour(costs);
  return heuristicTour(costs, options.seed, options.restarts);
}

}  // namespace ceilplan::mission
