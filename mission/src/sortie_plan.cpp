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

// "the 25 % reserve", or "the 25 % reserve with probability 0.99".
std::string reserveText(const BatterySpec& battery) {
  return "the " + percent(battery.reserve_soc) + " reserve" +
         (battery.reserve_confidence ? " with probability " + formatNumber(*battery.reserve_confidence) : "");
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

  SocIntegrator takeoff() const { return SocIntegrator(battery_.pack, battery_.start_soc, legs_.current_at_soc); }

  // Flies the leg from `from` to `to`, and the dwell at a target; `history` (when given) gains a
  // point per sample, each carrying the current drawn from it on; `sensitivity` (when given, with
  // the tour's uncertainty) gains the leg's or the dwell's.
  void flyLeg(SocIntegrator& flight, int from, int to, std::vector<SocSample>* history = nullptr,
              ChargeSensitivity* sensitivity = nullptr) const {
    const LegCost* found = &leg(from, to);
    const double before_ah = flight.chargeAh();
    if (found->load_profile.size() >= 2) {
      flyProfile(flight, found->load_profile, recorder(flight, history));
    } else {
      constant(flight, found->mean_current_a, found->duration_s, history);
    }
    addSensitivity(sensitivity, found->sensitivity, flight.chargeAh() - before_ah, found->charge_ah);
  }
  // A sortie of the split turning home at `from` (its last target) before position `end`.
  struct HomeFlight {
    SocIntegrator flight;
    ChargeSensitivity sensitivity;
    int from = 0;
    int end = 0;
  };

  // Flies each of `flights` home as flyLeg would, four at a time, interleaved sample by sample.
  // A flight is a chain of dependent steps (each current is the one at the SOC the step before
  // left), and the split flies tens of millions of such steps home; chains side by side let the
  // processor overlap them. Each flight's own arithmetic is flyLeg's, to the bit.
  void flyHome(std::vector<HomeFlight>& flights) const {
    constexpr std::size_t kLanes = 4;
    for (std::size_t first = 0; first < flights.size(); first += kLanes) {
      const std::size_t lanes = std::min(kLanes, flights.size() - first);
      HomeFlight* lane[kLanes];
      const LegCost* home[kLanes];
      double before_ah[kLanes];
      double previous_a[kLanes];
      std::size_t longest = 0;
      for (std::size_t j = 0; j < lanes; ++j) {
        lane[j] = &flights[first + j];
        home[j] = &leg(lane[j]->from, 0);
        before_ah[j] = lane[j]->flight.chargeAh();
        if (home[j]->load_profile.size() >= 2) {
          previous_a[j] = lane[j]->flight.currentFor(home[j]->load_profile.front().load);
          longest = std::max(longest, home[j]->load_profile.size());
        } else {
          constant(lane[j]->flight, home[j]->mean_current_a, home[j]->duration_s, nullptr);
        }
      }
      for (std::size_t k = 1; k < longest; ++k)
        for (std::size_t j = 0; j < lanes; ++j) {
          const std::vector<LoadSample>& profile = home[j]->load_profile;
          if (k >= profile.size()) continue;
          SocIntegrator& flight = lane[j]->flight;
          const double current_a = flight.currentFor(profile[k].load);
          flight.advance(profile[k].t_s - profile[k - 1].t_s, 0.5 * (previous_a[j] + current_a));
          previous_a[j] = current_a;
        }
      for (std::size_t j = 0; j < lanes; ++j)
        addSensitivity(&lane[j]->sensitivity, home[j]->sensitivity, lane[j]->flight.chargeAh() - before_ah[j],
                       home[j]->charge_ah);
    }
  }

  void dwellAt(SocIntegrator& flight, int target, std::vector<SocSample>* history = nullptr,
               ChargeSensitivity* sensitivity = nullptr) const {
    const Dwell& dwell = legs_.dwells[target];
    if (dwell.duration_s <= 0.0) return;
    const double before_ah = flight.chargeAh();
    if (dwell.load) {
      hover(flight, *dwell.load, dwell.duration_s, recorder(flight, history));
    } else {
      constant(flight, dwell.current_a, dwell.duration_s, history);
    }
    const double start_a =
        dwell.load && legs_.current_at_soc ? legs_.current_at_soc(*dwell.load, battery_.start_soc) : dwell.current_a;
    addSensitivity(sensitivity, dwell.sensitivity, flight.chargeAh() - before_ah,
                   start_a * dwell.duration_s / kSecondsPerHour);
  }

  // The sortie flying order[first..last] (inclusive).
  Sortie build(const std::vector<int>& order, int first, int last) const {
    Sortie sortie;
    sortie.targets.assign(order.begin() + first, order.begin() + last + 1);
    SocIntegrator flight = takeoff();
    std::vector<SocSample>& history = sortie.soc_history;
    history.push_back({0.0, battery_.start_soc, 0.0});
    int at = 0;
    auto fly = [&](int to) {
      const double charge0_ah = flight.chargeAh(), t0_s = flight.time_s();
      flyLeg(flight, at, to, &history, &sortie.sensitivity);
      sortie.legs.push_back({at, to, flight.chargeAh() - charge0_ah, flight.time_s() - t0_s});
      at = to;
    };
    for (int target : sortie.targets) {
      fly(target);
      dwellAt(flight, target, &history, &sortie.sensitivity);
    }
    fly(0);
    const double used_ah = flight.chargeAh();
    sortie.charge_ah = used_ah;
    sortie.flight_s = flight.time_s();
    sortie.lowest_soc = flight.lowestSoc();
    sortie.dod = battery_.start_soc - sortie.lowest_soc;
    sortie.fec = battery::fullEquivalentCycles(2.0 * used_ah, battery_.pack.capacity_ah);  // and the equal recharge
    sortie.recharge_s = rechargeS(used_ah);
    sortie.turnaround_s = battery_.between_sorties == Turnaround::Swap ? battery_.swap_s : sortie.recharge_s;
    history.back().current_a = -battery_.pack.charge_current_a;
    history.push_back({sortie.flight_s + sortie.recharge_s, battery_.start_soc, -battery_.pack.charge_current_a});
    if (legs_.uncertainty)
      sortie.landing = landingOdds(sortie.lowest_soc, sortie.sensitivity, *legs_.uncertainty,
                                   battery_.pack.usableCapacityAh(), battery_.reserve_soc);
    return sortie;
  }

  double rechargeS(double used_ah) const { return used_ah / battery_.pack.charge_current_a * kSecondsPerHour; }

 private:
  static SampleVisitor recorder(const SocIntegrator& flight, std::vector<SocSample>* history) {
    if (!history) return {};
    return [&flight, history](std::size_t k, double current_a) {
      if (k > 0) history->push_back({flight.time_s(), flight.soc(), 0.0});
      history->back().current_a = current_a;
    };
  }
  const LegCost& leg(int from, int to) const {
    const LegCost* found = legs_.legs.find(from, to);
    if (!found)
      throw ceilplan::InputError("the tour has no leg from '" + legs_.names[from] + "' to '" + legs_.names[to] +
                                 "' for a sortie to fly");
    return *found;
  }

  // A leg without a load profile, or a dwell without a load, draws its mean current throughout.
  static void constant(SocIntegrator& flight, double current_a, double duration_s, std::vector<SocSample>* history) {
    if (history) history->back().current_a = current_a;
    flight.advance(duration_s, current_a);
    if (history) history->push_back({flight.time_s(), flight.soc(), 0.0});
  }

  // The sensitivities are those of the charge drawn at the start SOC; lower in the sortie the
  // same power draws more current, and every term with it (landing_confidence.hpp).
  void addSensitivity(ChargeSensitivity* sum, const ChargeSensitivity& part, double flown_ah,
                      double start_soc_ah) const {
    if (sum && legs_.uncertainty) sum->add(part, start_soc_ah > 0.0 ? flown_ah / start_soc_ah : 1.0);
  }

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
           percent(merged.lowest_soc) + " SOC, " + (battery.reserve_confidence ? "short of " : "below ") +
           reserveText(battery);
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

// Gust charges, where there are any, at every gust point and finite (landing_confidence.hpp).
void requireGustCharges(const ChargeSensitivity& sensitivity, const std::string& what) {
  const std::vector<double>& gusts = sensitivity.gust_charge_ah;
  if (!gusts.empty() && gusts.size() != static_cast<std::size_t>(kGustPoints))
    throw ceilplan::InputError(what + " has " + std::to_string(gusts.size()) + " gust charges, not 0 or " +
                               std::to_string(kGustPoints));
  if (!std::all_of(gusts.begin(), gusts.end(), [](double q) { return std::isfinite(q); }))
    throw ceilplan::InputError(what + " gust charges must be finite");
}

}  // namespace

