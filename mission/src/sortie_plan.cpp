#include "ceilplan/mission/sortie_plan.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace ceilplan::mission {

namespace {

constexpr double kSecondsPerHour = 3600.0;

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f %%", 100.0 * fraction);
  return text;
}

void requireFiniteNonNegative(double value, const std::string& what) {
  if (!std::isfinite(value) || value < 0.0)
    throw ceilplan::InputError(what + " must be finite and non-negative, got " + formatNumber(value));
}

// Flies a sortie with the SOC integrator the flight record uses (soc_integrator.hpp), so the
// split decides on the SOC the record will show; the wear comes later.
class SortieBuilder {
 public:
  SortieBuilder(const TourCosts& legs, const BatterySpec& battery) : legs_(legs), battery_(battery) {}

  // The sortie flying order[first..last] (inclusive).
  Sortie build(const std::vector<int>& order, int first, int last) const {
    Sortie sortie;
    sortie.targets.assign(order.begin() + first, order.begin() + last + 1);
    SocIntegrator flight(battery_.pack, battery_.start_soc, legs_.current_at_soc);
    std::vector<SocSample>& history = sortie.soc_history;
    history.push_back({0.0, battery_.start_soc, 0.0});
    // Each history point carries the current drawn from it on.
    const SampleVisitor record = [&](std::size_t k, double current_a) {
      if (k > 0) history.push_back({flight.time_s(), flight.soc(), 0.0});
      history.back().current_a = current_a;
    };
    // A leg without a load profile, or a dwell without a load, draws its mean current throughout.
    const auto constant = [&](double current_a, double duration_s) {
      history.back().current_a = current_a;
      flight.advance(duration_s, current_a);
      history.push_back({flight.time_s(), flight.soc(), 0.0});
    };
    int at = 0;
    auto fly = [&](int to) {
      const LegCost& leg = legs_.legs[at][to];
      const double charge0_ah = flight.chargeAh(), t0_s = flight.time_s();
      if (leg.load_profile.size() >= 2) {
        flyProfile(flight, leg.load_profile, record);
      } else {
        constant(leg.mean_current_a, leg.duration_s);
      }
      sortie.legs.push_back({at, to, flight.chargeAh() - charge0_ah, flight.time_s() - t0_s});
      at = to;
    };
    for (int target : sortie.targets) {
      fly(target);
      const Dwell& dwell = legs_.dwells[target];
      if (dwell.duration_s > 0.0) {
        if (dwell.load) {
          hover(flight, *dwell.load, dwell.duration_s, record);
        } else {
          constant(dwell.current_a, dwell.duration_s);
        }
      }
    }
    fly(0);
    const double used_ah = flight.chargeAh();
    sortie.charge_ah = used_ah;
    sortie.flight_s = flight.time_s();
    sortie.lowest_soc = flight.lowestSoc();
    sortie.dod = battery_.start_soc - sortie.lowest_soc;
    sortie.fec = used_ah / battery_.pack.capacity_ah;  // discharge + equal recharge, over 2 C_nom
    sortie.recharge_s = used_ah / battery_.pack.charge_current_a * kSecondsPerHour;
    sortie.turnaround_s = battery_.between_sorties == Turnaround::Swap ? battery_.swap_s : sortie.recharge_s;
    history.back().current_a = -battery_.pack.charge_current_a;
    history.push_back({sortie.flight_s + sortie.recharge_s, battery_.start_soc, -battery_.pack.charge_current_a});
    return sortie;
  }

 private:
  const TourCosts& legs_;
  const BatterySpec& battery_;
};

// Feeds a sortie's history to `model`, its take-off at `start_s`.
void feed(battery::AgeingModel& model, const Sortie& sortie, double state_of_health, double start_s = 0.0) {
  std::vector<battery::AgeingSample> samples;
  samples.reserve(sortie.soc_history.size());
  for (const SocSample& s : sortie.soc_history)
    samples.push_back({start_s + s.t_s, std::clamp(s.soc, 0.0, 1.0), s.current_a, state_of_health});
  model.addSamples(samples);
}

double wearOf(const battery::AgeingModel& prototype, const Sortie& sortie, double state_of_health) {
  std::unique_ptr<battery::AgeingModel> model = prototype.clone();
  feed(*model, sortie, state_of_health);
  return model->cycleWear();
}

std::string targetList(const TourCosts& legs, const std::vector<int>& targets) {
  std::string text;
  for (int target : targets) text += (text.empty() ? "'" : ", '") + legs.names[target] + "'";
  return text;
}

