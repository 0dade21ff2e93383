// `ceilplan duty`: a duty-cycle study; with no arguments, the founding paper's two cases.

#include "cli_checks.hpp"
#include "command_registry.hpp"
#include "output.hpp"

#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/battery/duty_cycle.hpp"
#include "ceilplan/battery/lifetime.hpp"
#include "ceilplan/energy/lipo_open_circuit_voltage.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace ceilplan::app {
namespace {

using battery::DutyResult;
using battery::Sample;

struct DutyArguments {
  double capacity_ah = 5.2;         // the paper's pack
  double charge_current_a = 10.4;   // 2C
  std::vector<double> flight_currents_a{9.5, 8.0};  // free flight, ceiling effect (paper)
  double flight_min = 20.0;
  double idle_min = 5.0;
  double charge_max_min = 20.0;
  double soc_start = 0.95;
  int missions_per_day = 15;
  int days = 30;
  double dt_s = 30.0;  // the paper's step; 0 = exact
  double years = 0.0;  // > 0 replaces days
  std::string model = "all";
  double temperature_c = 25.0;
  double end_of_life_soh = 0.8;
  std::string chemistry = "LiPo";
  double woehler_n100 = battery::WoehlerParameters{}.cycles_at_full_depth;
  double woehler_k = battery::WoehlerParameters{}.exponent;
  std::string json_path;
  std::string csv_dir;
};

// One ageing model's view of a case: with the fade fed back (the projection) and with the pack
// held new over the study period (as Xu et al. 2018 and the paper derive it, SOH = 1).
struct AgeingResult {
  battery::LifetimeResult projection;
  battery::LifetimeResult new_pack;
};

struct CaseResult {
  double flight_current_a;
  DutyResult run;
  std::vector<AgeingResult> ageing;  // one per model, in the order of modelNames()
};

int studyDays(const DutyArguments& args) {
  return args.years > 0.0 ? static_cast<int>(std::lround(365.0 * args.years)) : args.days;
}

// "30 days", or "1825 days (5 years)" when the study was given in years.
std::string studySpan(const DutyArguments& args) {
  const std::string days = std::to_string(studyDays(args)) + (studyDays(args) == 1 ? " day" : " days");
  return args.years > 0.0 ? days + " (" + formatNumber(args.years) + (args.years == 1.0 ? " year)" : " years)") : days;
}

std::vector<std::string> modelNames(const DutyArguments& args) {
  if (args.model == "none") return {};
  if (args.model == "all") return battery::ageingModelNames();
  return {args.model};
}


double reductionPct(const CaseResult& first, const CaseResult& other) {
  return 100.0 * (1.0 - other.run.fecTotal() / first.run.fecTotal());
}

// Model `m`'s cases compare over the same span: the whole days of the study every case flew
// (a faded pack that gives out stops its case early). 0 when some case flew no whole day.
int comparisonDays(const std::vector<CaseResult>& cases, std::size_t m) {
  int days = cases.front().ageing[m].projection.days_flown;
  for (const CaseResult& c : cases) days = std::min(days, c.ageing[m].projection.days_flown);
  return days;
}

// 100 (1 - other / first) of a per-day series at the end of day `days`, or nothing.
std::optional<double> reductionAtDay(const std::vector<double>& first, const std::vector<double>& other, int days) {
  if (days < 1 || first[days - 1] == 0.0) return std::nullopt;
  return 100.0 * (1.0 - other[days - 1] / first[days - 1]);
}

std::vector<double> fadeByDay(const battery::LifetimeResult& projection) {
  std::vector<double> fade;
  for (double soh : projection.soh_by_day) fade.push_back(1.0 - soh);
  return fade;
}

// The reductions of model `m` for case `c` against the first case, over `days` days.
struct Reductions {
  std::optional<double> wear, wear_new_pack, fade;
};

Reductions reductions(const CaseResult& first, const CaseResult& c, std::size_t m, int days) {
  const AgeingResult &base = first.ageing[m], &other = c.ageing[m];
  return {reductionAtDay(base.projection.cycle_wear_by_day, other.projection.cycle_wear_by_day, days),
          reductionAtDay(base.new_pack.cycle_wear_by_day, other.new_pack.cycle_wear_by_day, days),
          reductionAtDay(fadeByDay(base.projection), fadeByDay(other.projection), days)};
}

std::string percentCell(const std::optional<double>& value) { return value ? formatFixed(*value, 2) : "n/a"; }

void printTable(const DutyArguments& args, const std::vector<CaseResult>& cases) {
  std::cout << "Duty cycle: " << args.missions_per_day << " missions a day for " << studySpan(args)
            << "; each flies " << formatFixed(args.flight_min, 1) << " min, idles " << formatFixed(args.idle_min, 1)
            << " min, charges at " << formatFixed(args.charge_current_a, 2) << " A for at most "
            << formatFixed(args.charge_max_min, 1) << " min back to " << formatFixed(100 * args.soc_start, 1) << " % SOC; "
            << formatFixed(args.capacity_ah, 2) << " Ah pack; "
            << (args.dt_s > 0 ? formatFixed(args.dt_s, 1) + " s steps" : std::string("exact, event-driven")) << "\n\n";
  const auto row = [&](const std::string& label, const auto& cell) {
    std::cout << std::left << std::setw(32) << label;
    for (const CaseResult& c : cases) std::cout << std::right << std::setw(12) << cell(c);
    std::cout << '\n';
  };
  for (size_t i = 0; i < cases.size(); ++i) std::cout << (i == 0 ? std::string(32, ' ') : "") << std::right << std::setw(12) << "case " + std::to_string(i + 1);
  std::cout << '\n';
  row("flight current [A]", [](const CaseResult& c) { return formatFixed(c.flight_current_a, 2); });
  row("lowest SOC [%]", [](const CaseResult& c) { return formatFixed(100 * c.run.minSoc(), 1); });
  row("charge complete [min]", [](const CaseResult& c) { return formatFixed(c.run.missions.back().charge_end_s / 60, 2); });
  row("FEC per mission", [](const CaseResult& c) { return formatFixed(c.run.fecPerMission(), 4); });
  row("FEC per day", [](const CaseResult& c) { return formatFixed(c.run.fecPerDay(), 3); });
  row("FEC after " + studySpan(args).substr(0, studySpan(args).find(" (")),
      [](const CaseResult& c) { return formatFixed(c.run.fecTotal(), 2); });
  row("charge put back [Ah]", [](const CaseResult& c) { return formatFixed(c.run.final_state.charge_ah, 1); });
  row("FEC reduction vs first [%]", [&](const CaseResult& c) { return formatFixed(reductionPct(cases.front(), c), 2); });
  if (cases.front().ageing.empty()) return;

  const int study_days = studyDays(args);
  std::cout << "\nBattery ageing over " << studySpan(args) << " at " << formatFixed(args.temperature_c, 1)
            << " C, capacity fade fed back into the SOH; end of life at " << formatFixed(100 * args.end_of_life_soh, 0)
            << " % SOH\nFEC counts the charge moved against the nominal capacity, cycles of the faded pack against "
               "the faded one\n";
  for (size_t m = 0; m < cases.front().ageing.size(); ++m) {
    const auto& first = cases.front().ageing[m];
    const int days = comparisonDays(cases, m);
    std::cout << first.projection.model;
    if (days < study_days)
      std::cout << " (a faded pack gave out before the study's end: totals cover the days each case flew, "
                   "reductions the "
                << days << (cases.size() > 2 ? " days every case flew)" : " days both flew)");
    std::cout << ":\n";
    if (days < study_days)
      row("  days flown", [m](const CaseResult& c) { return std::to_string(c.ageing[m].projection.days_flown); });
    row("  " + first.projection.cycle_wear_name,
        [m](const CaseResult& c) { return formatNumber(c.ageing[m].projection.cycle_wear, 5); });
    row("  cycles of the faded pack",
        [m](const CaseResult& c) { return formatNumber(c.ageing[m].projection.faded_pack_cycles, 5); });
    row("  capacity fade [%]", [m](const CaseResult& c) { return formatFixed(100 * c.ageing[m].projection.capacity_loss, 2); });
    row("  days to end of life", [m](const CaseResult& c) {
      const auto& days_to_end = c.ageing[m].projection.days_to_end_of_life;
      return days_to_end ? formatFixed(*days_to_end, 1) : std::string("never*");
    });
    row("  wear reduction vs first [%]",
        [&](const CaseResult& c) { return percentCell(reductions(cases.front(), c, m, days).wear); });
    row("  ... with the pack kept new [%]",
        [&](const CaseResult& c) { return percentCell(reductions(cases.front(), c, m, days).wear_new_pack); });
  }
  for (const CaseResult& c : cases)
    for (const AgeingResult& a : c.ageing) {
      if (!a.projection.stopped_because.empty())
        std::cout << "* " << a.projection.model << ", " << formatFixed(c.flight_current_a, 2)
                  << " A: " << a.projection.stopped_because << '\n';
    }
  for (const AgeingResult& a : cases.front().ageing)
    for (const std::string& warning : a.projection.warnings) std::cout << "warning: " << warning << '\n';
}

nlohmann::json optionalJson(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

nlohmann::json ageingJson(const std::vector<CaseResult>& cases, const CaseResult& c) {
  nlohmann::json models = nlohmann::json::array();
  for (size_t m = 0; m < c.ageing.size(); ++m) {
    const battery::LifetimeResult& p = c.ageing[m].projection;
    const int days = comparisonDays(cases, m);
    const Reductions reduced = reductions(cases.front(), c, m, days);
    models.push_back(
        {{"model", p.model},
         {"cycle_wear_name", p.cycle_wear_name},
         {"cycle_wear", p.cycle_wear},
         {"cycle_wear_new_pack", c.ageing[m].new_pack.cycle_wear},
         {"capacity_fade", p.capacity_loss},
         {"fec", p.fec},
         {"faded_pack_cycles", p.faded_pack_cycles},
         {"min_soc", p.min_soc},
         {"days_flown", p.days_flown},
         {"days_to_end_of_life", optionalJson(p.days_to_end_of_life)},
         {"missions_to_end_of_life",
          p.missions_to_end_of_life ? nlohmann::json(*p.missions_to_end_of_life) : nlohmann::json(nullptr)},
         {"comparison_days", days},
         {"wear_reduction_pct", optionalJson(reduced.wear)},
         {"wear_reduction_new_pack_pct", optionalJson(reduced.wear_new_pack)},
         {"fade_reduction_pct", optionalJson(reduced.fade)},
         {"stopped_because", p.stopped_because},
         {"warnings", p.warnings}});
  }
  return models;
}

nlohmann::json toJson(const DutyArguments& args, const std::vector<CaseResult>& cases) {
  nlohmann::json out;
  out["scenario"] = {{"capacity_ah", args.capacity_ah},         {"charge_current_a", args.charge_current_a},
                     {"flight_min", args.flight_min},           {"idle_min", args.idle_min},
                     {"charge_max_min", args.charge_max_min},   {"soc_start", args.soc_start},
                     {"missions_per_day", args.missions_per_day}, {"days", args.days},
                     {"dt_s", args.dt_s},
                     {"study_days", studyDays(args)},
                     {"years", args.years > 0.0 ? nlohmann::json(args.years) : nlohmann::json(nullptr)},
                     {"temperature_c", args.temperature_c},
                     {"end_of_life_soh", args.end_of_life_soh},
                     {"chemistry", args.chemistry}};
  out["cases"] = nlohmann::json::array();
  for (const CaseResult& c : cases) {
    out["cases"].push_back({{"flight_current_a", c.flight_current_a},
                            {"min_soc", c.run.minSoc()},
                            {"charge_end_min", c.run.missions.back().charge_end_s / 60.0},
                            {"fec_per_mission", c.run.fecPerMission()},
                            {"fec_per_day", c.run.fecPerDay()},
                            {"fec_total", c.run.fecTotal()},
                            {"charge_ah_total", c.run.final_state.charge_ah},
                            {"discharge_ah_total", c.run.final_state.discharge_ah},
                            {"reduction_pct", reductionPct(cases.front(), c)},
                            {"ageing", ageingJson(cases, c)}});
  }
  return out;
}

void writeSeries(const std::filesystem::path& path, const std::vector<Sample>& samples) {
  writeTextAtomically(path, [&](std::ostream& out) {
    out << "t_s,current_a,soc,fec,fec_continuous,mode\n" << std::setprecision(10);
    for (const Sample& s : samples)
      out << s.t_s << ',' << s.current_a << ',' << s.soc << ',' << s.fec << ',' << s.fec_continuous << ','
          << battery::toString(s.mode) << '\n';
  });
}

void writeCsvDirectory(const std::filesystem::path& dir, const std::vector<CaseResult>& cases) {
  for (size_t i = 0; i < cases.size(); ++i) {
    const std::string prefix = "case" + std::to_string(i + 1);
    writeSeries(dir / (prefix + "_mission.csv"), cases[i].run.first_mission);
    writeSeries(dir / (prefix + "_day.csv"), cases[i].run.first_day);
    writeSeries(dir / (prefix + "_run.csv"), cases[i].run.run);
  }
  for (size_t i = 0; i < cases.size(); ++i) {
    if (cases[i].ageing.empty()) continue;
    writeTextAtomically(dir / ("case" + std::to_string(i + 1) + "_soh.csv"), [&](std::ostream& out) {
      out << "model,day,soh\n" << std::setprecision(10);
      for (const AgeingResult& a : cases[i].ageing)
        for (size_t day = 0; day < a.projection.soh_by_day.size(); ++day)
          out << a.projection.model << ',' << day + 1 << ',' << a.projection.soh_by_day[day] << '\n';
    });
  }
  writeTextAtomically(dir / "cases.csv", [&](std::ostream& out) {
    out << "case,prefix,flight_current_a\n";
    for (size_t i = 0; i < cases.size(); ++i)
      out << i + 1 << ",case" << i + 1 << ',' << cases[i].flight_current_a << '\n';
  });
}

std::vector<AgeingResult> projectAgeing(const DutyArguments& args, const battery::Pack& pack,
                                       const battery::DutyCycle& duty, double flight_current_a) {
  battery::AgeingModelOptions model_options;
  model_options.conditions = battery::OperatingConditions::fromCelsius(args.temperature_c);
  model_options.conditions.chemistry = args.chemistry;
  const energy::LipoOpenCircuitVoltage ocv;  // the energy module's cell curve, for Schmalstieg
  model_options.cell_voltage_of_soc = [ocv](double soc) { return ocv.cellVoltageV(soc); };
  model_options.woehler.cycles_at_full_depth = args.woehler_n100;
  model_options.woehler.exponent = args.woehler_k;

  std::vector<AgeingResult> results;
  for (const std::string& name : modelNames(args)) {
    battery::LifetimeOptions options;
    options.study_days = studyDays(args);
    options.end_of_life_soh = args.end_of_life_soh;
    options.max_projection_days = std::max(options.max_projection_days, options.study_days);
    options.step_s = args.dt_s;
    Progress progress("ageing (" + name + ", " + formatFixed(flight_current_a, 2) + " A)");
    options.progress = [&progress](double fraction) { progress.update(fraction); };
    const auto model = battery::makeAgeingModel(name, model_options);
    AgeingResult result{battery::projectLifetime(pack, duty, *model, model_options.conditions, options), {}};

    options.feed_back_fade = false;
    options.max_projection_days = options.study_days;
    options.progress = nullptr;
    const auto new_pack_model = battery::makeAgeingModel(name, model_options);
    result.new_pack = battery::projectLifetime(pack, duty, *new_pack_model, model_options.conditions, options);
    results.push_back(std::move(result));
  }
  return results;
}

// Limits of a study, so that a typo cannot ask for unbounded time or memory.
constexpr int kMaxStudyDays = 36500;           // 100 years, the lifetime projection's own limit
constexpr double kMaxMissionsInRun = 1e6;      // tallies kept for the table (about 100 MB)
constexpr double kMaxRecordedSamples = 1e7;    // --csv-dir's whole-run series (about 500 MB)
constexpr double kMinutesPerDay = 1440.0;

// The checks that involve several flags, each naming them, before any work.
void checkStudy(const DutyArguments& args, const battery::MissionTemplate& mission) {
  const double mission_min = args.flight_min + args.idle_min + args.charge_max_min;
  if (args.missions_per_day * mission_min > kMinutesPerDay)
    throw InputError("--missions-per-day " + std::to_string(args.missions_per_day) + " missions of " +
                     formatNumber(mission_min) + " min (--flight-min + --idle-min + --charge-max-min) take " +
                     formatNumber(args.missions_per_day * mission_min) + " min, more than a day's " +
                     formatNumber(kMinutesPerDay) + "; fly fewer or shorter missions");
  const double steps = battery::stepsPerMission(mission, args.dt_s);
  if (steps > battery::kMaxStepsPerMission)
    throw InputError("--dt-s " + formatNumber(args.dt_s) + " cuts each " + formatNumber(mission_min) +
                     "-min mission into " + formatNumber(steps) + " steps, over the " +
                     formatNumber(battery::kMaxStepsPerMission) + " allowed: give --dt-s 0 (exact) or at least " +
                     formatNumber(60.0 * mission_min / battery::kMaxStepsPerMission, 3));
  const double missions = static_cast<double>(args.missions_per_day) * studyDays(args);
  if (missions > kMaxMissionsInRun)
    throw InputError("--missions-per-day " + std::to_string(args.missions_per_day) + " over " + studySpan(args) +
                     " is " + formatNumber(missions) + " missions, over the " + formatNumber(kMaxMissionsInRun) +
                     " a study may hold; shorten --days or --years");
  // Each mission records a start and an end point per segment and the rest to its slot's end.
  const double recorded = missions * (steps + 2.0 * (mission.segments.size() + 1)) + studyDays(args);
  if (!args.csv_dir.empty() && recorded > kMaxRecordedSamples)
    throw InputError("--csv-dir would record " + formatNumber(recorded, 3) + " samples of the whole run, over the " +
                     formatNumber(kMaxRecordedSamples) + " allowed: use --dt-s 0 (exact), or shorten --days or --years");
}

void runDuty(const DutyArguments& args) {
  if (!args.json_path.empty()) checkWritableFile(args.json_path);  // before the work
  if (!args.csv_dir.empty()) io::OutputSet::checkWritable(args.csv_dir);
  battery::Pack pack;
  pack.capacity_ah = args.capacity_ah;
  pack.charge_current_a = args.charge_current_a;
  pack.validate();

  std::vector<battery::DutyCycle> duties;
  for (double flight_current_a : args.flight_currents_a) {
    battery::DutyCycle duty;
    duty.mission = battery::flyIdleChargeMission(flight_current_a, 60.0 * args.flight_min, 60.0 * args.idle_min,
                                                 args.charge_current_a, 60.0 * args.charge_max_min, args.soc_start);
    duty.missions_per_day = args.missions_per_day;
    duty.days = studyDays(args);
    duty.initial_soc = args.soc_start;
    checkStudy(args, duty.mission);
    duties.push_back(duty);
  }
  std::vector<CaseResult> cases;
  for (std::size_t i = 0; i < duties.size(); ++i) {
    const double flight_current_a = args.flight_currents_a[i];
    battery::DutyOptions options;
    options.step_s = args.dt_s;
    options.record_run = !args.csv_dir.empty();
    Progress progress("duty " + formatFixed(flight_current_a, 2) + " A");
    options.progress = [&progress](double fraction) { progress.update(fraction); };
    try {
      cases.push_back({flight_current_a, battery::simulateDuty(pack, duties[i], options), {}});
    } catch (const battery::DepletionError& e) {
      throw InfeasibleError("case " + formatFixed(flight_current_a, 2) + " A: " + e.what() +
                            "; fly less, charge longer or start fuller");
    }
    cases.back().ageing = projectAgeing(args, pack, duties[i], flight_current_a);
  }
  printTable(args, cases);
  std::optional<io::OutputSet> csv;  // staged whole: the JSON is never left beside half a series
  if (!args.csv_dir.empty()) {
    csv.emplace(args.csv_dir);
    writeCsvDirectory(csv->path(), cases);
  }
  if (!args.json_path.empty())
    writeTextAtomically(args.json_path, [&](std::ostream& out) { out << toJson(args, cases).dump(2) << '\n'; });
  if (csv) csv->commit();
}

// 0 (the exact scheme), or a step of 1 ms to an hour.
CLI::Validator timeStep() {
  return CLI::Validator(
      [](std::string& input) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(input, value)) return "'" + input + "' is not a number";
        if (!(value == 0.0 || (value >= 1e-3 && value <= 3600.0)))
          return "must be 0 (exact) or a step of 0.001 to 3600 s, got " + input;
        return {};
      },
      "0 or 0.001..3600");
}