void TourCosts::validate() const {
  const std::size_t n = names.size();
  if (n < 1) throw ceilplan::InputError("a tour needs home at index 0");
  if (static_cast<std::size_t>(legs.placeCount()) != n || dwells.size() != n)
    throw ceilplan::InputError("a tour of " + std::to_string(n) + " places needs legs between " + std::to_string(n) +
                               " places and " + std::to_string(n) + " dwells");
  for (std::size_t i = 0; i < n; ++i) {
    for (const auto& [j, leg] : legs.row(static_cast<int>(i))) {
      if (static_cast<std::size_t>(j) == i) continue;  // a place to itself is never flown
      if (j < 0 || static_cast<std::size_t>(j) >= n)
        throw ceilplan::InputError("a leg from '" + names[i] + "' leads to place " + std::to_string(j) +
                                   ", not one of the " + std::to_string(n) + " others");
      const std::string what = "leg '" + names[i] + "' -> '" + names[j] + "'";
      requireFiniteNonNegative(leg.charge_ah, what + " charge (Ah)");
      requireFiniteNonNegative(leg.duration_s, what + " duration (s)");
      requireFiniteNonNegative(leg.mean_current_a, what + " mean current (A)");
      requireGustCharges(leg.sensitivity, what);
      const auto& profile = leg.load_profile;
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
      requireGustCharges(dwells[i].sensitivity, "dwell at '" + names[i] + "'");
    }
  }
}

