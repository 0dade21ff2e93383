#include "ceilplan/mission/view_selection.hpp"

#include "ceilplan/core/parallel_for.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>

namespace ceilplan::mission {
namespace {

class LocalImprovement {
 public:
  LocalImprovement(const CandidateViews& views, const std::vector<double>& cost, std::vector<std::uint8_t>& chosen,
                   std::size_t element_count, bool tiling_only_allowed)
      : views_(views),
        cost_(cost),
        chosen_(chosen),
        count_(element_count, 0),
        chosen_of_(element_count),
        tiling_only_allowed_(tiling_only_allowed) {
    for (std::uint32_t v = 0; v < views.size(); ++v)
      if (chosen_[v]) choose(v, true);
  }

  // Drops chosen views whose every element another chosen view covers, dearest first.
  std::size_t removeRedundant() {
    std::size_t removed = 0;
    for (const std::uint32_t v : chosenByCost())
      if (redundant(v)) {
        choose(v, false);
        ++removed;
      }
    return removed;
  }

  // Exchanges: adds an unchosen view where the chosen views it makes redundant (dearest first)
  // cost more than it does, and drops them. One pass over the candidates in index order.
  std::size_t exchange() {
    std::size_t moves = 0;
    std::vector<std::uint8_t> marked(views_.size(), 0);
    std::vector<std::uint32_t> neighbours, dropped;
    for (std::uint32_t w = 0; w < views_.size(); ++w) {
      if (chosen_[w] || (!tiling_only_allowed_ && views_.tilingOnly(w))) continue;
      neighbours.clear();
      double neighbours_cost = 0.0;
      for (ElementIterator s = views_.begin(w); s != views_.end(w); ++s)
        for (const std::uint32_t v : chosen_of_[*s]) {
          if (marked[v]) continue;
          marked[v] = 1;
          neighbours.push_back(v);
          neighbours_cost += cost_[v];
        }
      for (const std::uint32_t v : neighbours) marked[v] = 0;
      if (neighbours_cost <= cost_[w]) continue;
      std::stable_sort(neighbours.begin(), neighbours.end(), [&](std::uint32_t a, std::uint32_t b) {
        return cost_[a] > cost_[b] || (cost_[a] == cost_[b] && a < b);
      });
      count(w, +1);
      dropped.clear();
      double saved = 0.0;
      for (const std::uint32_t v : neighbours)
        if (redundant(v)) {
          count(v, -1);
          dropped.push_back(v);
          saved += cost_[v];
        }
      for (const std::uint32_t v : dropped) count(v, +1);
      count(w, -1);
      if (saved > cost_[w] * (1.0 + 1e-12)) {
        choose(w, true);
        for (const std::uint32_t v : dropped) choose(v, false);
        ++moves;
      }
    }
    return moves;
  }

 private:
  // How many chosen views cover each element, tentatively.
  void count(std::uint32_t v, int delta) {
    for (ElementIterator s = views_.begin(v); s != views_.end(v); ++s) count_[*s] += delta;
  }

  // Chooses or drops a view: counts and the per-element lists of chosen views.
  void choose(std::uint32_t v, bool chosen) {
    chosen_[v] = chosen ? 1 : 0;
    count(v, chosen ? +1 : -1);
    for (ElementIterator s = views_.begin(v); s != views_.end(v); ++s) {
      std::vector<std::uint32_t>& list = chosen_of_[*s];
      if (chosen) {
        list.push_back(v);
      } else {
        *std::find(list.begin(), list.end(), v) = list.back();
        list.pop_back();
      }
    }
  }

  std::vector<std::uint32_t> chosenByCost() const {
    std::vector<std::uint32_t> order;
    for (std::uint32_t v = 0; v < views_.size(); ++v)
      if (chosen_[v]) order.push_back(v);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return cost_[a] > cost_[b]; });
    return order;
  }

  // Whether every element of chosen view v is covered by another chosen view too.
  bool redundant(std::uint32_t v) const {
    for (ElementIterator s = views_.begin(v); s != views_.end(v); ++s)
      if (count_[*s] < 2) return false;
    return true;
  }

  const CandidateViews& views_;
  const std::vector<double>& cost_;
  std::vector<std::uint8_t>& chosen_;
  std::vector<int> count_;
  std::vector<std::vector<std::uint32_t>> chosen_of_;  // per element, the chosen views covering it
  bool tiling_only_allowed_;                           // whether views kept for the tilings may be added
};

}  // namespace

