#include "ceilplan/battery/duty_study.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <algorithm>
#include <cmath>

namespace ceilplan::battery {
namespace {

AgeingModelOptions ageingModelOptions(const DutyStudyOptions& options) {
  AgeingModelOptions model_options;
  model_options.conditions = OperatingConditions::fromCelsius(options.temperature_c);
  model_options.conditions.chemistry = options.chemistry;
  model_options.cell_voltage_of_soc = options.cell_voltage_of_soc;
  model_options.woehler = options.woehler;
  return model_options;
}

std::string caseLabel(double flight_current_a) { return formatFixed(flight_current_a, 2) + " A"; }

std::vector<DutyStudyAgeing> projectAgeing(const DutyStudyOptions& options, const DutyCycle& duty,
                                           double flight_current_a) {
  const AgeingModelOptions model_options = ageingModelOptions(options);
  std::vector<DutyStudyAgeing> results;
  for (const std::string& name : options.ageing_models) {
    LifetimeOptions lifetime;
    lifetime.study_days = options.studyDays();
    lifetime.end_of_life_soh = options.end_of_life_soh;
    lifetime.max_projection_days = std::max(lifetime.max_projection_days, lifetime.study_days);
    lifetime.step_s = options.step_s;
    if (options.progress) {
      const std::string stage = "ageing (" + name + ", " + caseLabel(flight_current_a) + ")";
      lifetime.progress = [&options, stage](double fraction) { options.progress(stage, fraction); };
    }
    DutyStudyAgeing result;
    const auto model = makeAgeingModel(name, model_options);
    result.projection = projectLifetime(options.pack, duty, *model, model_options.conditions, lifetime);

    lifetime.feed_back_fade = false;
    lifetime.max_projection_days = lifetime.study_days;
    lifetime.progress = nullptr;
    const auto new_pack_model = makeAgeingModel(name, model_options);
    result.new_pack = projectLifetime(options.pack, duty, *new_pack_model, model_options.conditions, lifetime);
    results.push_back(std::move(result));
  }
  return results;
}

// 100 (1 - other / first) of a per-day series at the end of day `days`, or nothing.
std::optional<double> reductionAtDay(const std::vector<double>& first, const std::vector<double>& other, int days) {
  if (days < 1 || first[days - 1] == 0.0) return std::nullopt;
  return 100.0 * (1.0 - other[days - 1] / first[days - 1]);
}

std::vector<double> fadeByDay(const LifetimeResult& projection) {
  std::vector<double> fade;
  for (double soh : projection.soh_by_day) fade.push_back(1.0 - soh);
  return fade;
}

void compareWithTheFirstCase(DutyStudyResult& result, std::size_t model_count) {
  const DutyStudyCase& first = result.cases.front();
  for (DutyStudyCase& c : result.cases) c.fec_reduction_pct = 100.0 * (1.0 - c.run.fecTotal() / first.run.fecTotal());
  for (std::size_t m = 0; m < model_count; ++m) {
    int days = first.ageing[m].projection.days_flown;
    for (const DutyStudyCase& c : result.cases) days = std::min(days, c.ageing[m].projection.days_flown);
    result.comparison_days.push_back(days);
    const DutyStudyAgeing& base = first.ageing[m];
    for (DutyStudyCase& c : result.cases) {
      DutyStudyAgeing& other = c.ageing[m];
      other.wear_reduction_pct =
          reductionAtDay(base.projection.cycle_wear_by_day, other.projection.cycle_wear_by_day, days);
      other.wear_reduction_new_pack_pct =
          reductionAtDay(base.new_pack.cycle_wear_by_day, other.new_pack.cycle_wear_by_day, days);
      other.fade_reduction_pct = reductionAtDay(fadeByDay(base.projection), fadeByDay(other.projection), days);
    }
  }
}

}  // namespace

int DutyStudyOptions::studyDays() const { return years > 0.0 ? static_cast<int>(std::lround(365.0 * years)) : days; }

std::string DutyStudyOptions::spanText() const {
  const int study_days = studyDays();
  const std::string text = std::to_string(study_days) + (study_days == 1 ? " day" : " days");
  return years > 0.0 ? text + " (" + formatNumber(years) + (years == 1.0 ? " year)" : " years)") : text;
}

MissionTemplate DutyStudyOptions::mission(double flight_current_a) const {
  return flyIdleChargeMission(flight_current_a, flight_s, idle_s, pack.charge_current_a, charge_max_s, soc_start);
}

DutyCycle DutyStudyOptions::dutyCycle(double flight_current_a) const {
  DutyCycle duty;
  duty.mission = mission(flight_current_a);
  duty.missions_per_day = missions_per_day;
  duty.days = studyDays();
  duty.initial_soc = soc_start;
  return duty;
}

double DutyStudyOptions::studyMissions() const { return static_cast<double>(missions_per_day) * studyDays(); }

double DutyStudyOptions::recordedRunSamples() const {
  // Each mission records its steps and a start and an end point per segment and for the rest to
  // its slot's end; each night its steps and a start and an end point.
  const DutyCycle duty = dutyCycle(flight_currents_a.empty() ? 0.0 : flight_currents_a.front());
  const double night_s = std::max(0.0, duty.day_s - missions_per_day * duty.mission.periodS());
  const double per_night = (step_s > 0.0 ? std::ceil(night_s / step_s) : 0.0) + 2.0;
  return studyMissions() * (stepsPerMission(duty.mission, step_s) + 2.0 * (duty.mission.segments.size() + 1)) +
         studyDays() * per_night;
}

void DutyStudyOptions::validate() const {
  pack.validate();
  if (flight_currents_a.empty()) throw InputError("a duty study needs at least one flight current");
  // Bounded before studyDays() turns them into a whole number of days.
  if (!(std::isfinite(years) && years >= 0.0 && years <= kMaxStudyDays / 365.0))
    throw InputError("the study's years must be a finite number in [0, " + formatNumber(kMaxStudyDays / 365.0) +
                     "], got " + formatNumber(years));
  if (studyDays() < 1 || studyDays() > kMaxStudyDays)
    throw InputError("a study of " + spanText() + " is outside 1 to " + std::to_string(kMaxStudyDays) + " days");
  if (!(step_s == 0.0 || (std::isfinite(step_s) && step_s > 0.0)))
    throw InputError("the time step must be 0 (exact) or a finite number of seconds > 0, got " + formatNumber(step_s));
  for (double flight_current_a : flight_currents_a) {
    if (!(std::isfinite(flight_current_a) && flight_current_a >= 0.0))
      throw InputError("flight current must be a finite number of amperes >= 0, got " + formatNumber(flight_current_a));
    dutyCycle(flight_current_a).validate();
  }
  const MissionTemplate one = mission(flight_currents_a.front());
  const double steps = stepsPerMission(one, step_s);
  if (steps > kMaxStepsPerMission)
    throw InputError("a time step of " + formatNumber(step_s) + " s cuts each " + formatNumber(one.periodS() / 60.0) +
                     "-min mission into " + formatNumber(steps) + " steps, over the " +
                     formatNumber(kMaxStepsPerMission) + " allowed: use a step of at least " +
                     formatNumber(one.periodS() / kMaxStepsPerMission, 3) + " s, or 0 (exact)");
  if (studyMissions() > kMaxStudyMissions)
    throw InputError(std::to_string(missions_per_day) + " missions a day over " + spanText() + " is " +
                     formatNumber(studyMissions()) + " missions, over the " + formatNumber(kMaxStudyMissions) +
                     " a study may hold");
  if (record_run && recordedRunSamples() > kMaxRecordedRunSamples)
    throw InputError("recording the whole run would keep " + formatNumber(recordedRunSamples(), 3) +
                     " samples per case, over the " + formatNumber(kMaxRecordedRunSamples) +
                     " allowed: use the exact scheme (step 0) or a shorter study");
  if (ageing_models.empty()) return;
  LifetimeOptions lifetime;
  lifetime.study_days = studyDays();
  lifetime.end_of_life_soh = end_of_life_soh;
  lifetime.validate();
  const AgeingModelOptions model_options = ageingModelOptions(*this);
  for (const std::string& name : ageing_models) makeAgeingModel(name, model_options);  // throws for bad options
}

DutyStudyResult runDutyStudy(const DutyStudyOptions& options) {
  options.validate();
  DutyStudyResult result;
  result.study_days = options.studyDays();
  for (double flight_current_a : options.flight_currents_a) {
    const DutyCycle duty = options.dutyCycle(flight_current_a);
    DutyOptions run_options;
    run_options.step_s = options.step_s;
    run_options.record_run = options.record_run;
    if (options.progress) {
      const std::string stage = "duty " + caseLabel(flight_current_a);
      run_options.progress = [&options, stage](double fraction) { options.progress(stage, fraction); };
    }
    DutyStudyCase study_case;
    study_case.flight_current_a = flight_current_a;
    try {
      study_case.run = simulateDuty(options.pack, duty, run_options);
    } catch (const DepletionError& e) {
      throw InfeasibleError("case " + caseLabel(flight_current_a) + ": " + e.what() +
                            "; fly less, charge longer or start fuller");
    }
    double start_soc = options.soc_start;
    for (const MissionTally& mission : study_case.run.missions) {
      study_case.max_dod = std::max(study_case.max_dod, start_soc - mission.min_soc);
      start_soc = mission.end_soc;  // the pack rests overnight without self-discharge
    }
    study_case.ageing = projectAgeing(options, duty, flight_current_a);
    result.cases.push_back(std::move(study_case));
  }
  compareWithTheFirstCase(result, options.ageing_models.size());
  return result;
}

}  // namespace ceilplan::battery
