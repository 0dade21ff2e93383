#include "ceilplan/battery/lifetime.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <algorithm>
#include <stdexcept>

namespace ceilplan::battery {

void LifetimeOptions::validate() const {
  if (study_days < 1) throw ceilplan::InputError("the study needs at least one day, got " + std::to_string(study_days));
  if (!(end_of_life_soh > 0.0 && end_of_life_soh < 1.0))
    throw ceilplan::InputError("end-of-life state of health must be in (0, 1), got " + formatNumber(end_of_life_soh));
  if (max_projection_days < study_days)
    throw ceilplan::InputError("the projection limit of " + std::to_string(max_projection_days) +
                               " days is shorter than the " + std::to_string(study_days) + "-day study");
}

LifetimeResult projectLifetime(const Pack& pack, const DutyCycle& duty, AgeingModel& model,
                               const OperatingConditions& conditions, const LifetimeOptions& options) {
  options.validate();
  LifetimeResult result;
  result.model = model.name();
  result.cycle_wear_name = model.cycleWearName();

  DutyCycle projection = duty;
  projection.days = options.max_projection_days;
  const long study_missions = static_cast<long>(options.study_days) * duty.missions_per_day;
  // The SOH the pack is left with when a model's loss reaches 1 (a law extrapolated past a dead
  // cell): small but positive, so the next mission fails as a depletion, not as bad input.
  constexpr double kDeadPackSoh = 1e-3;

  std::vector<AgeingSample> history;
  DutyOptions run_options;
  run_options.step_s = options.step_s;
  run_options.record_missions = false;
  run_options.record_first_day = false;
  double fec_so_far = 0.0;
  double faded_pack_cycles_so_far = 0.0;
  run_options.on_mission = [&](const MissionTally& mission, const std::vector<Sample>& samples) {
    history.clear();
    for (const Sample& s : samples) history.push_back({s.t_s, s.soc, s.current_a, mission.state_of_health});
    model.addSamples(history);
    const double soh = 1.0 - model.capacityLoss();
    fec_so_far += mission.fec;
    faded_pack_cycles_so_far += mission.faded_pack_cycles;
    if (mission.index < study_missions) {
      result.min_soc = std::min(result.min_soc, mission.min_soc);
      if (mission.index + 1 == study_missions) {
        result.cycle_wear = model.cycleWear();
        result.capacity_loss = 1.0 - soh;
        result.fec = fec_so_far;
        result.faded_pack_cycles = faded_pack_cycles_so_far;
      }
    }
    if (!result.missions_to_end_of_life && soh <= options.end_of_life_soh) {
      result.missions_to_end_of_life = mission.index + 1;
      result.days_to_end_of_life = samples.back().t_s / 86400.0;
    }
    return options.feed_back_fade ? std::max(soh, kDeadPackSoh) : pack.state_of_health;
  };
  run_options.continue_after_day = [&](const DayTally& day) {
    result.soh_by_day.push_back(day.state_of_health);
    result.cycle_wear_by_day.push_back(model.cycleWear());
    if (options.progress) options.progress(std::min(1.0, (day.day + 1.0) / options.study_days));
    return day.day + 1 < options.study_days || !result.missions_to_end_of_life;
  };

  try {
    simulateDuty(pack, projection, run_options);
    if (!result.missions_to_end_of_life)
      result.stopped_because =
          "end of life not reached within " + std::to_string(options.max_projection_days) + " days";
  } catch (const DepletionError& e) {
    if (static_cast<long>(result.soh_by_day.size()) < options.study_days) {
      // The study itself cannot be flown: report what was reached.
      result.cycle_wear = model.cycleWear();
      result.capacity_loss = std::min(1.0, model.capacityLoss());
      result.fec = fec_so_far;
      result.faded_pack_cycles = faded_pack_cycles_so_far;
    }
    result.stopped_because = std::string("the faded pack can no longer fly the mission: ") + e.what();
  }
  result.days_flown = static_cast<int>(std::min<std::size_t>(result.soh_by_day.size(), options.study_days));
  result.warnings = validityWarnings(model, conditions, pack.capacity_ah);
  return result;
}

}  // namespace ceilplan::battery