std::vector<ViewCost> viewCosts(const planner::FlightCostModel& model, const Camera& camera,
                                const CandidateViews& views, const ViewCostOptions& options) {
  if (!(std::isfinite(options.transit_speed_m_s) && options.transit_speed_m_s > 0.0))
    throw ceilplan::InputError("view costs: the transit speed must be positive");
  std::vector<ViewCost> costs(views.size());
  parallelFor(views.size(), options.workers, [&](std::size_t v) {
    const double area_m2 = views.summaries[v].area_m2, finest_gsd = views.summaries[v].finest_gsd_mm_px;
    ViewCost& cost = costs[v];
    const double spacing_m = std::sqrt(area_m2);
    cost.speed_m_s = std::min(options.transit_speed_m_s, camera.maxSpeedForBlur_m_s(finest_gsd));
    if (camera.capture == CaptureStyle::OnTheMove && camera.min_photo_interval_s > 0.0)
      cost.speed_m_s = std::min(cost.speed_m_s, spacing_m / camera.min_photo_interval_s);
    cost.stop_s = camera.stopPerPhoto_s();
    cost.transit_s = spacing_m / cost.speed_m_s;
    const planner::PointConditions conditions = model.conditionsAt(views.poses[v].body_m);
    cost.hover_current_a = model.currentA(conditions, model.hoverAt(conditions), model.options().planning_soc);
    cost.charge_ah = cost.hover_current_a * (cost.stop_s + cost.transit_s) / 3600.0;
  });
  return costs;
}

namespace {

// Greedy by cost per newly covered area from the views `start` (chosen first, whatever their
// ratio), then local improvement; the views kept for the tilings only when starting from them.
SetCoverResult greedyCover(const CandidateViews& views, const std::vector<double>& area,
                           const std::vector<double>& cost, const SetCoverOptions& options,
                           const std::vector<std::uint32_t>& start) {
  const bool tiling_only_allowed = !start.empty();
  SetCoverResult result;
  std::vector<std::uint8_t> covered(area.size(), 0), chosen(views.size(), 0);
  const auto take = [&](std::uint32_t v) {
    chosen[v] = 1;
    result.greedy_cost += cost[v];
    ++result.greedy_views;
    for (ElementIterator s = views.begin(v); s != views.end(v); ++s) covered[*s] = 1;
  };
  for (const std::uint32_t v : start) take(v);
  const auto gainOf = [&](std::uint32_t v) {
    double gain = 0.0;
    for (ElementIterator s = views.begin(v); s != views.end(v); ++s)
      if (!covered[*s]) gain += area[*s];
    return gain;
  };
  // Lazy greedy (Minoux 1978): a view's gain only falls as others are chosen, so a stale ratio
  // is a lower bound on its true ratio; re-evaluate the top until it stays on top.
  struct Entry {
    double ratio;  // cost per newly covered area
    std::uint32_t view;
    bool operator>(const Entry& other) const {
      return ratio > other.ratio || (ratio == other.ratio && view > other.view);
    }
  };
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (std::uint32_t v = 0; v < views.size(); ++v) {
    if (chosen[v] || (!tiling_only_allowed && views.tilingOnly(v))) continue;
    const double gain = gainOf(v);
    ++result.evaluations;
    if (gain > 0.0) queue.push({cost[v] / gain, v});
  }
  while (!queue.empty()) {
    const Entry top = queue.top();
    queue.pop();
    const double gain = gainOf(top.view);
    ++result.evaluations;
    if (gain <= 0.0) continue;
    const Entry fresh{cost[top.view] / gain, top.view};
    if (!queue.empty() && fresh > queue.top()) {
      queue.push(fresh);
      continue;
    }
    take(top.view);
  }

  LocalImprovement improve(views, cost, chosen, area.size(), tiling_only_allowed);
  for (int round = 0; round < options.improvement_rounds; ++round) {
    const std::size_t removed = improve.removeRedundant();
    const std::size_t exchanges = improve.exchange();
    result.removed += removed;
    result.exchanges += exchanges;
    if (removed == 0 && exchanges == 0) break;
  }
  result.removed += improve.removeRedundant();
  for (std::uint32_t v = 0; v < views.size(); ++v)
    if (chosen[v]) {
      result.chosen.push_back(v);
      result.cost += cost[v];
    }
  return result;
}

// Per flat patch, the views of its tiling of least cost per area covered (the area its views
// cover together, wherever it lies), ties to the first.
std::vector<std::uint32_t> cheapestTilings(const CandidateViews& views, const std::vector<double>& area,
                                           const std::vector<double>& cost) {
  std::vector<std::uint8_t> seen(area.size(), 0);
  std::map<std::uint32_t, std::pair<double, const Tiling*>> best;  // per patch: cost per area, tiling
  for (const Tiling& tiling : views.tilings) {
    double tiling_cost = 0.0, tiling_area = 0.0;
    for (const std::uint32_t v : tiling.views) {
      tiling_cost += cost[v];
      for (ElementIterator s = views.begin(v); s != views.end(v); ++s)
        if (!seen[*s]) {
          seen[*s] = 1;
          tiling_area += area[*s];
        }
    }
    for (const std::uint32_t v : tiling.views)
      for (ElementIterator s = views.begin(v); s != views.end(v); ++s) seen[*s] = 0;
    if (!(tiling_area > 0.0)) continue;
    const double ratio = tiling_cost / tiling_area;
    const auto found = best.find(tiling.patch);
    if (found == best.end() || ratio < found->second.first) best[tiling.patch] = {ratio, &tiling};
  }
  std::vector<std::uint32_t> start;
  for (const auto& entry : best)
    start.insert(start.end(), entry.second.second->views.begin(), entry.second.second->views.end());
  std::sort(start.begin(), start.end());
  start.erase(std::unique(start.begin(), start.end()), start.end());
  return start;
}

}  // namespace

