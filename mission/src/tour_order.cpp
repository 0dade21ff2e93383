#include "ceilplan/mission/tour_order.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>

namespace ceilplan::mission {

namespace {

constexpr const char* kHeuristicName = "nearest-neighbour+2-opt+or-opt";
constexpr const char* kNeighbourListName = "neighbour-list 2-opt+or-opt";

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
          const double reversed =
              removal + gap + leg(a, last_node) + leg(first_node, b) + against(i, last) - along(i, last);
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

// The tour as a closed walk, as Walk, over lazily asked costs: moves join a place only to one
// of its neighbours, found by position in O(1).
class NeighbourWalk {
 public:
  NeighbourWalk(const PairCost& cost, const PairCost& bound, const std::vector<std::vector<int>>& neighbours,
                const std::vector<int>& targets)
      : cost_(&cost), bound_(&bound), neighbours_(&neighbours), position_(targets.size() + 1, 0) {
    nodes_.reserve(targets.size() + 2);
    nodes_.push_back(0);
    nodes_.insert(nodes_.end(), targets.begin(), targets.end());
    nodes_.push_back(0);
    refresh();
  }

  double cost() const { return forward_.back(); }
  std::vector<int> targets() const { return {nodes_.begin() + 1, nodes_.end() - 1}; }

  void improve() {
    while (sweep()) {
    }
  }

  // A double bridge A B C D -> A C B D with B and C within `window` positions each, near a
  // random position.
  void kick(std::mt19937_64& random, int window) {
    const int n = targetCount();
    if (n < 4) return;
    const int span = std::min(n, 3 * window);
    std::uniform_int_distribution<int> where(1, n - span + 1);
    std::uniform_int_distribution<int> cut(0, span);
    const int base = where(random);
    int c[3];
    do {
      for (int& value : c) value = cut(random);
      std::sort(c, c + 3);
    } while (c[0] == c[1] || c[1] == c[2]);
    const std::vector<int> before = nodes_;
    std::vector<int> part(nodes_.begin() + base + c[0], nodes_.begin() + base + c[2]);
    std::rotate(part.begin(), part.begin() + (c[1] - c[0]), part.end());
    std::copy(part.begin(), part.end(), nodes_.begin() + base + c[0]);
    relink(before);
  }

 private:
  int targetCount() const { return static_cast<int>(nodes_.size()) - 2; }
  double leg(int from_node, int to_node) const { return (*cost_)(from_node, to_node); }
  double lowest(int from_node, int to_node) const { return (*bound_)(from_node, to_node); }
  double legAt(int from, int to) const { return leg(nodes_[from], nodes_[to]); }
  double along(int i, int j) const { return forward_[j] - forward_[i]; }
  double against(int i, int j) const { return backward_[j] - backward_[i]; }
  double threshold() const { return kRelativeGain * std::max(1.0, cost()); }

  void refresh() {
    const int legs = static_cast<int>(nodes_.size()) - 1;
    out_.assign(legs, 0.0);
    back_.assign(legs, 0.0);
    for (int k = 0; k < legs; ++k) {
      out_[k] = legAt(k, k + 1);
      back_[k] = legAt(k + 1, k);
    }
    sumAndPlace();
  }

  // After a move turned `before` into nodes_: each leg's cost taken from the walk before where
  // it joined the same two places (either way), asked only for the new ones. A cost asked is
  // a map lookup through a std::function, and a large tour makes thousands of moves: asking
  // every leg again made the search grow with the square of the places. The sums are the same
  // to the bit (the same values added in the same order).
  void relink(const std::vector<int>& before) {
    const int legs = static_cast<int>(nodes_.size()) - 1;
    std::vector<double> out(legs), back(legs);
    for (int k = 0; k < legs; ++k) {
      const int from = nodes_[k], to = nodes_[k + 1];
      const int was = k == 0 ? 0 : position_[from];  // home leaves from position 0 only
      if (before[was + 1] == to) {
        out[k] = out_[was];
        back[k] = back_[was];
      } else if (was > 0 && before[was - 1] == to) {
        out[k] = back_[was - 1];
        back[k] = out_[was - 1];
      } else {
        out[k] = leg(from, to);
        back[k] = leg(to, from);
      }
    }
    out_ = std::move(out);
    back_ = std::move(back);
    sumAndPlace();
  }