namespace {

// The best way found to fly order[0..split position - 1]; ties broken by fewer sorties.
struct Best {
  double wear = std::numeric_limits<double>::infinity();
  int sorties = 0;
  int split = -1;  // index of the last sortie's start
};

void offer(Best& best, const Best& before, double wear, int split) {
  const double total = before.wear + wear;
  const int sorties = before.sorties + 1;
  const bool first = best.split < 0;
  const double tie = first ? 0.0 : 1e-12 * std::max(std::fabs(total), std::fabs(best.wear));
  if (first || total < best.wear - tie || (total <= best.wear + tie && sorties < best.sorties))
    best = {total, sorties, split};
}

// Where the stretches between split points begin, sorted, 0 first (every position when there
// are none), then the order's end: stretch b is order[starts[b]..starts[b + 1] - 1].
std::vector<int> stretchStarts(const std::vector<int>& split_points, int n) {
  std::vector<int> starts;
  if (split_points.empty())
    for (int k = 0; k < n; ++k) starts.push_back(k);
  else
    starts.push_back(0);
  for (int p : split_points) {
    if (p < 0 || p >= std::max(n, 1))
      throw ceilplan::InputError("sortie split point " + std::to_string(p) + " is not a position in the order 0.." +
                                 std::to_string(n - 1));
    starts.push_back(p);
  }
  std::sort(starts.begin(), starts.end());
  starts.erase(std::unique(starts.begin(), starts.end()), starts.end());
  starts.push_back(n);
  return starts;
}

// The checks planSorties and stretchesNoSortieFlies make of their input.
void checkTour(const TourCosts& legs, const std::vector<int>& order, const BatterySpec& battery) {
  legs.validate();
  battery.validate();
  if (battery.reserve_confidence && !legs.uncertainty)
    throw ceilplan::InputError(
        "a reserve confidence needs the calibrated vehicle's uncertainty (its 'calibration:' block, written by "
        "ceilplan calibrate)");
  const int n = static_cast<int>(order.size());
  if (n != legs.targetCount())
    throw ceilplan::InputError("the visiting order lists " + std::to_string(n) + " targets, the tour has " +
                               std::to_string(legs.targetCount()));
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (int k = 0; k < n; ++k)
    if (sorted[k] != k + 1)
      throw ceilplan::InputError("the visiting order must list every target 1.." + std::to_string(n) + " exactly once");
}

// At or above the reserve, but for rounding.
bool aboveReserve(const BatterySpec& battery, double soc) { return soc >= battery.reserve_soc - 1e-12; }

// The per-sortie feasibility test: the planned landing SOC above the reserve and, with a
// reserve confidence, above the effective reserve its uncertainty asks for (landing_confidence.hpp).
bool landsAboveReserve(const TourCosts& legs, const BatterySpec& battery, double landing_soc,
                       const ChargeSensitivity& sensitivity) {
  if (!aboveReserve(battery, landing_soc)) return false;
  if (!battery.reserve_confidence) return true;
  return meetsConfidence(landing_soc, *battery.reserve_confidence, sensitivity, *legs.uncertainty,
                         battery.pack.usableCapacityAh(), battery.reserve_soc);
}

bool landsAboveReserve(const TourCosts& legs, const BatterySpec& battery, const Sortie& sortie) {
  return landsAboveReserve(legs, battery, sortie.lowest_soc, sortie.sensitivity);
}

// Whether one sortie flies each stretch between `starts` (stretchStarts) alone.
std::vector<std::uint8_t> stretchesFly(const TourCosts& legs, const SortieBuilder& builder,
                                       const std::vector<int>& order, const std::vector<int>& starts,
                                       const BatterySpec& battery) {
  std::vector<std::uint8_t> flies(starts.size() - 1, 0);
  for (std::size_t b = 0; b + 1 < starts.size(); ++b)
    flies[b] = landsAboveReserve(legs, battery, builder.build(order, starts[b], starts[b + 1] - 1));
  return flies;
}

// Cycle wear of a sortie from its SOC turning points alone (take-off, landing, the end of the
// recharge, the flight at its mean current): within a flight the SOC only falls, so its rainflow
// cycle is the same; the large-tour split ranks candidates by it.
double turningPointWear(const battery::AgeingModel& prototype, const BatterySpec& battery, const SocIntegrator& flight,
                        double recharge_s, double state_of_health) {
  Sortie sortie;
  const double flight_s = flight.time_s();
  const double mean_a = flight_s > 0.0 ? flight.chargeAh() * kSecondsPerHour / flight_s : 0.0;
  sortie.soc_history = {{0.0, battery.start_soc, mean_a},
                        {flight_s, flight.soc(), -battery.pack.charge_current_a},
                        {flight_s + recharge_s, battery.start_soc, -battery.pack.charge_current_a}};
  return wearOf(prototype, sortie, state_of_health);
}

std::uint64_t memoKey(int first, int end) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(first)) << 32) | static_cast<std::uint32_t>(end);
}

