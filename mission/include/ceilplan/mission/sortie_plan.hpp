#pragma once
/// @file
/// Splits a tour, in its fixed visiting order, into sorties: the vehicle returns home and the
/// pack is recharged (or swapped) to the start SOC before the SOC would fall below the reserve,
/// and the split points are chosen to wear the battery least under an ageing model. Cycle stress
/// is convex in depth of discharge under "xu" and "woehler", so several shallow sorties can wear
/// less than one deep one despite the extra transit; under "fec" wear follows charge alone.

#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/battery/pack.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/mission/battery_spec.hpp"
#include "ceilplan/mission/landing_confidence.hpp"
#include "ceilplan/mission/pair_table.hpp"
#include "ceilplan/mission/soc_integrator.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace ceilplan::mission {

/// What flying from one place to another costs the battery.
struct LegCost {
  /// Flown from the start SOC: what orders the tour.
  double charge_ah = 0.0;
  double duration_s = 0.0;      ///< flight time of the leg
  double mean_current_a = 0.0;  ///< charge / duration
  /// What the leg draws over [0, duration_s], turned into current at the SOC the sortie has
  /// reached there (TourCosts::current_at_soc). Empty: mean_current_a throughout, as a current.
  std::vector<LoadSample> load_profile;
  /// How the leg's charge moves with the calibrated parameters; empty: TourCosts has no uncertainty.
  ChargeSensitivity sensitivity;
};

/// Hovering at a target's viewpoint for its inspection.
struct Dwell {
  double duration_s = 0.0;        ///< hover time
  double current_a = 0.0;         ///< at the start SOC: what orders the tour
  std::optional<double> load;     ///< what hovering draws (current_at_soc); unset: current_a, as a current
  ChargeSensitivity sensitivity;  ///< as LegCost::sensitivity
};

/// Everything indexed like the tour's cost matrix: 0 is home, 1..N the targets.
struct TourCosts {
  std::vector<std::string> names;  ///< names[0] is home's, e.g. "home"
  /// legs[i][j]: flying from i to j. Only the legs a split can fly are needed: between
  /// neighbours in the order, and out of home and back where a sortie may start and end.
  PairTable<LegCost> legs;
  std::vector<Dwell> dwells;    ///< dwells[0] is ignored
  CurrentAtSoc current_at_soc;  ///< unset: loads are currents
  /// The calibration's uncertainty the sensitivities refer to: with BatterySpec::reserve_confidence,
  /// a sortie must land above the reserve with that probability (landing_confidence.hpp).
  std::optional<energy::FitUncertainty> uncertainty;

  /// Targets, home left out.
  int targetCount() const { return static_cast<int>(names.size()) - 1; }
  /// Throws ceilplan::InputError naming the first bad entry (sizes, NaN, negative values).
  void validate() const;
};

/// How planSorties splits the order: the ageing model it minimises and where sorties may start.
struct SortieOptions {
  std::string ageing_model = "xu";     ///< battery::ageingModelNames()
  battery::AgeingModelOptions ageing;  ///< the model's conditions and constants
  /// Positions in the order (0-based) where a sortie may start; 0 always may. Empty: every
  /// position. planTour spaces a large tour's by the sorties it needs (docs/tours.md, "Large
  /// tours").
  std::vector<int> split_points;
};

/// One leg of a sortie.
struct SortieLeg {
  int from = 0;             ///< matrix indices
  int to = 0;               ///< matrix index flown to
  double charge_ah = 0.0;   ///< charge drawn on the leg
  double duration_s = 0.0;  ///< flight time of the leg
};

/// A point of a sortie's SOC history: flight, then the recharge back to the start SOC.
struct SocSample {
  double t_s = 0.0;        ///< from the sortie's take-off
  double soc = 0.0;        ///< state of charge, 0..1
  double current_a = 0.0;  ///< positive discharging, negative charging
};

/// One flight from home and back: its targets, legs, charge, depth of discharge, wear and why it ends there.
struct Sortie {
  std::vector<int> targets;            ///< matrix indices in visiting order
  std::vector<SortieLeg> legs;         ///< home -> targets -> home
  double charge_ah = 0.0;              ///< legs and dwells
  double flight_s = 0.0;               ///< take-off to landing, dwells included
  double recharge_s = 0.0;             ///< back to the start SOC at the pack's charge current
  double turnaround_s = 0.0;           ///< landing to the next take-off: the recharge, or the pack swap
  double fec = 0.0;                    ///< the discharge and its recharge, against nominal capacity
  double dod = 0.0;                    ///< start SOC - lowest SOC
  double lowest_soc = 0.0;             ///< at landing (the SOC only falls in flight)
  double wear = 0.0;                   ///< the ageing model's cycle wear of this sortie, fresh pack
  std::string reason;                  ///< why it ends where it does, one sentence
  std::vector<SocSample> soc_history;  ///< leg and dwell boundaries, profile samples, recharge end
  ChargeSensitivity sensitivity;       ///< of its legs and dwells (with TourCosts::uncertainty)
  std::optional<LandingOdds> landing;  ///< the odds of landing above the reserve (with TourCosts::uncertainty)
  /// planTour's Monte Carlo check of `landing` over the flight record (TourOptions::landing_draws).
  std::optional<SampledLanding> sampled_landing;
};