// Why a sortie ends before `next`: one sortie flying both (`merged`) would break the reserve,
// or would wear more than the two.
std::string splitReason(const TourCosts& legs, const BatterySpec& battery, const battery::AgeingModel& prototype,
                        const Sortie& sortie, const Sortie& next, const Sortie& merged, bool merged_feasible) {
  const std::string head = "split after '" + legs.names[sortie.targets.back()] + "': ";
  if (!merged_feasible)
    return head + "one sortie on through '" + legs.names[next.targets.back()] + "' would land at " +
           percent(merged.lowest_soc) + " SOC, below the " + percent(battery.reserve_soc) + " reserve";
  const double soh = battery.pack.state_of_health;
  const double two = wearOf(prototype, sortie, soh) + wearOf(prototype, next, soh);
  const double one = wearOf(prototype, merged, soh);
  char saving[64];
  std::snprintf(saving, sizeof saving, "%.0f %% less", one > 0.0 ? 100.0 * (one - two) / one : 0.0);
  char transit[64];
  std::snprintf(transit, sizeof transit, "%.2f Ah", sortie.charge_ah + next.charge_ah - merged.charge_ah);
  return head + "two sorties of " + percent(sortie.dod) + " and " + percent(next.dod) + " DoD wear " +
         (two < one ? std::string(saving) : "no more") + " than one of " + percent(merged.dod) + " under " +
         prototype.name() + ", for " + transit + " of extra transit";
}

}  // namespace

void TourCosts::validate() const {
  const std::size_t n = names.size();
  if (n < 1) throw ceilplan::InputError("a tour needs home at index 0");
  if (legs.size() != n || dwells.size() != n)
    throw ceilplan::InputError("a tour of " + std::to_string(n) + " places needs " + std::to_string(n) + " x " +
                                std::to_string(n) + " legs and " + std::to_string(n) + " dwells");
  for (std::size_t i = 0; i < n; ++i) {
    if (legs[i].size() != n)
      throw ceilplan::InputError("legs from '" + names[i] + "' list " + std::to_string(legs[i].size()) +
                                  " destinations, expected " + std::to_string(n));
    for (std::size_t j = 0; j < n; ++j) {
      if (i == j) continue;
      const std::string what = "leg '" + names[i] + "' -> '" + names[j] + "'";
      requireFiniteNonNegative(legs[i][j].charge_ah, what + " charge (Ah)");
      requireFiniteNonNegative(legs[i][j].duration_s, what + " duration (s)");
      requireFiniteNonNegative(legs[i][j].mean_current_a, what + " mean current (A)");
      const auto& profile = legs[i][j].load_profile;
      for (std::size_t k = 0; k < profile.size(); ++k) {
        if (!std::isfinite(profile[k].load)) throw ceilplan::InputError(what + " profile load must be finite");
        if (!std::isfinite(profile[k].t_s) || (k > 0 && profile[k].t_s < profile[k - 1].t_s))
          throw ceilplan::InputError(what + " profile times must be finite and increasing");
      }
    }
    if (i > 0) {
      requireFiniteNonNegative(dwells[i].duration_s, "dwell time (s) at '" + names[i] + "'");
      requireFiniteNonNegative(dwells[i].current_a, "dwell current (A) at '" + names[i] + "'");
      if (dwells[i].load && !std::isfinite(*dwells[i].load))
        throw ceilplan::InputError("dwell load at '" + names[i] + "' must be finite");
    }
  }
}