SortiePlan splitOrder(const TourCosts& legs, const std::vector<int>& order, const BatterySpec& battery,
                      const SortieOptions& options, SortieMemo* memo) {
  checkTour(legs, order, battery);
  const int n = static_cast<int>(order.size());
  const std::unique_ptr<battery::AgeingModel> prototype =
      battery::makeAgeingModel(options.ageing_model, options.ageing);
  const SortieBuilder builder(legs, battery);
  const auto above = [&](double soc) { return aboveReserve(battery, soc); };
  auto feasible = [&](const Sortie& sortie) { return landsAboveReserve(legs, battery, sortie); };
  const double soh = battery.pack.state_of_health;

  // Sorties start at `starts` (every position by default); best[e] covers order[0..starts[e]-1].
  const bool every_position = options.split_points.empty();
  const std::vector<int> starts = stretchStarts(options.split_points, n);
  const int stretches = static_cast<int>(starts.size()) - 1;
  std::vector<Best> best(stretches + 1);
  best[0].wear = 0.0;
  const std::vector<std::uint8_t> stretch_flies = stretchesFly(legs, builder, order, starts, battery);

  if (every_position) {
    // Every candidate sortie flown in full and priced by its whole SOC history: O(N^2) sorties.
    if (std::all_of(stretch_flies.begin(), stretch_flies.end(), [](std::uint8_t f) { return f != 0; }))
      for (int e = 1; e <= stretches; ++e)
        for (int b = 0; b < e; ++b) {
          const Sortie sortie = builder.build(order, starts[b], starts[e] - 1);
          if (feasible(sortie)) offer(best[e], best[b], wearOf(*prototype, sortie, soh), b);
        }
  } else {
    // From each split point, fly on target by target; at each split point after it, the sortie
    // turns home on a copy of the flight. Once the SOC before turning home is below the reserve
    // no longer sortie can fly, so the search from that start ends: O(P x L) flying.
    std::vector<SortieBuilder::HomeFlight> homeward;
    for (int b = 0; b < stretches; ++b) {
      SocIntegrator flight = builder.takeoff();
      ChargeSensitivity sensitivity;
      int at = 0;
      const auto arrive = [&](int e, const SortieEnding& ending) {
        if (ending.lands && std::isfinite(best[b].wear)) offer(best[e], best[b], ending.wear, b);
      };
      homeward.clear();
      for (int e = b + 1; e <= stretches; ++e) {
        for (int p = starts[e - 1]; p < starts[e]; ++p) {
          builder.flyLeg(flight, at, order[p], nullptr, &sensitivity);
          builder.dwellAt(flight, order[p], nullptr, &sensitivity);
          at = order[p];
        }
        if (!above(flight.lowestSoc())) break;
        // The way home from here is most of the flying (it is as long as the sortie is far out):
        // a sortie an earlier split flew is looked up, the others fly home together below.
        if (const SortieEnding* kept = memo ? memo->find(starts[b], starts[e]) : nullptr) {
          arrive(e, *kept);
        } else {
          homeward.push_back({flight, sensitivity, at, e});
        }
      }
      builder.flyHome(homeward);
      for (const SortieBuilder::HomeFlight& home : homeward) {
        SortieEnding ending;
        ending.landing_soc = home.flight.lowestSoc();
        ending.lands = landsAboveReserve(legs, battery, ending.landing_soc, home.sensitivity);
        if (ending.lands)
          ending.wear =
              turningPointWear(*prototype, battery, home.flight, builder.rechargeS(home.flight.chargeAh()), soh);
        if (memo) memo->store(starts[b], starts[home.end], ending);
        arrive(home.end, ending);
      }
    }
  }

  std::vector<int> unreachable;
  int first_unreachable = -1;
  for (int b = stretches - 1; b >= 0; --b)
    if (!stretch_flies[b]) {
      unreachable.insert(unreachable.begin(), order.begin() + starts[b], order.begin() + starts[b + 1]);
      first_unreachable = b;
    }
  if (!unreachable.empty()) {
    const int first = starts[first_unreachable], last = starts[first_unreachable + 1] - 1;
    const Sortie alone = builder.build(order, first, last);
    throw ceilplan::InfeasibleError("no single sortie can reach, inspect and return from " +
                                    targetList(legs, unreachable) + " above " + reserveText(battery) + " (home -> '" +
                                    legs.names[order[first]] +
                                    (last > first ? "' ... '" + legs.names[order[last]] : "") + "' -> home lands at " +
                                    percent(alone.lowest_soc) + "); move home closer or use a larger pack");
  }

  std::vector<int> chosen;
  for (int e = stretches; e > 0; e = best[e].split) chosen.push_back(starts[best[e].split]);
  std::reverse(chosen.begin(), chosen.end());
  chosen.push_back(n);

  SortiePlan plan;
  plan.ageing_model = prototype->name();
  plan.wear_name = prototype->cycleWearName();
  plan.state_of_health = soh;
  for (std::size_t s = 0; s + 1 < chosen.size(); ++s) {
    Sortie sortie = builder.build(order, chosen[s], chosen[s + 1] - 1);
    sortie.wear = wearOf(*prototype, sortie, soh);
    if (s + 2 < chosen.size()) {
      const Sortie next = builder.build(order, chosen[s + 1], chosen[s + 2] - 1);
      const Sortie merged = builder.build(order, chosen[s], chosen[s + 2] - 1);
      sortie.reason = splitReason(legs, battery, *prototype, sortie, next, merged, feasible(merged));
    } else {
      sortie.reason = std::string(chosen.size() == 2 ? "one sortie flies the whole tour" : "last sortie") +
                      ": lands at " + percent(sortie.lowest_soc) + " SOC, above " + reserveText(battery);
    }
    plan.charge_ah += sortie.charge_ah;
    plan.flight_s += sortie.flight_s;
    plan.duration_s += sortie.flight_s + (s + 2 < chosen.size() ? sortie.turnaround_s : 0.0);
    plan.fec += sortie.fec;
    plan.wear += sortie.wear;
    plan.min_soc = std::min(plan.min_soc, sortie.lowest_soc);
    plan.sorties.push_back(std::move(sortie));
  }
  return plan;
}

}  // namespace