// At most `maximum` (CLI::Range would print its bounds as "0.000000"); NaN is left to the
// finiteness check it is combined with.
CLI::Validator atMost(double maximum) {
  return CLI::Validator(
      [maximum](std::string& input) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(input, value)) return "'" + input + "' is not a number";
        if (value > maximum) return "must be at most " + formatNumber(maximum) + ", got " + input;
        return {};
      },
      "<= " + formatNumber(maximum));
}

// A finite number strictly between `low` and `high`.
CLI::Validator finiteBetween(double low, double high) {
  const std::string range = "(" + formatNumber(low) + ", " + formatNumber(high) + ")";
  return CLI::Validator(
      [low, high, range](std::string& input) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(input, value)) return "'" + input + "' is not a number";
        if (!(value > low && value < high)) return "must be a number in " + range + ", got " + input;
        return {};
      },
      "NUMBER in " + range);
}

// A chemistry name as the models' validity ranges spell them ("LiPo", "NMC", "LFP"): letters,
// digits and '-', at most 32, so that a typo never echoes raw bytes into the warnings.
CLI::Validator chemistryName() {
  return CLI::Validator(
      [](std::string& input) -> std::string {
        const bool plain = !input.empty() && input.size() <= 32 &&
                           std::all_of(input.begin(), input.end(), [](char c) {
                             return std::isalnum(static_cast<unsigned char>(c)) || c == '-';
                           });
        return plain ? std::string() : "must be 1 to 32 letters, digits or '-' (e.g. LiPo, NMC, LFP)";
      },
      "NAME");
}

