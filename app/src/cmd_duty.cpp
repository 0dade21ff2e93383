// `ceilplan duty`: a duty-cycle study; with no arguments, the founding paper's two cases.

#include "cli_checks.hpp"
#include "command_registry.hpp"
#include "output.hpp"

#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/battery/duty_cycle.hpp"
#include "ceilplan/battery/lifetime.hpp"
#include "ceilplan/energy/lipo_open_circuit_voltage.hpp"
#include "ceilplan/core/format.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
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
// held new over the study period (the reference's derivations).
struct AgeingResult {
  battery::LifetimeResult projection;
  double cycle_wear_new_pack;
};

struct CaseResult {
  double flight_current_a;
  DutyResult run;
  std::vector<AgeingResult> ageing;  // one per model, in the order of modelNames()
};

int studyDays(const DutyArguments& args) {
  return args.years > 0.0 ? static_cast<int>(std::lround(365.0 * args.years)) : args.days;
}

std::vector<std::string> modelNames(const DutyArguments& args) {
  if (args.model == "none") return {};
  if (args.model == "all") return battery::ageingModelNames();
  return {args.model};
}


double reductionPct(const CaseResult& first, const CaseResult& other) {
  return 100.0 * (1.0 - other.run.fecTotal() / first.run.fecTotal());
}