/// A tour's sorties and their totals (planSorties).
struct SortiePlan {
  std::string ageing_model;      ///< the model the split minimises
  std::string wear_name;         ///< its cycle-wear measure, e.g. "Miner damage"
  std::vector<Sortie> sorties;   ///< in flying order
  double charge_ah = 0.0;        ///< charge drawn over all sorties
  double flight_s = 0.0;         ///< in the air, dwells included
  double duration_s = 0.0;       ///< first take-off to last landing: flights and the turnarounds between them
  double fec = 0.0;              ///< full equivalent cycles of all sorties and recharges
  double wear = 0.0;             ///< the model's cycle wear, summed over the sorties
  double min_soc = 1.0;          ///< lowest SOC at any landing
  double state_of_health = 1.0;  ///< of the pack that flies it
};

/// Chooses the sorties by dynamic programming over split points of `order` (matrix indices of
/// the targets in visiting order): O(P^2) candidate sorties for P split points, each priced by
/// feeding its SOC history (discharge, then recharge to the start SOC) to a fresh ageing model;
/// a candidate whose legs and dwells alone, at the start SOC, already use more than the charge
/// between the start SOC and the reserve is skipped unflown. Ties go to fewer sorties. Throws
/// ceilplan::InputError for bad input, and ceilplan::InfeasibleError naming every target that no
/// single sortie can reach, inspect and return from above the reserve (with split points: every
/// target of a stretch between two of them that no sortie can fly).
SortiePlan planSorties(const TourCosts& legs, const std::vector<int>& order, const BatterySpec& battery,
                       const SortieOptions& options = {});

/// How a candidate sortie of the split ends: whether it lands above the reserve, and its wear.
struct SortieEnding {
  bool lands = false;        ///< lands above the reserve (and with BatterySpec::reserve_confidence's odds)
  double landing_soc = 0.0;  ///< the SOC it lands at, as flySortie gives it
  double wear = 0.0;         ///< the ranking's cycle wear from the sortie's SOC turning points, when it lands
};

/// The candidate sorties a split with split points has flown home, kept for another split of the
/// same legs, order, pack and options with other split points: a large tour splits each order
/// three times, each time with more points, the earlier ones among them (docs/tours.md, "Large
/// tours"), and a sortie between two positions both splits try is then looked up instead of
/// flown again, to the same plan. Keyed by positions only: clear() it before the legs, the order,
/// the pack or the options change.
class SortieMemo {
 public:
  /// The sortie flying positions `first` to `end` - 1 of the order, or null if not kept.
  const SortieEnding* find(int first, int end) const;
  /// Keeps how the sortie flying positions `first` to `end` - 1 ends.
  void store(int first, int end, const SortieEnding& ending);
  /// Forgets every sortie (and the count of reuses).
  void clear();
  /// Sorties kept.
  std::size_t size() const { return endings_.size(); }
  /// Sorties looked up instead of flown since the last clear().
  std::size_t reused() const { return reused_; }

 private:
  std::unordered_map<std::uint64_t, SortieEnding> endings_;
  mutable std::size_t reused_ = 0;
};

/// planSorties with split points, looking up in `memo` the candidate sorties an earlier split of
/// the same tour flew home and keeping the ones it flies; the same plan as planSorties.
SortiePlan planSorties(const TourCosts& legs, const std::vector<int>& order, const BatterySpec& battery,
                       const SortieOptions& options, SortieMemo& memo);

/// Where the stretches of `order` between consecutive `split_points` (as SortieOptions::split_points;
/// empty: every position) begin that no single sortie can fly alone, from home and back above the
/// reserve: planSorties refuses the tour while there are any. A stretch of several targets may fly
/// once split points divide it. Throws ceilplan::InputError as planSorties does.
std::vector<int> stretchesNoSortieFlies(const TourCosts& legs, const std::vector<int>& order,
                                        const BatterySpec& battery, const std::vector<int>& split_points);

/// One sortie flying `targets` (matrix indices, in order) from home and back, its wear left 0
/// and its reason empty: for pricing a sortie chosen by hand.
Sortie flySortie(const TourCosts& legs, const std::vector<int>& targets, const BatterySpec& battery);

/// Wear of a plan under any model, so one split can be reported under every model: one new pack
/// flies the sorties back to back, recharged to the start SOC after each.
struct PlanWear {
  std::string model;           ///< the ageing model's name
  std::string wear_name;       ///< its cycle-wear measure, e.g. "Miner damage"
  double cycle_wear = 0.0;     ///< the model's cycle wear (equal to the sum over the sorties)
  double capacity_loss = 0.0;  ///< fraction of nominal capacity lost, calendar ageing included
};
/// The wear of `plan` under `model` (battery::ageingModelNames()).
PlanWear planWear(const SortiePlan& plan, const std::string& model, const battery::AgeingModelOptions& options = {});

}  // namespace ceilplan::mission
