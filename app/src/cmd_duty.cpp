// `ceilplan duty`: a duty-cycle study; with no arguments, the founding paper's two cases.

#include "cli_checks.hpp"
#include "command_registry.hpp"
#include "output.hpp"

#include "ceilplan/battery/duty_cycle.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
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
  std::string json_path;
  std::string csv_dir;
};

struct CaseResult {
  double flight_current_a;
  DutyResult run;
};

std::string fixed(double value, int decimals) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(decimals) << value;
  return text.str();
}

double reductionPct(const CaseResult& first, const CaseResult& other) {
  return 100.0 * (1.0 - other.run.fecTotal() / first.run.fecTotal());
}

void printTable(const DutyArguments& args, const std::vector<CaseResult>& cases) {
  std::cout << "Duty cycle: " << args.missions_per_day << " missions a day for " << args.days
            << " days; each flies " << fixed(args.flight_min, 1) << " min, idles " << fixed(args.idle_min, 1)
            << " min, charges at " << fixed(args.charge_current_a, 2) << " A for at most "
            << fixed(args.charge_max_min, 1) << " min back to " << fixed(100 * args.soc_start, 1) << " % SOC; "
            << fixed(args.capacity_ah, 2) << " Ah pack; "
            << (args.dt_s > 0 ? fixed(args.dt_s, 1) + " s steps" : std::string("exact, event-driven")) << "\n\n";
  const auto row = [&](const std::string& label, const auto& cell) {
    std::cout << std::left << std::setw(32) << label;
    for (const CaseResult& c : cases) std::cout << std::right << std::setw(12) << cell(c);
    std::cout << '\n';
  };
  for (size_t i = 0; i < cases.size(); ++i) std::cout << (i == 0 ? std::string(32, ' ') : "") << std::right << std::setw(12) << "case " + std::to_string(i + 1);
  std::cout << '\n';
  row("flight current [A]", [](const CaseResult& c) { return fixed(c.flight_current_a, 2); });
  row("lowest SOC [%]", [](const CaseResult& c) { return fixed(100 * c.run.minSoc(), 1); });
  row("charge complete [min]", [](const CaseResult& c) { return fixed(c.run.missions.back().charge_end_s / 60, 2); });
  row("FEC per mission", [](const CaseResult& c) { return fixed(c.run.fecPerMission(), 4); });
  row("FEC per day", [](const CaseResult& c) { return fixed(c.run.fecPerDay(), 3); });
  row("FEC after " + std::to_string(args.days) + " days", [](const CaseResult& c) { return fixed(c.run.fecTotal(), 2); });
  row("charge put back [Ah]", [](const CaseResult& c) { return fixed(c.run.final_state.charge_ah, 1); });
  row("FEC reduction vs first [%]", [&](const CaseResult& c) { return fixed(reductionPct(cases.front(), c), 2); });
}

nlohmann::json toJson(const DutyArguments& args, const std::vector<CaseResult>& cases) {
  nlohmann::json out;
  out["scenario"] = {{"capacity_ah", args.capacity_ah},         {"charge_current_a", args.charge_current_a},
                     {"flight_min", args.flight_min},           {"idle_min", args.idle_min},
                     {"charge_max_min", args.charge_max_min},   {"soc_start", args.soc_start},
                     {"missions_per_day", args.missions_per_day}, {"days", args.days},
                     {"dt_s", args.dt_s}};
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
                            {"reduction_pct", reductionPct(cases.front(), c)}});
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
  writeTextAtomically(dir / "cases.csv", [&](std::ostream& out) {
    out << "case,prefix,flight_current_a\n";
    for (size_t i = 0; i < cases.size(); ++i)
      out << i + 1 << ",case" << i + 1 << ',' << cases[i].flight_current_a << '\n';
  });
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
    duty.days = args.days;
    duty.initial_soc = args.soc_start;
    battery::DutyOptions options;
    options.step_s = args.dt_s;
    options.record_run = !args.csv_dir.empty();
    Progress progress("duty " + fixed(flight_current_a, 2) + " A");
    options.progress = [&progress](double fraction) { progress.update(fraction); };
    try {
      cases.push_back({flight_current_a, battery::simulateDuty(pack, duty, options)});
    } catch (const battery::DepletionError& e) {
      throw std::runtime_error("case " + fixed(flight_current_a, 2) + " A: " + e.what() +
                               "; fly less, charge longer or start fuller");
    }
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
  duty->add_option("--json", args->json_path, "Write the results as JSON to this file");
  duty->add_option("--csv-dir", args->csv_dir,
                   "Write time series (one mission, one day, the whole run) per case to this directory");
  duty->callback([args] { runDuty(*args); });
}

const CommandRegistration registration{10, addDutyCommand};

}  // namespace
}  // namespace ceilplan::app