  void sumAndPlace() {
    const int legs = static_cast<int>(nodes_.size()) - 1;
    forward_.assign(legs + 1, 0.0);
    backward_.assign(legs + 1, 0.0);
    for (int k = 0; k < legs; ++k) {
      forward_[k + 1] = forward_[k] + out_[k];
      backward_[k + 1] = backward_[k] + back_[k];
    }
    for (int k = 1; k <= targetCount(); ++k) position_[nodes_[k]] = k;
  }

  // Where a node stands in the walk: home at both ends.
  std::vector<int> positionsOf(int node) const {
    if (node == 0) return {0, targetCount() + 1};
    return {position_[node]};
  }

  // One pass over the positions, applying every improving move found; whether any was.
  bool sweep() {
    bool improved = false;
    for (int i = 1; i <= targetCount(); ++i) {
      while (twoOptAt(i) || orOptAt(i)) improved = true;
    }
    return improved;
  }

  // The exact price of a move whose legs are `legs` (`price` sums them with the cost it is
  // given), or none if it cannot gain: priced with bounds, then with its legs asked one at a
  // time, the others still at their bounds, until it cannot gain or every leg is asked. A leg
  // not known yet is estimated when asked, on the search's one thread, and most moves loose
  // bounds let through fail on their first exact leg. A price that cannot gain with bounds
  // cannot gain exactly (a sum never falls as a term rises), and the exact price is the sum
  // itself, so the search moves as it would pricing every leg of every such move exactly.
  template <class Price>
  std::optional<double> gainingPrice(const Price& price, const std::array<std::pair<int, int>, 3>& legs) const {
    std::array<double, 3> known;  // the bounds, then the costs of the legs asked
    for (std::size_t k = 0; k < legs.size(); ++k) known[k] = lowest(legs[k].first, legs[k].second);
    const auto cost = [&](int from, int to) {
      std::size_t k = 0;
      while (legs[k] != std::make_pair(from, to)) ++k;
      return known[k];
    };
    for (std::size_t asked = 0;; ++asked) {
      const double value = price(cost);
      if (value >= -threshold()) return std::nullopt;
      if (asked == legs.size()) return value;
      known[asked] = leg(legs[asked].first, legs[asked].second);
    }
  }

  // Reverses positions i..j (i < j <= n) where that joins nodes_[i - 1] or nodes_[i] to a neighbour.
  bool twoOptAt(int i) {
    const int n = targetCount();
    const auto tryMove = [&](int j) {
      if (j <= i || j > n) return false;
      const double before = out_[i - 1] + along(i, j) + out_[j];
      const int a = nodes_[i - 1], b = nodes_[i], c = nodes_[j], d = nodes_[j + 1];
      if (lowest(a, c) + against(i, j) + lowest(b, d) >= before - threshold()) return false;
      const double after = leg(a, c) + against(i, j) + leg(b, d);
      if (after >= before - threshold()) return false;
      const std::vector<int> walk = nodes_;
      std::reverse(nodes_.begin() + i, nodes_.begin() + j + 1);
      relink(walk);
      return true;
    };
    for (int c : (*neighbours_)[nodes_[i - 1]])  // new leg nodes_[i - 1] -> c
      for (int j : positionsOf(c))
        if (tryMove(j)) return true;
    for (int c : (*neighbours_)[nodes_[i]])  // new leg nodes_[i] -> c
      for (int q : positionsOf(c))
        if (tryMove(q - 1)) return true;
    return false;
  }

