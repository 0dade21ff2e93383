// `ceilplan duty`: a duty-cycle study; with no arguments, the founding paper's two cases.

#include "cli_checks.hpp"
#include "command_registry.hpp"
#include "output.hpp"

#include "ceilplan/battery/duty_study.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/energy/lipo_open_circuit_voltage.hpp"
#include "ceilplan/io/duty_study_files.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/output_set.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <memory>
#include <string>
#include <vector>

namespace ceilplan::app {
namespace {

// The flags in the library's units bind to the study's options, whose defaults are the paper's.
struct DutyArguments {
  battery::DutyStudyOptions study;
  double flight_min = study.flight_s / 60.0;
  double idle_min = study.idle_s / 60.0;
  double charge_max_min = study.charge_max_s / 60.0;
  std::string model = "all";
  std::string json_path;
  std::string csv_dir;
};

constexpr double kMinutesPerDay = 1440.0;

battery::DutyStudyOptions studyOptions(const DutyArguments& args) {
  battery::DutyStudyOptions study = args.study;
  study.flight_s = 60.0 * args.flight_min;
  study.idle_s = 60.0 * args.idle_min;
  study.charge_max_s = 60.0 * args.charge_max_min;
  if (args.model == "none") study.ageing_models.clear();
  if (args.model != "all" && args.model != "none") study.ageing_models = {args.model};
  study.cell_voltage_of_soc = energy::lipoCellVoltageOfSoc();
  study.record_run = !args.csv_dir.empty();
  return study;
}

// The study's limits that involve several flags, each naming them, before any work (the library
// checks the same in its own terms).
void checkStudy(const DutyArguments& args, const battery::DutyStudyOptions& study) {
  const double mission_min = args.flight_min + args.idle_min + args.charge_max_min;
  if (study.missions_per_day * mission_min > kMinutesPerDay)
    throw InputError("--missions-per-day " + std::to_string(study.missions_per_day) + " missions of " +
                     formatNumber(mission_min) + " min (--flight-min + --idle-min + --charge-max-min) take " +
                     formatNumber(study.missions_per_day * mission_min) + " min, more than a day's " +
                     formatNumber(kMinutesPerDay) + "; fly fewer or shorter missions");
  const double steps = battery::stepsPerMission(study.mission(study.flight_currents_a.front()), study.step_s);
  if (steps > battery::kMaxStepsPerMission)
    throw InputError("--dt-s " + formatNumber(study.step_s) + " cuts each " + formatNumber(mission_min) +
                     "-min mission into " + formatNumber(steps) + " steps, over the " +
                     formatNumber(battery::kMaxStepsPerMission) + " allowed: give --dt-s 0 (exact) or at least " +
                     formatNumber(60.0 * mission_min / battery::kMaxStepsPerMission, 3));
  if (study.studyMissions() > battery::kMaxStudyMissions)
    throw InputError("--missions-per-day " + std::to_string(study.missions_per_day) + " over " + study.spanText() +
                     " is " + formatNumber(study.studyMissions()) + " missions, over the " +
                     formatNumber(battery::kMaxStudyMissions) + " a study may hold; shorten --days or --years");
  if (study.record_run && study.recordedRunSamples() > battery::kMaxRecordedRunSamples)
    throw InputError("--csv-dir would record " + formatNumber(study.recordedRunSamples(), 3) +
                     " samples of the whole run, over the " + formatNumber(battery::kMaxRecordedRunSamples) +
                     " allowed: use --dt-s 0 (exact), or shorten --days or --years");
}

void runDuty(const DutyArguments& args) {
  battery::DutyStudyOptions study = studyOptions(args);
  checkStudy(args, study);
  // Checked and staged before the work; the JSON and the CSV directory appear together.
  io::OutputSet out({{"--json", args.json_path}, {"--csv-dir", args.csv_dir, true}}, commandInputs({}));
  const io::Provenance provenance = commandProvenance();
  study.progress = terminalProgress();
  const battery::DutyStudyResult result = battery::runDutyStudy(study);
  study.progress = nullptr;  // clears the progress line before the table
  print(io::dutyStudyTable(study, result));
  if (!args.json_path.empty())
    io::writeJsonFile(out.path("--json"), io::withProvenance(io::dutyStudyJson(study, result), provenance));
  if (!args.csv_dir.empty()) io::writeDutyStudyCsv(out.path("--csv-dir"), result, provenance);
  out.commit();
}

// 0 (the exact scheme), or a step of 1 ms to an hour.
CLI::Validator timeStep() {
  return numberWhere([](double v) { return v == 0.0 || (v >= 1e-3 && v <= 3600.0); },
                     "0 (exact) or a step of 0.001 to 3600 s", "0 or 0.001..3600");
}

// A chemistry name as the models' validity ranges spell them ("LiPo", "NMC", "LFP"): letters,
// digits and '-', at most 32, so that a typo never echoes raw bytes into the warnings.
CLI::Validator chemistryName() {
  return CLI::Validator(
      [](std::string& input) -> std::string {
        const bool plain = !input.empty() && input.size() <= 32 && std::all_of(input.begin(), input.end(), [](char c) {
          return std::isalnum(static_cast<unsigned char>(c)) || c == '-';
        });
        return plain ? std::string() : "must be 1 to 32 letters, digits or '-' (e.g. LiPo, NMC, LFP)";
      },
      "NAME");
}

void addDutyCommand(CLI::App& parent) {
  auto args = std::make_shared<DutyArguments>();
  CLI::App* duty = parent.add_subcommand("duty",
                                         "Duty-cycle study: SOC, FEC and charge over repeated fly/idle/charge missions "
                                         "(defaults: the founding paper's two cases)");
  duty->add_option("--capacity-ah", args->study.pack.capacity_ah, "Nominal pack capacity [Ah], 0.01 to 1000")
      ->capture_default_str()
      ->check(finiteRange(battery::Pack::kMinCapacity_ah, battery::Pack::kMaxCapacity_ah));
  duty->add_option("--charge-current-a", args->study.pack.charge_current_a, "Charger current [A], up to 1000")
      ->capture_default_str()
      ->check(positiveFinite() & atMost(1000.0));
  duty->add_option("--flight-current-a", args->study.flight_currents_a,
                   "Mean flight current [A], up to 1000; repeat for one case each (first is the baseline)")
      ->capture_default_str()
      ->check(nonNegativeFinite() & atMost(1000.0))
      ->take_all();
  duty->add_option("--flight-min", args->flight_min, "Flight time per mission [min], up to a day")
      ->capture_default_str()
      ->check(nonNegativeFinite() & atMost(kMinutesPerDay));
  duty->add_option("--idle-min", args->idle_min, "Idle time after landing [min], up to a day")
      ->capture_default_str()
      ->check(nonNegativeFinite() & atMost(kMinutesPerDay));
  duty->add_option("--charge-max-min", args->charge_max_min, "Longest charge per mission [min], up to a day")
      ->capture_default_str()
      ->check(nonNegativeFinite() & atMost(kMinutesPerDay));
  duty->add_option("--soc-start", args->study.soc_start, "SOC at the first take-off, and the charge-back target")
      ->capture_default_str()
      ->check(socFraction());
  duty->add_option("--missions-per-day", args->study.missions_per_day, "Missions per day")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  duty->add_option("--days", args->study.days, "Days simulated, up to 36500")
      ->capture_default_str()
      ->check(CLI::Range(1, battery::kMaxStudyDays));
  duty->add_option("--dt-s", args->study.step_s, "Time step [s]: 0 = exact, event-driven, or 0.001 to 3600")
      ->capture_default_str()
      ->check(timeStep());
  duty->add_option("--years", args->study.years, "Study period in years, up to 100 (replaces --days)")
      ->check(positiveFinite() & atMost(battery::kMaxStudyDays / 365.0));
  std::vector<std::string> model_choices = battery::ageingModelNames();
  model_choices.insert(model_choices.end(), {"all", "none"});
  duty->add_option("--model", args->model, "Ageing model: fec, xu, schmalstieg, woehler, all or none")
      ->capture_default_str()
      ->check(CLI::IsMember(model_choices));
  duty->add_option("--temperature-c", args->study.temperature_c, "Cell temperature [C] for the ageing models")
      ->capture_default_str()
      ->check(finiteAtLeast(-273.15, true));
  duty->add_option("--eol-soh", args->study.end_of_life_soh, "End of life: state of health at or below this, in (0, 1)")
      ->capture_default_str()
      ->check(finiteBetween(0.0, 1.0));
  duty->add_option("--chemistry", args->study.chemistry, "Pack chemistry, checked against each model's validity range")
      ->capture_default_str()
      ->check(chemistryName());
  duty->add_option("--woehler-n100", args->study.woehler.cycles_at_full_depth,
                   "Cycles to end of life at 100 % DoD (fec, woehler), up to 1e6 [open]")
      ->capture_default_str()
      ->check(positiveFinite() & atMost(1e6));
  duty->add_option("--woehler-k", args->study.woehler.exponent, "Woehler exponent k (woehler), 0 to 10 [open]")
      ->capture_default_str()
      ->check(nonNegativeFinite() & atMost(10.0));
  duty->add_option("--json", args->json_path, "Write the results as JSON to this file");
  duty->add_option("--csv-dir", args->csv_dir,
                   "Write time series (one mission, one day, the whole run) per case to this directory");
  duty->callback([args] { runDuty(*args); });
}

const CommandRegistration registration{10, addDutyCommand};

}  // namespace
}  // namespace ceilplan::app
