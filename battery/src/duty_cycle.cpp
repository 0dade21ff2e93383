#include "ceilplan/battery/duty_cycle.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace ceilplan::battery {
namespace {

double totalDurationS(const LoadProfile& segments) {
  return std::accumulate(segments.begin(), segments.end(), 0.0,
                         [](double sum, const Segment& s) { return sum + s.duration_s; });
}

}  // namespace

double MissionTemplate::periodS() const { return period_s > 0.0 ? period_s : totalDurationS(segments); }

void MissionTemplate::validate() const {
  if (segments.empty()) throw ceilplan::InputError("a mission needs at least one segment");
  for (const Segment& segment : segments) segment.validate();
  if (!(std::isfinite(period_s) && period_s >= 0.0))
    throw ceilplan::InputError("mission period must be >= 0 s, got " + formatNumber(period_s));
  if (period_s > 0.0 && period_s < totalDurationS(segments))
    throw ceilplan::InputError("mission period of " + formatNumber(period_s) + " s is shorter than its segments' " +
                               formatNumber(totalDurationS(segments)) + " s");
}

MissionTemplate flyIdleChargeMission(double flight_current_a, double flight_s, double idle_s, double charge_current_a,
                                     double charge_max_s, double target_soc) {
  MissionTemplate mission;
  mission.segments = {Segment::discharge(flight_current_a, flight_s), Segment::idle(idle_s),
                      Segment::charge(charge_current_a, charge_max_s, target_soc)};
  return mission;
}

void DutyCycle::validate() const {
  mission.validate();
  if (missions_per_day < 1)
    throw ceilplan::InputError("missions per day must be at least 1, got " + std::to_string(missions_per_day));
  if (days < 1) throw ceilplan::InputError("days must be at least 1, got " + std::to_string(days));
  if (!(initial_soc > 0.0 && initial_soc <= 1.0))
    throw ceilplan::InputError("start SOC must be in (0, 1], got " + formatNumber(initial_soc));
  if (missions_per_day * mission.periodS() > day_s)
    throw ceilplan::InputError(std::to_string(missions_per_day) + " missions of " +
                               formatNumber(mission.periodS() / 60.0) + " min do not fit in a day");
}

double stepsPerMission(const MissionTemplate& mission, double step_s) {
  return step_s > 0.0 ? std::ceil(mission.periodS() / step_s) : 0.0;
}

double DutyResult::fecPerMission() const { return missions_flown == 0 ? 0.0 : fecTotal() / missions_flown; }

double DutyResult::fecPerDay() const { return days.empty() ? 0.0 : fecTotal() / days.size(); }

DutyResult simulateDuty(const Pack& pack, const DutyCycle& duty, const DutyOptions& options) {
  duty.validate();
  if (stepsPerMission(duty.mission, options.step_s) > kMaxStepsPerMission)
    throw ceilplan::InputError("a time step of " + formatNumber(options.step_s) + " s cuts each " +
                               formatNumber(duty.mission.periodS() / 60.0) + "-min mission into " +
                               formatNumber(stepsPerMission(duty.mission, options.step_s)) + " steps, over the " +
                               formatNumber(kMaxStepsPerMission) + " allowed: use a step of at least " +
                               formatNumber(duty.mission.periodS() / kMaxStepsPerMission) + " s, or 0 (exact)");
  Simulator simulator(pack, duty.initial_soc, options.step_s);
  DutyResult result;
  if (options.record_missions) result.missions.reserve(static_cast<size_t>(duty.missions_per_day) * duty.days);
  result.days.reserve(duty.days);
  const double period_s = duty.mission.periodS();
  std::vector<Sample> mission_samples;

  for (int day = 0; day < duty.days; ++day) {
    const double day_start_s = day * duty.day_s;
    DayTally day_tally{day, 0.0, simulator.state().soc, 0.0, simulator.pack().state_of_health};
    for (int m = 0; m < duty.missions_per_day; ++m) {
      const BatteryState before = simulator.state();
      MissionTally tally;
      tally.index = static_cast<long>(day) * duty.missions_per_day + m;
      tally.day = day;
      tally.mission_in_day = m;
      tally.start_s = day_start_s + m * period_s;
      tally.state_of_health = simulator.pack().state_of_health;
      tally.min_soc = before.soc;
      mission_samples.clear();
      try {
        for (const Segment& segment : duty.mission.segments) {
          simulator.run(segment, &mission_samples);
          tally.min_soc = std::min(tally.min_soc, simulator.state().soc);
          if (segment.mode == Mode::Charge) tally.charge_end_s = simulator.state().t_s - tally.start_s;
        }
        const double rest_s = tally.start_s + period_s - simulator.state().t_s;
        if (rest_s > 0.0) simulator.run(Segment::idle(rest_s), &mission_samples);
      } catch (const DepletionError& e) {
        throw DepletionError("mission " + std::to_string(m + 1) + " of day " + std::to_string(day + 1) + " (mission " +
                                 std::to_string(tally.index + 1) + " of the run) " + e.what(),
                             e.reachedSoc(), e.floorSoc());
      }
      const BatteryState& after = simulator.state();
      tally.discharge_ah = after.discharge_ah - before.discharge_ah;
      tally.charge_ah = after.charge_ah - before.charge_ah;
      tally.fec = after.fec_continuous - before.fec_continuous;
      tally.faded_pack_cycles = after.faded_pack_cycles - before.faded_pack_cycles;
      tally.end_soc = after.soc;
      day_tally.fec += tally.fec;
      day_tally.min_soc = std::min(day_tally.min_soc, tally.min_soc);
      if (options.on_mission) simulator.setStateOfHealth(options.on_mission(tally, mission_samples));
      if (options.record_first_day && tally.index == 0) result.first_mission = mission_samples;
      if (options.record_first_day && day == 0)
        result.first_day.insert(result.first_day.end(), mission_samples.begin(), mission_samples.end());
      if (options.record_run) result.run.insert(result.run.end(), mission_samples.begin(), mission_samples.end());
      if (options.record_missions) result.missions.push_back(tally);
      ++result.missions_flown;
    }
    // Overnight rest to the next day's start.
    const double rest_s = day_start_s + duty.day_s - simulator.state().t_s;
    simulator.run(Segment::idle(rest_s), options.record_run ? &result.run : nullptr);
    day_tally.end_soc = simulator.state().soc;
    day_tally.state_of_health = simulator.pack().state_of_health;
    result.days.push_back(day_tally);
    if (options.progress) options.progress(static_cast<double>(day + 1) / duty.days);
    if (options.continue_after_day && !options.continue_after_day(day_tally)) break;
  }
  simulator.closeModeInterval();
  result.final_state = simulator.state();
  return result;
}

}  // namespace ceilplan::battery