SortiePlan planSorties(const TourCosts& legs, const std::vector<int>& order, const BatterySpec& battery,
                       const SortieOptions& options) {
  legs.validate();
  battery.validate();
  const int n = static_cast<int>(order.size());
  if (n != legs.targetCount())
    throw ceilplan::InputError("the visiting order lists " + std::to_string(n) + " targets, the tour has " +
                                std::to_string(legs.targetCount()));
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (int k = 0; k < n; ++k)
    if (sorted[k] != k + 1)
      throw ceilplan::InputError("the visiting order must list every target 1.." + std::to_string(n) + " exactly once");
  const std::unique_ptr<battery::AgeingModel> prototype = battery::makeAgeingModel(options.ageing_model, options.ageing);
  const SortieBuilder builder(legs, battery);
  const double reserve_tolerance = 1e-12;
  auto feasible = [&](const Sortie& sortie) { return sortie.lowest_soc >= battery.reserve_soc - reserve_tolerance; };

  std::vector<int> unreachable;
  for (int k = 0; k < n; ++k)
    if (!feasible(builder.build(order, k, k))) unreachable.push_back(order[k]);
  if (!unreachable.empty()) {
    const Sortie alone = builder.build(unreachable, 0, 0);
    throw ceilplan::InfeasibleError("no single sortie can reach, inspect and return from " + targetList(legs, unreachable) +
                                " above the " + percent(battery.reserve_soc) + " reserve (home -> '" +
                                legs.names[unreachable.front()] + "' -> home lands at " + percent(alone.lowest_soc) +
                                "); move home closer or use a larger pack");
  }

  // best[j]: least total wear covering order[0..j-1]; ties broken by fewer sorties.
  struct Best {
    double wear = std::numeric_limits<double>::infinity();
    int sorties = 0;
    int split = -1;  // the last sortie flies order[split..j-1]
  };
  std::vector<Best> best(n + 1);
  best[0].wear = 0.0;
  for (int j = 1; j <= n; ++j)
    for (int i = 0; i < j; ++i) {
      const Sortie sortie = builder.build(order, i, j - 1);
      if (!feasible(sortie)) continue;
      const double wear = best[i].wear + wearOf(*prototype, sortie, battery.pack.state_of_health);
      const int sorties = best[i].sorties + 1;
      const bool first = best[j].split < 0;
      const double tie = first ? 0.0 : 1e-12 * std::max(std::fabs(wear), std::fabs(best[j].wear));
      if (first || wear < best[j].wear - tie || (wear <= best[j].wear + tie && sorties < best[j].sorties))
        best[j] = {wear, sorties, i};
    }

  std::vector<int> starts;
  for (int j = n; j > 0; j = best[j].split) starts.push_back(best[j].split);
  std::reverse(starts.begin(), starts.end());
  starts.push_back(n);

  SortiePlan plan;
  plan.ageing_model = prototype->name();
  plan.wear_name = prototype->cycleWearName();
  plan.state_of_health = battery.pack.state_of_health;
  for (std::size_t s = 0; s + 1 < starts.size(); ++s) {
    Sortie sortie = builder.build(order, starts[s], starts[s + 1] - 1);
    sortie.wear = wearOf(*prototype, sortie, battery.pack.state_of_health);
    if (s + 2 < starts.size()) {
      const Sortie next = builder.build(order, starts[s + 1], starts[s + 2] - 1);
      const Sortie merged = builder.build(order, starts[s], starts[s + 2] - 1);
      sortie.reason = splitReason(legs, battery, *prototype, sortie, next, merged, feasible(merged));
    } else {
      sortie.reason = std::string(starts.size() == 2 ? "one sortie flies the whole tour" : "last sortie") +
                      ": lands at " + percent(sortie.lowest_soc) + " SOC, above the " +
                      percent(battery.reserve_soc) + " reserve";
    }
    plan.charge_ah += sortie.charge_ah;
    plan.flight_s += sortie.flight_s;
    plan.duration_s += sortie.flight_s + (s + 2 < starts.size() ? sortie.turnaround_s : 0.0);
    plan.fec += sortie.fec;
    plan.wear += sortie.wear;
    plan.min_soc = std::min(plan.min_soc, sortie.lowest_soc);
    plan.sorties.push_back(std::move(sortie));
  }
  return plan;
}

Sortie flySortie(const TourCosts& legs, const std::vector<int>& targets, const BatterySpec& battery) {
  legs.validate();
  battery.validate();
  for (int target : targets)
    if (target < 1 || target > legs.targetCount())
      throw ceilplan::InputError("target index " + std::to_string(target) + " is not in 1.." +
                                  std::to_string(legs.targetCount()));
  return SortieBuilder(legs, battery).build(targets, 0, static_cast<int>(targets.size()) - 1);
}

PlanWear planWear(const SortiePlan& plan, const std::string& model, const battery::AgeingModelOptions& options) {
  const std::unique_ptr<battery::AgeingModel> prototype = battery::makeAgeingModel(model, options);
  PlanWear wear;
  wear.model = prototype->name();
  wear.wear_name = prototype->cycleWearName();
  const std::unique_ptr<battery::AgeingModel> pack = prototype->clone();
  double start_s = 0.0;
  for (const Sortie& sortie : plan.sorties) {
    feed(*pack, sortie, plan.state_of_health, start_s);
    start_s += sortie.soc_history.back().t_s;
  }
  wear.cycle_wear = pack->cycleWear();
  wear.capacity_loss = pack->capacityLoss();
  return wear;
}

}  // namespace ceilplan::mission
