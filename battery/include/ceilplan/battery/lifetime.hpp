#pragma once
/// @file
/// Lifetime projection: a duty cycle run with an ageing model whose capacity fade is fed back
/// into the pack (paper eq. 7 with SOH < 1), so late-life missions go deeper, until the pack
/// reaches end of life.

#include "ceilplan/battery/ageing_model.hpp"
#include "ceilplan/battery/duty_cycle.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::battery {

/// How projectLifetime runs a model over a duty cycle until end of life.
struct LifetimeOptions {
  int study_days = 30;              ///< wear and fade are reported at the end of this period
  double end_of_life_soh = 0.8;     ///< the usual data-sheet end of life
  int max_projection_days = 36500;  ///< the projection gives up after this (100 years)
  double step_s = 0.0;              ///< 0 = exact
  /// false: the pack keeps its SOH whatever the model says (as Xu et al. 2018 derive their
  /// figures, and the paper's SOH = 1); the wear is still counted.
  bool feed_back_fade = true;
  std::function<void(double fraction)> progress;  ///< optional: the share of the projection done

  /// Throws ceilplan::InputError naming the first field out of range.
  void validate() const;
};

/// Figures "over the study period" cover the days the pack flew of it: all of them, unless the
/// faded pack gave out before the study ended (then `days_flown` < study days).
struct LifetimeResult {
  std::string model;            ///< the ageing model's name
  std::string cycle_wear_name;  ///< what `cycle_wear` measures
  double cycle_wear = 0.0;      ///< the model's cycle-ageing measure over the study period
  double capacity_loss = 0.0;   ///< fraction of nominal capacity lost over the study period
  double fec = 0.0;             ///< FEC over the study period (against nominal capacity)
  /// The same throughput counted against the faded pack's usable capacity (sum |dSOC| / 2):
  /// larger than the FEC once the pack has faded.
  double faded_pack_cycles = 0.0;
  double min_soc = 1.0;  ///< lowest SOC over the study period
  int days_flown = 0;    ///< whole days of the study period flown
  /// First mission whose end finds SOH <= end_of_life_soh: its 1-based number and the time from
  /// the first take-off to its end, in days. Empty if end of life was not reached.
  std::optional<long> missions_to_end_of_life;
  std::optional<double> days_to_end_of_life;  ///< days from the first take-off to that mission's end
  /// Why the projection stopped short of end of life, if it did (empty otherwise).
  std::string stopped_because;
  std::vector<double> soh_by_day;  ///< SOH at the end of each projected day
  /// The model's cycle wear at the end of each projected day, so that cases that stopped on
  /// different days can be compared over the same span.
  std::vector<double> cycle_wear_by_day;
  std::vector<std::string> warnings;  ///< the study leaves the model's validity range
};

/// Runs `duty` (its `days` ignored) with `model` fed every mission's history. Goes on past the
/// study period until end of life, the projection limit, or a mission the faded pack can no
/// longer fly. `model` must be fresh; `conditions` are those the model was built with (for the
/// validity warnings).
LifetimeResult projectLifetime(const Pack& pack, const DutyCycle& duty, AgeingModel& model,
                               const OperatingConditions& conditions, const LifetimeOptions& options);

}  // namespace ceilplan::battery