const SortieEnding* SortieMemo::find(int first, int end) const {
  const auto it = endings_.find(memoKey(first, end));
  if (it == endings_.end()) return nullptr;
  ++reused_;
  return &it->second;
}

void SortieMemo::store(int first, int end, const SortieEnding& ending) { endings_[memoKey(first, end)] = ending; }

void SortieMemo::clear() {
  endings_.clear();
  reused_ = 0;
}

SortiePlan planSorties(const TourCosts& legs, const std::vector<int>& order, const BatterySpec& battery,
                       const SortieOptions& options) {
  return splitOrder(legs, order, battery, options, nullptr);
}

SortiePlan planSorties(const TourCosts& legs, const std::vector<int>& order, const BatterySpec& battery,
                       const SortieOptions& options, SortieMemo& memo) {
  return splitOrder(legs, order, battery, options, &memo);
}

std::vector<int> stretchesNoSortieFlies(const TourCosts& legs, const std::vector<int>& order,
                                        const BatterySpec& battery, const std::vector<int>& split_points) {
  checkTour(legs, order, battery);
  const std::vector<int> starts = stretchStarts(split_points, static_cast<int>(order.size()));
  const std::vector<std::uint8_t> flies = stretchesFly(legs, SortieBuilder(legs, battery), order, starts, battery);
  std::vector<int> failing;
  for (std::size_t b = 0; b < flies.size(); ++b)
    if (!flies[b]) failing.push_back(starts[b]);
  return failing;
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