  // Moves the stretch starting at position i (1 to 3 targets) between two other neighbours
  // where one of them is a neighbour of its first or last target, in either direction.
  bool orOptAt(int i) {
    const int n = targetCount();
    for (int length = 1; length <= 3 && i + length - 1 <= n; ++length) {
      const int last = i + length - 1;
      const int first_node = nodes_[i], last_node = nodes_[last];
      const int before_node = nodes_[i - 1], after_node = nodes_[last + 1];
      const double cut = -out_[i - 1] - out_[last];
      const double turn = against(i, last) - along(i, last);
      // A single target's ends are one: its neighbours once.
      const std::array<int, 2> ends{first_node, last_node};
      for (int e = 0; e < (length == 1 ? 1 : 2); ++e)
        for (int c : (*neighbours_)[ends[e]])
          for (int q : positionsOf(c))
            for (int p : {q, q - 1}) {
              if (p < 0 || p > n || (p >= i - 1 && p <= last)) continue;  // an edge touching the stretch
              const int a = nodes_[p], b = nodes_[p + 1];
              // Closing the gap, opening a -> b, the stretch either way round; each way priced
              // exactly only as far as its bounds say it may gain (gainingPrice).
              const double opened = out_[p];
              const auto kept_price = [&](const auto& cost) {
                return cost(before_node, after_node) + cut - opened + cost(a, first_node) + cost(last_node, b);
              };
              const auto reversed_price = [&](const auto& cost) {
                return cost(before_node, after_node) + cut - opened + cost(a, last_node) + cost(first_node, b) + turn;
              };
              const auto kept =
                  gainingPrice(kept_price, {{{before_node, after_node}, {a, first_node}, {last_node, b}}});
              // A single target either way round is the same move, at the same price.
              const auto reversed =
                  length == 1
                      ? std::nullopt
                      : gainingPrice(reversed_price, {{{before_node, after_node}, {a, last_node}, {first_node, b}}});
              if (!kept && !reversed) continue;
              std::vector<int> stretch(nodes_.begin() + i, nodes_.begin() + last + 1);
              if (reversed && (!kept || *reversed < *kept)) std::reverse(stretch.begin(), stretch.end());
              std::vector<int> moved;
              moved.reserve(nodes_.size());
              for (int k = 0; k < static_cast<int>(nodes_.size()); ++k) {
                if (k >= i && k <= last) continue;
                moved.push_back(nodes_[k]);
                if (k == p) moved.insert(moved.end(), stretch.begin(), stretch.end());
              }
              std::swap(nodes_, moved);
              relink(moved);
              return true;
            }
    }
    return false;
  }