void printTable(const DutyArguments& args, const std::vector<CaseResult>& cases) {
  std::cout << "Duty cycle: " << args.missions_per_day << " missions a day for " << args.days
            << " days; each flies " << formatFixed(args.flight_min, 1) << " min, idles " << formatFixed(args.idle_min, 1)
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
  row("FEC after " + std::to_string(args.days) + " days", [](const CaseResult& c) { return formatFixed(c.run.fecTotal(), 2); });
  row("charge put back [Ah]", [](const CaseResult& c) { return formatFixed(c.run.final_state.charge_ah, 1); });
  row("FEC reduction vs first [%]", [&](const CaseResult& c) { return formatFixed(reductionPct(cases.front(), c), 2); });
  if (cases.front().ageing.empty()) return;

  std::cout << "\nBattery ageing over " << studyDays(args) << " days at " << formatFixed(args.temperature_c, 1)
            << " C, capacity fade fed back into the SOH; end of life at " << formatFixed(100 * args.end_of_life_soh, 0)
            << " % SOH\n";
  for (size_t m = 0; m < cases.front().ageing.size(); ++m) {
    const auto& first = cases.front().ageing[m];
    std::cout << first.projection.model << ":\n";
    const auto wear = [m](const CaseResult& c) { return c.ageing[m].projection.cycle_wear; };
    const auto new_pack_wear = [m](const CaseResult& c) { return c.ageing[m].cycle_wear_new_pack; };
    row("  " + first.projection.cycle_wear_name, [&](const CaseResult& c) { return formatNumber(wear(c), 4); });
    row("  capacity fade [%]", [m](const CaseResult& c) { return formatFixed(100 * c.ageing[m].projection.capacity_loss, 2); });
    row("  days to end of life", [m](const CaseResult& c) {
      const auto& days = c.ageing[m].projection.days_to_end_of_life;
      return days ? formatFixed(*days, 1) : std::string("never*");
    });
    row("  wear reduction vs first [%]", [&](const CaseResult& c) { return formatFixed(100 * (1 - wear(c) / wear(cases.front())), 2); });
    row("  ... with the pack kept new [%]",
        [&](const CaseResult& c) { return formatFixed(100 * (1 - new_pack_wear(c) / new_pack_wear(cases.front())), 2); });
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

nlohmann::json ageingJson(const CaseResult& first, const CaseResult& c) {
  nlohmann::json models = nlohmann::json::array();
  for (size_t m = 0; m < c.ageing.size(); ++m) {
    const battery::LifetimeResult& p = c.ageing[m].projection;
    const battery::LifetimeResult& base = first.ageing[m].projection;
    models.push_back(
        {{"model", p.model},
         {"cycle_wear_name", p.cycle_wear_name},
         {"cycle_wear", p.cycle_wear},
         {"cycle_wear_new_pack", c.ageing[m].cycle_wear_new_pack},
         {"capacity_fade", p.capacity_loss},
         {"fec", p.fec},
         {"min_soc", p.min_soc},
         {"days_to_end_of_life", optionalJson(p.days_to_end_of_life)},
         {"missions_to_end_of_life",
          p.missions_to_end_of_life ? nlohmann::json(*p.missions_to_end_of_life) : nlohmann::json(nullptr)},
         {"wear_reduction_pct", 100.0 * (1.0 - p.cycle_wear / base.cycle_wear)},
         {"wear_reduction_new_pack_pct",
          100.0 * (1.0 - c.ageing[m].cycle_wear_new_pack / first.ageing[m].cycle_wear_new_pack)},
         {"fade_reduction_pct", 100.0 * (1.0 - p.capacity_loss / base.capacity_loss)},
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
                            {"ageing", ageingJson(cases.front(), c)}});
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
    AgeingResult result{battery::projectLifetime(pack, duty, *model, model_options.conditions, options), 0.0};

    options.feed_back_fade = false;
    options.max_projection_days = options.study_days;
    options.progress = nullptr;
    const auto new_pack_model = battery::makeAgeingModel(name, model_options);
    result.cycle_wear_new_pack =
        battery::projectLifetime(pack, duty, *new_pack_model, model_options.conditions, options).cycle_wear;
    results.push_back(std::move(result));
  }
  return results;
}

void runDuty(const DutyArguments& args) {
  battery::Pack pack;
  pack.capacity_ah = args.capacity_ah;
  pack.charge_current_a = args.charge_current_a;
  pack.validate();

  std::vector<CaseResult> cases;
  for (double flight_current_a : args.flight_currents_a) {
    battery::DutyCycle duty;
    duty.mission = battery::flyIdleChargeMission(flight_current_a, 60.0 * args.flight_min, 60.0 * args.idle_min,
                                                 args.charge_current_a, 60.0 * args.charge_max_min, args.soc_start);
    duty.missions_per_day = args.missions_per_day;
    duty.days = studyDays(args);
    duty.initial_soc = args.soc_start;
    battery::DutyOptions options;
    options.step_s = args.dt_s;
    options.record_run = !args.csv_dir.empty();
    Progress progress("duty " + formatFixed(flight_current_a, 2) + " A");
    options.progress = [&progress](double fraction) { progress.update(fraction); };
    try {
      cases.push_back({flight_current_a, battery::simulateDuty(pack, duty, options), {}});
    } catch (const battery::DepletionError& e) {
      throw std::runtime_error("case " + formatFixed(flight_current_a, 2) + " A: " + e.what() +
                               "; fly less, charge longer or start fuller");
    }
    cases.back().ageing = projectAgeing(args, pack, duty, flight_current_a);
  }
  printTable(args, cases);
  if (!args.json_path.empty())
    writeTextAtomically(args.json_path, [&](std::ostream& out) { out << toJson(args, cases).dump(2) << '\n'; });
  if (!args.csv_dir.empty()) writeCsvDirectory(args.csv_dir, cases);
}

void addDutyCommand(CLI::App& parent) {
  auto args = std::make_shared<DutyArguments>();
  CLI::App* duty = parent.add_subcommand(
      "duty", "Duty-cycle study: SOC, FEC and charge over repeated fly/idle/charge missions "
              "(defaults: the founding paper's two cases)");
  duty->add_option("--capacity-ah", args->capacity_ah, "Nominal pack capacity [Ah]")
      ->capture_default_str()->check(positiveFinite());
  duty->add_option("--charge-current-a", args->charge_current_a, "Charger current [A]")
      ->capture_default_str()->check(positiveFinite());
  duty->add_option("--flight-current-a", args->flight_currents_a,
                   "Mean flight current [A]; repeat for one case each (first is the baseline)")
      ->capture_default_str()->check(nonNegativeFinite())->take_all();
  duty->add_option("--flight-min", args->flight_min, "Flight time per mission [min]")
      ->capture_default_str()->check(nonNegativeFinite());
  duty->add_option("--idle-min", args->idle_min, "Idle time after landing [min]")
      ->capture_default_str()->check(nonNegativeFinite());
  duty->add_option("--charge-max-min", args->charge_max_min, "Longest charge per mission [min]")
      ->capture_default_str()->check(nonNegativeFinite());
  duty->add_option("--soc-start", args->soc_start, "SOC at the first take-off, and the charge-back target")
      ->capture_default_str()->check(socFraction());
  duty->add_option("--missions-per-day", args->missions_per_day, "Missions per day")
      ->capture_default_str()->check(CLI::Range(1, 1000));
  duty->add_option("--days", args->days, "Days simulated")->capture_default_str()->check(CLI::Range(1, 100000));
  duty->add_option("--dt-s", args->dt_s, "Time step [s]; 0 = exact, event-driven")
      ->capture_default_str()->check(nonNegativeFinite());
  duty->add_option("--years", args->years, "Study period in years (replaces --days)")
      ->check(nonNegativeFinite());
  std::vector<std::string> model_choices = battery::ageingModelNames();
  model_choices.insert(model_choices.end(), {"all", "none"});
  duty->add_option("--model", args->model, "Ageing model: fec, xu, schmalstieg, woehler, all or none")
      ->capture_default_str()->check(CLI::IsMember(model_choices));
  duty->add_option("--temperature-c", args->temperature_c, "Cell temperature [C] for the ageing models")
      ->capture_default_str()->check(finiteAtLeast(-273.15, true));
  duty->add_option("--eol-soh", args->end_of_life_soh, "End of life: state of health at or below this")
      ->capture_default_str()->check(CLI::Range(0.0, 1.0) & positiveFinite());
  duty->add_option("--chemistry", args->chemistry, "Pack chemistry, checked against each model's validity range")
      ->capture_default_str();
  duty->add_option("--woehler-n100", args->woehler_n100, "Cycles to end of life at 100 % DoD (fec, woehler) [open]")
      ->capture_default_str()->check(positiveFinite());
  duty->add_option("--woehler-k", args->woehler_k, "Woehler exponent k (woehler) [open]")
      ->capture_default_str()->check(nonNegativeFinite());
  duty->add_option("--json", args->json_path, "Write the results as JSON to this file");
  duty->add_option("--csv-dir", args->csv_dir,
                   "Write time series (one mission, one day, the whole run) per case to this directory");
  duty->callback([args] { runDuty(*args); });
}

const CommandRegistration registration{10, addDutyCommand};

}  // namespace
}  // namespace ceilplan::app
