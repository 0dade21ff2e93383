#pragma once
/// @file
/// A mission template (fly, idle, charge back) repeated N times a day for D days, as in the
/// founding paper's month-long study (Kocer et al. 2019; docs/battery.md).

#include "ceilplan/battery/load_profile.hpp"
#include "ceilplan/battery/pack.hpp"
#include "ceilplan/battery/simulation.hpp"

#include <functional>
#include <vector>

namespace ceilplan::battery {

/// One mission. Missions start every `period_s` (0: the sum of the segments' durations); when a
/// segment stops early (a charge that reached its target) the battery idles to the slot's end.
struct MissionTemplate {
  LoadProfile segments;   ///< the mission's load, in order
  double period_s = 0.0;  ///< slot length, s; 0: the sum of the segments' durations

  /// The slot length, s: period_s, or the segments' total duration when period_s is 0.
  double periodS() const;
  /// Throws ceilplan::InputError for an empty profile, a bad segment or a period shorter than the segments.
  void validate() const;
};

/// The paper's mission: fly at `flight_current_a` for `flight_s`, idle for `idle_s`, then charge
/// at `charge_current_a` until SOC >= `target_soc` for at most `charge_max_s`.
MissionTemplate flyIdleChargeMission(double flight_current_a, double flight_s, double idle_s, double charge_current_a,
                                     double charge_max_s, double target_soc);

/// The most steps the fixed-step scheme may take per mission. Finer steps only cost time and
/// memory: the exact scheme (step 0) is exact, and the paper's 30 s take 90 steps a mission.
inline constexpr double kMaxStepsPerMission = 10000.0;

/// Steps the fixed-step scheme takes over one mission slot at `step_s`; 0 for the exact scheme.
double stepsPerMission(const MissionTemplate& mission, double step_s);

/// Missions flown every day for a number of days, from a starting SOC (runDutyCycle).
struct DutyCycle {
  MissionTemplate mission;    ///< what each mission does
  int missions_per_day = 15;  ///< missions started each day
  int days = 30;              ///< days run
  double day_s = 86400.0;     ///< missions start at the beginning of each day; the pack rests overnight
  double initial_soc = 0.95;  ///< no self-discharge (paper)

  /// Throws ceilplan::InputError for a bad mission, counts out of range or missions that do not fit in a day.
  void validate() const;
};

/// The figures of one mission of a duty run.
struct MissionTally {
  long index = 0;                  ///< 0-based over the whole run
  int day = 0;                     ///< 0-based
  int mission_in_day = 0;          ///< 0-based
  double start_s = 0.0;            ///< mission start, s from the run's start
  double fec = 0.0;                ///< this mission's FEC (its discharge and charge, against C_nom)
  double faded_pack_cycles = 0.0;  ///< the same against the usable capacity C_nom * SOH
  double discharge_ah = 0.0;       ///< charge drawn, Ah
  double charge_ah = 0.0;          ///< charge put back, Ah
  double min_soc = 0.0;            ///< lowest SOC in the mission
  double end_soc = 0.0;            ///< SOC at the mission's end
  double charge_end_s = 0.0;       ///< end of its last charge, from the mission's start (0 if none)
  double state_of_health = 1.0;    ///< during this mission
};

/// The figures of one day of a duty run.
struct DayTally {
  int day = 0;                   ///< 0-based
  double fec = 0.0;              ///< the day's FEC, against C_nom
  double min_soc = 0.0;          ///< lowest SOC of the day
  double end_soc = 0.0;          ///< SOC at the day's end
  double state_of_health = 1.0;  ///< at the day's end
};

/// Called after every mission with its tally and its recorded samples; returns the state of
/// health for the missions that follow (capacity fade fed back, paper eq. 7).
using MissionHook = std::function<double(const MissionTally& mission, const std::vector<Sample>& samples)>;

/// How runDutyCycle integrates and what it records.
struct DutyOptions {
  double step_s = 0.0;                            ///< 0 = exact, event-driven
  bool record_missions = true;                    ///< keeps every mission's tally in DutyResult::missions
  bool record_first_day = true;                   ///< keeps samples of mission 1 and day 1
  bool record_run = false;                        ///< keeps samples of the whole run
  MissionHook on_mission;                         ///< optional
  std::function<void(double fraction)> progress;  ///< optional, called once a day
  /// Optional: called after every day; returning false ends the run there.
  std::function<bool(const DayTally& day)> continue_after_day;
};

/// What runDutyCycle returns: tallies, the final state and the recorded samples.
struct DutyResult {
  std::vector<MissionTally> missions;  ///< empty unless DutyOptions::record_missions
  long missions_flown = 0;             ///< missions flown (fewer than planned when continue_after_day stopped the run)
  std::vector<DayTally> days;          ///< one tally per day flown
  BatteryState final_state;            ///< the battery at the end of the run
  std::vector<Sample> first_mission;   ///< samples of the first mission (DutyOptions::record_first_day)
  std::vector<Sample> first_day;       ///< samples of the first day (DutyOptions::record_first_day)
  std::vector<Sample> run;             ///< samples of the whole run (DutyOptions::record_run)

  /// FEC over the run (discrete, paper eq. 3-5).
  double fecTotal() const { return final_state.fec; }
  double fecPerMission() const;  ///< mean over the run
  double fecPerDay() const;      ///< mean over the run
  /// Lowest SOC over the run.
  double minSoc() const { return final_state.min_soc; }
};

/// Runs the duty cycle. A mission that would cross the SOC floor throws DepletionError saying
/// which mission of which day and by how much. Throws ceilplan::InputError, before any work, for
/// a bad duty cycle or a step that cuts a mission into more than kMaxStepsPerMission steps.
DutyResult simulateDuty(const Pack& pack, const DutyCycle& duty, const DutyOptions& options = {});

}  // namespace ceilplan::battery