  const PairCost* cost_;
  const PairCost* bound_;
  const std::vector<std::vector<int>>* neighbours_;
  std::vector<int> nodes_;
  std::vector<int> position_;  // of each target in nodes_
  std::vector<double> out_;    // out_[k]: the leg nodes_[k] -> nodes_[k + 1]
  std::vector<double> back_;   // back_[k]: the leg nodes_[k + 1] -> nodes_[k]
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
    const int before = previous[set * n + last];  // NOLINT(bugprone-signed-char-misuse): -1 marks the first target
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
  if (restarts < 0)
    throw ceilplan::InputError("the heuristic's restart count must be >= 0, got " + std::to_string(restarts));
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

TourOrder neighbourListTour(int target_count, const PairCost& cost, const PairCost& bound,
                            const std::vector<std::vector<int>>& neighbours,
                            const std::vector<std::vector<int>>& starts, int kicks, std::uint64_t seed,
                            int kick_window) {
  if (target_count < 0) throw ceilplan::InputError("a tour cannot have a negative number of targets");
  if (static_cast<int>(neighbours.size()) != target_count + 1)
    throw ceilplan::InputError("neighbour lists for " + std::to_string(neighbours.size()) + " places, the tour has " +
                               std::to_string(target_count + 1));
  for (const std::vector<int>& list : neighbours)
    for (int place : list)
      if (place < 0 || place > target_count)
        throw ceilplan::InputError("neighbour " + std::to_string(place) + " is not a place 0.." +
                                   std::to_string(target_count));
  if (starts.empty()) throw ceilplan::InputError("the neighbour-list search needs at least one start order");
  TourOrder result;
  result.method = kNeighbourListName;
  result.cost = std::numeric_limits<double>::infinity();
  for (const std::vector<int>& start : starts) {
    std::vector<int> sorted = start;
    std::sort(sorted.begin(), sorted.end());
    bool listed = static_cast<int>(sorted.size()) == target_count;
    for (int k = 0; listed && k < target_count; ++k) listed = sorted[k] == k + 1;
    if (!listed)
      throw ceilplan::InputError("a start order must list every target 1.." + std::to_string(target_count) + " once");
    NeighbourWalk walk(cost, bound, neighbours, start);
    walk.improve();
    if (walk.cost() < result.cost) {
      result.cost = walk.cost();
      result.targets = walk.targets();
    }
  }
  if (kicks > 0) {
    if (kick_window < 1) throw ceilplan::InputError("the kick window must be at least 1 position");
    std::mt19937_64 random(seed);
    NeighbourWalk best(cost, bound, neighbours, result.targets);
    for (int round = 0; round < kicks; ++round) {
      NeighbourWalk trial = best;
      trial.kick(random, kick_window);
      trial.improve();
      if (trial.cost() < best.cost() - kRelativeGain * std::max(1.0, best.cost())) best = trial;
    }
    result.targets = best.targets();
    result.cost = best.cost();
    result.seed = seed;
  }
  return result;
}

std::vector<std::vector<int>> nearestPlaces(const std::vector<Eigen::Vector3d>& places_m, int k) {
  const int n = static_cast<int>(places_m.size());
  if (k < 1) throw ceilplan::InputError("the neighbour count must be at least 1, got " + std::to_string(k));
  std::vector<int> by_x(n);
  std::iota(by_x.begin(), by_x.end(), 0);
  std::sort(by_x.begin(), by_x.end(), [&](int a, int b) {
    return places_m[a].x() < places_m[b].x() || (places_m[a].x() == places_m[b].x() && a < b);
  });
  std::vector<int> rank(n);
  for (int r = 0; r < n; ++r) rank[by_x[r]] = r;
  std::vector<std::vector<int>> nearest(n);
  using Candidate = std::pair<double, int>;  // squared distance, place
  for (int p = 0; p < n; ++p) {
    std::vector<Candidate> best;  // a max-heap of the k nearest so far
    const auto consider = [&](int q) {
      const double d2 = (places_m[q] - places_m[p]).squaredNorm();
      if (static_cast<int>(best.size()) < k) {
        best.emplace_back(d2, q);
        std::push_heap(best.begin(), best.end());
      } else if (Candidate{d2, q} < best.front()) {
        std::pop_heap(best.begin(), best.end());
        best.back() = {d2, q};
        std::push_heap(best.begin(), best.end());
      }
    };
    const auto farEnough = [&](int q) {
      const double dx = places_m[q].x() - places_m[p].x();
      return static_cast<int>(best.size()) == k && dx * dx > best.front().first;
    };
    for (int r = rank[p] + 1; r < n && !farEnough(by_x[r]); ++r) consider(by_x[r]);
    for (int r = rank[p] - 1; r >= 0 && !farEnough(by_x[r]); --r) consider(by_x[r]);
    std::sort(best.begin(), best.end());
    for (const Candidate& c : best) nearest[p].push_back(c.second);
  }
  return nearest;
}

std::vector<int> nearestNeighbourOrder(const std::vector<Eigen::Vector3d>& places_m,
                                       const std::vector<std::vector<int>>& neighbours) {
  const int n = static_cast<int>(places_m.size()) - 1;
  std::vector<bool> visited(n + 1, false);
  visited[0] = true;
  std::vector<int> order;
  int at = 0;
  for (int step = 0; step < n; ++step) {
    int next = -1;
    for (int c : neighbours.at(at))
      if (!visited[c]) {
        next = c;
        break;
      }
    if (next < 0) {
      double nearest = std::numeric_limits<double>::infinity();
      for (int j = 1; j <= n; ++j) {
        const double d2 = (places_m[j] - places_m[at]).squaredNorm();
        if (!visited[j] && d2 < nearest) {
          nearest = d2;
          next = j;
        }
      }
    }
    visited[next] = true;
    order.push_back(next);
    at = next;
  }
  return order;
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