SetCoverResult chooseViews(const CandidateViews& views, const std::vector<double>& area,
                           const std::vector<double>& cost, const SetCoverOptions& options) {
  if (cost.size() != views.size())
    throw ceilplan::InputError("view selection: " + std::to_string(cost.size()) + " costs for " +
                               std::to_string(views.size()) + " candidates");
  for (const double c : cost)
    if (!(std::isfinite(c) && c > 0.0))
      throw ceilplan::InputError("view selection: every cost must be positive and finite");
  for (const ElementRun& run : views.runs)
    if (static_cast<std::size_t>(run.first) + run.count > area.size())
      throw ceilplan::InputError("view selection: a candidate covers an unknown element");
  for (const Tiling& tiling : views.tilings)
    for (const std::uint32_t v : tiling.views)
      if (v >= views.size()) throw ceilplan::InputError("view selection: a tiling names an unknown candidate");
  if (!views.tiling_only.empty() && views.tiling_only.size() != views.size())
    throw ceilplan::InputError("view selection: " + std::to_string(views.tiling_only.size()) +
                               " tiling-only flags for " + std::to_string(views.size()) + " candidates");

  SetCoverResult result = greedyCover(views, area, cost, options, {});
  if (views.tilings.empty()) return result;
  // The greedy takes the single view of best ratio first, and the views around it then leave
  // slivers that cost whole photos; the cheapest tiling of every flat patch, completed by the
  // greedy, covers each patch as a survey would. The better cover is kept (below). The views
  // kept for the tilings only (the second image orientation's) join that cover alone, so the
  // first is the cover of the other candidates as it was without them.
  const std::vector<std::uint32_t> start = cheapestTilings(views, area, cost);
  SetCoverResult tiled = greedyCover(views, area, cost, options, start);
  tiled.evaluations += result.evaluations;
  // The first cover lacks what only the tilings' own views see, if anything: then it is no cover.
  const auto coveredArea = [&](const SetCoverResult& cover) {
    std::vector<std::uint8_t> covered(area.size(), 0);
    double total = 0.0;
    for (const std::uint32_t v : cover.chosen)
      for (ElementIterator s = views.begin(v); s != views.end(v); ++s)
        if (!covered[*s]) {
          covered[*s] = 1;
          total += area[*s];
        }
    return total;
  };
  // The tilings are there to save photos: their cover is kept when it takes fewer for less charge
  // (the estimate alone picked one more photo on the tunnel crown, whose tour then cost more).
  const bool fewer_for_less = tiled.chosen.size() < result.chosen.size() && tiled.cost < result.cost;
  if (!fewer_for_less && !(coveredArea(tiled) > coveredArea(result) * (1.0 + 1e-12))) {
    result.evaluations = tiled.evaluations;
    return result;
  }
  tiled.tiling_views = start.size();
  return tiled;
}

}  // namespace ceilplan::mission
