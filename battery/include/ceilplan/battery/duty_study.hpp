#pragma once
/// @file
/// The founding paper's duty study (Kocer et al. 2019, arXiv 1812.11707; docs/battery.md): one
/// fly/idle/charge mission flown N times a day for D days at several flight currents, each case
/// projected with the ageing models, and every case compared with the first. The defaults are the
/// paper's (and `ceilplan duty`'s): 9.5 A in free flight against 8 A under the ceiling, 20 min of
/// flight, 5 min idle, at most 20 min of charge at 2C back to 95 %, 15 missions a day for 30 days,
/// 30 s steps.

#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/battery/duty_cycle.hpp"
#include "ceilplan/battery/lifetime.hpp"
#include "ceilplan/core/progress.hpp"

#include <optional>
#include <string>
#include <vector>

namespace ceilplan::battery {

/// Limits of a study, so that a typo cannot ask for unbounded time or memory.
inline constexpr int kMaxStudyDays = 36500;            ///< 100 years, the lifetime projection's own limit
inline constexpr double kMaxStudyMissions = 1e6;       ///< mission tallies kept per case (about 100 MB)
inline constexpr double kMaxRecordedRunSamples = 1e7;  ///< a case's whole-run series (about 500 MB)

/// The founding paper's duty study (`ceilplan duty`): one fly/idle/charge duty run per flight current, with ageing
/// projections.
struct DutyStudyOptions {
  Pack pack;  ///< the paper's 5.2 Ah pack; its charge_current_a (2C) is the missions' charger too
  std::vector<double> flight_currents_a{9.5, 8.0};  ///< one case each; the first is the baseline
  double flight_s = 1200.0;                         ///< flight per mission, s (the paper's 20 min)
  double idle_s = 300.0;                            ///< idle after the flight, s (the paper's 5 min)
  double charge_max_s = 1200.0;                     ///< longest charge per mission, s (the paper's 20 min)
  double soc_start = 0.95;                          ///< SOC at the first take-off, and the charge-back target
  int missions_per_day = 15;                        ///< missions started each day
  int days = 30;                                    ///< days studied, unless `years` is given
  double years = 0.0;                               ///< > 0 replaces `days` (365 days a year, rounded to whole days)
  double step_s = 30.0;                             ///< the paper's step; 0 = exact, event-driven
  std::vector<std::string> ageing_models = ageingModelNames();  ///< empty: no ageing projection
  double temperature_c = 25.0;                                  ///< cell temperature, Celsius
  std::string chemistry = "LiPo";                               ///< checked against each model's validity range
  double end_of_life_soh = 0.8;                                 ///< state of health taken as the end of life
  WoehlerParameters woehler;                                    ///< used by "fec" (N100) and "woehler" [open]
  /// The cell's open-circuit voltage, needed by "schmalstieg" (e.g. energy::LipoOpenCircuitVoltage).
  CellVoltageOfSoc cell_voltage_of_soc;
  bool record_run = false;  ///< keep each case's samples of the whole run (DutyResult::run)
  /// Optional; stages "duty 9.50 A" (the run) and "ageing (xu, 9.50 A)" (a projection).
  ProgressCallback progress;

  /// Days studied: `days`, or `years` in whole days.
  int studyDays() const;
  /// "30 days", or "1825 days (5 years)" when the study was given in years.
  std::string spanText() const;
  /// The fly/idle/charge mission and the duty cycle of one case.
  MissionTemplate mission(double flight_current_a) const;
  /// The duty cycle of the case flying at `flight_current_a`.
  DutyCycle dutyCycle(double flight_current_a) const;
  /// Missions each case flies, and the samples record_run keeps of each case's run.
  double studyMissions() const;
  /// Samples record_run keeps of each case's run.
  double recordedRunSamples() const;
  /// Throws ceilplan::InputError, in the library's terms, for anything out of range: the pack, a
  /// current, missions that do not fit in a day, a step or a study over the limits above, an
  /// unknown ageing model, a temperature or an end of life out of range.
  void validate() const;
};

/// One ageing model's view of one case.
struct DutyStudyAgeing {
  LifetimeResult projection;  ///< with the capacity fade fed back into the SOH
  LifetimeResult new_pack;    ///< with the pack held new over the study (Xu et al. 2018; the paper's SOH = 1)
  /// 100 (1 - this case / the first case) over the model's comparison days, of the cycle wear, of
  /// the cycle wear with the pack kept new, and of the capacity fade. Empty when some case flew
  /// no whole day or the first case's figure is 0.
  std::optional<double> wear_reduction_pct;
  std::optional<double> wear_reduction_new_pack_pct;  ///< reduction of the cycle wear with the pack kept new, %
  std::optional<double> fade_reduction_pct;           ///< reduction of the capacity fade, %
};

/// One flight current of a duty study: its run and each ageing model's projection.
struct DutyStudyCase {
  double flight_current_a = 0.0;        ///< the mission's flight current, A
  DutyResult run;                       ///< the duty cycle over the whole study, pack held new
  double max_dod = 0.0;                 ///< the deepest mission's start SOC minus its lowest
  double fec_reduction_pct = 0.0;       ///< 100 (1 - this FEC / the first case's)
  std::vector<DutyStudyAgeing> ageing;  ///< one per DutyStudyOptions::ageing_models, in order
};

/// What runDutyStudy returns: one case per flight current.
struct DutyStudyResult {
  int study_days = 0;                ///< days studied
  std::vector<DutyStudyCase> cases;  ///< one per flight current, in order
  /// Per ageing model: the whole days of the study every case flew (a faded pack that gives out
  /// stops its case early), over which the reductions compare.
  std::vector<int> comparison_days;
};

/// Runs the study. Throws ceilplan::InputError (before any work) for bad options, and
/// ceilplan::InfeasibleError naming the case when a mission would take the pack below empty.
DutyStudyResult runDutyStudy(const DutyStudyOptions& options);

}  // namespace ceilplan::battery