void addDutyCommand(CLI::App& parent) {
  auto args = std::make_shared<DutyArguments>();
  CLI::App* duty = parent.add_subcommand(
      "duty", "Duty-cycle study: SOC, FEC and charge over repeated fly/idle/charge missions "
              "(defaults: the founding paper's two cases)");
  duty->add_option("--capacity-ah", args->capacity_ah, "Nominal pack capacity [Ah], up to 1000")
      ->capture_default_str()->check(positiveFinite() & atMost(1000.0));
  duty->add_option("--charge-current-a", args->charge_current_a, "Charger current [A], up to 1000")
      ->capture_default_str()->check(positiveFinite() & atMost(1000.0));
  duty->add_option("--flight-current-a", args->flight_currents_a,
                   "Mean flight current [A], up to 1000; repeat for one case each (first is the baseline)")
      ->capture_default_str()->check(nonNegativeFinite() & atMost(1000.0))->take_all();
  duty->add_option("--flight-min", args->flight_min, "Flight time per mission [min], up to a day")
      ->capture_default_str()->check(nonNegativeFinite() & atMost(kMinutesPerDay));
  duty->add_option("--idle-min", args->idle_min, "Idle time after landing [min], up to a day")
      ->capture_default_str()->check(nonNegativeFinite() & atMost(kMinutesPerDay));
  duty->add_option("--charge-max-min", args->charge_max_min, "Longest charge per mission [min], up to a day")
      ->capture_default_str()->check(nonNegativeFinite() & atMost(kMinutesPerDay));
  duty->add_option("--soc-start", args->soc_start, "SOC at the first take-off, and the charge-back target")
      ->capture_default_str()->check(socFraction());
  duty->add_option("--missions-per-day", args->missions_per_day, "Missions per day")
      ->capture_default_str()->check(CLI::Range(1, 1000));
  duty->add_option("--days", args->days, "Days simulated, up to 36500")
      ->capture_default_str()->check(CLI::Range(1, kMaxStudyDays));
  duty->add_option("--dt-s", args->dt_s, "Time step [s]: 0 = exact, event-driven, or 0.001 to 3600")
      ->capture_default_str()->check(timeStep());
  duty->add_option("--years", args->years, "Study period in years, up to 100 (replaces --days)")
      ->check(positiveFinite() & atMost(kMaxStudyDays / 365.0));
  std::vector<std::string> model_choices = battery::ageingModelNames();
  model_choices.insert(model_choices.end(), {"all", "none"});
  duty->add_option("--model", args->model, "Ageing model: fec, xu, schmalstieg, woehler, all or none")
      ->capture_default_str()->check(CLI::IsMember(model_choices));
  duty->add_option("--temperature-c", args->temperature_c, "Cell temperature [C] for the ageing models")
      ->capture_default_str()->check(finiteAtLeast(-273.15, true));
  duty->add_option("--eol-soh", args->end_of_life_soh, "End of life: state of health at or below this, in (0, 1)")
      ->capture_default_str()->check(finiteBetween(0.0, 1.0));
  duty->add_option("--chemistry", args->chemistry, "Pack chemistry, checked against each model's validity range")
      ->capture_default_str()->check(chemistryName());
  duty->add_option("--woehler-n100", args->woehler_n100,
                   "Cycles to end of life at 100 % DoD (fec, woehler), up to 1e6 [open]")
      ->capture_default_str()->check(positiveFinite() & atMost(1e6));
  duty->add_option("--woehler-k", args->woehler_k, "Woehler exponent k (woehler), 0 to 10 [open]")
      ->capture_default_str()->check(nonNegativeFinite() & atMost(10.0));
  duty->add_option("--json", args->json_path, "Write the results as JSON to this file");
  duty->add_option("--csv-dir", args->csv_dir,
                   "Write time series (one mission, one day, the whole run) per case to this directory");
  duty->callback([args] { runDuty(*args); });
}

const CommandRegistration registration{10, addDutyCommand};

}  // namespace
}  // namespace ceilplan::app
