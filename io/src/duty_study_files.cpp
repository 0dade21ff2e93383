#include "ceilplan/io/duty_study_files.hpp"

#include "ceilplan/core/format.hpp"
#include "ceilplan/io/atomic_file.hpp"

#include <iomanip>
#include <optional>
#include <sstream>

namespace ceilplan::io {
namespace {

using battery::DutyStudyAgeing;
using battery::DutyStudyCase;

std::string percentCell(const std::optional<double>& value) { return value ? formatFixed(*value, 2) : "n/a"; }

nlohmann::json optionalJson(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

void writeScenario(std::ostream& out, const battery::DutyStudyOptions& options) {
  out << "Duty cycle: " << options.missions_per_day << " missions a day for " << options.spanText() << "; each flies "
      << formatFixed(options.flight_s / 60.0, 1) << " min, idles " << formatFixed(options.idle_s / 60.0, 1)
      << " min, charges at " << formatFixed(options.pack.charge_current_a, 2) << " A for at most "
      << formatFixed(options.charge_max_s / 60.0, 1) << " min back to " << formatFixed(100 * options.soc_start, 1)
      << " % SOC; " << formatFixed(options.pack.capacity_ah, 2) << " Ah pack; "
      << (options.step_s > 0 ? formatFixed(options.step_s, 1) + " s steps" : std::string("exact, event-driven"))
      << "\n\n";
}

// Rows of one label and one cell per case.
struct CaseRows {
  std::ostream& out;
  const std::vector<DutyStudyCase>& cases;

  template <class Cell>
  void operator()(const std::string& label, const Cell& cell) const {
    out << std::left << std::setw(32) << label;
    for (const DutyStudyCase& c : cases) out << std::right << std::setw(12) << cell(c);
    out << '\n';
  }
};

void writeAgeing(std::ostream& out, const battery::DutyStudyOptions& options, const battery::DutyStudyResult& result) {
  const auto& cases = result.cases;
  const CaseRows row{out, cases};
  out << "\nBattery ageing over " << options.spanText() << " at " << formatFixed(options.temperature_c, 1)
      << " C, capacity fade fed back into the SOH; end of life at " << formatFixed(100 * options.end_of_life_soh, 0)
      << " % SOH\nFEC counts the charge moved against the nominal capacity, cycles of the faded pack against "
         "the faded one\n";
  for (size_t m = 0; m < cases.front().ageing.size(); ++m) {
    const auto& first = cases.front().ageing[m];
    const int days = result.comparison_days[m];
    out << first.projection.model;
    if (days < result.study_days)
      out << " (a faded pack gave out before the study's end: totals cover the days each case flew, "
             "reductions the "
          << days << (cases.size() > 2 ? " days every case flew)" : " days both flew)");
    out << ":\n";
    if (days < result.study_days)
      row("  days flown", [m](const DutyStudyCase& c) { return std::to_string(c.ageing[m].projection.days_flown); });
    row("  " + first.projection.cycle_wear_name,
        [m](const DutyStudyCase& c) { return formatNumber(c.ageing[m].projection.cycle_wear, 5); });
    row("  cycles of the faded pack",
        [m](const DutyStudyCase& c) { return formatNumber(c.ageing[m].projection.faded_pack_cycles, 5); });
    row("  capacity fade [%]",
        [m](const DutyStudyCase& c) { return formatFixed(100 * c.ageing[m].projection.capacity_loss, 2); });
    row("  days to end of life", [m](const DutyStudyCase& c) {
      const auto& days_to_end = c.ageing[m].projection.days_to_end_of_life;
      return days_to_end ? formatFixed(*days_to_end, 1) : std::string("never*");
    });
    row("  wear reduction vs first [%]",
        [m](const DutyStudyCase& c) { return percentCell(c.ageing[m].wear_reduction_pct); });
    row("  ... with the pack kept new [%]",
        [m](const DutyStudyCase& c) { return percentCell(c.ageing[m].wear_reduction_new_pack_pct); });
  }
  for (const DutyStudyCase& c : cases)
    for (const DutyStudyAgeing& a : c.ageing) {
      if (!a.projection.stopped_because.empty())
        out << "* " << a.projection.model << ", " << formatFixed(c.flight_current_a, 2)
            << " A: " << a.projection.stopped_because << '\n';
    }
  for (const DutyStudyAgeing& a : cases.front().ageing)
    for (const std::string& warning : a.projection.warnings) out << "warning: " << warning << '\n';
}

nlohmann::json ageingJson(const battery::DutyStudyResult& result, const DutyStudyCase& c) {
  nlohmann::json models = nlohmann::json::array();
  for (size_t m = 0; m < c.ageing.size(); ++m) {
    const battery::LifetimeResult& p = c.ageing[m].projection;
    models.push_back({{"model", p.model},
                      {"cycle_wear_name", p.cycle_wear_name},
                      {"cycle_wear", p.cycle_wear},
                      {"cycle_wear_new_pack", c.ageing[m].new_pack.cycle_wear},
                      {"capacity_fade", p.capacity_loss},
                      {"fec", p.fec},
                      {"faded_pack_cycles", p.faded_pack_cycles},
                      {"min_soc", p.min_soc},
                      {"days_flown", p.days_flown},
                      {"days_to_end_of_life", optionalJson(p.days_to_end_of_life)},
                      {"missions_to_end_of_life", p.missions_to_end_of_life ? nlohmann::json(*p.missions_to_end_of_life)
                                                                            : nlohmann::json(nullptr)},
                      {"comparison_days", result.comparison_days[m]},
                      {"wear_reduction_pct", optionalJson(c.ageing[m].wear_reduction_pct)},
                      {"wear_reduction_new_pack_pct", optionalJson(c.ageing[m].wear_reduction_new_pack_pct)},
                      {"fade_reduction_pct", optionalJson(c.ageing[m].fade_reduction_pct)},
                      {"stopped_because", p.stopped_because},
                      {"warnings", p.warnings}});
  }
  return models;
}

}  // namespace

std::string dutyStudyTable(const battery::DutyStudyOptions& options, const battery::DutyStudyResult& result) {
  std::ostringstream out;
  const auto& cases = result.cases;
  writeScenario(out, options);
  const CaseRows row{out, cases};
  for (size_t i = 0; i < cases.size(); ++i)
    out << (i == 0 ? std::string(32, ' ') : "") << std::right << std::setw(12) << "case " + std::to_string(i + 1);
  out << '\n';
  const std::string span = options.spanText();
  row("flight current [A]", [](const DutyStudyCase& c) { return formatFixed(c.flight_current_a, 2); });
  row("lowest SOC [%]", [](const DutyStudyCase& c) { return formatFixed(100 * c.run.minSoc(), 1); });
  row("charge complete [min]",
      [](const DutyStudyCase& c) { return formatFixed(c.run.missions.back().charge_end_s / 60, 2); });
  row("FEC per mission", [](const DutyStudyCase& c) { return formatFixed(c.run.fecPerMission(), 4); });
  row("FEC per day", [](const DutyStudyCase& c) { return formatFixed(c.run.fecPerDay(), 3); });
  row("FEC after " + span.substr(0, span.find(" (")),
      [](const DutyStudyCase& c) { return formatFixed(c.run.fecTotal(), 2); });
  row("charge put back [Ah]", [](const DutyStudyCase& c) { return formatFixed(c.run.final_state.charge_ah, 1); });
  row("FEC reduction vs first [%]", [](const DutyStudyCase& c) { return formatFixed(c.fec_reduction_pct, 2); });
  if (!cases.front().ageing.empty()) writeAgeing(out, options, result);
  return out.str();
}

nlohmann::json dutyStudyJson(const battery::DutyStudyOptions& options, const battery::DutyStudyResult& result) {
  nlohmann::json out;
  out["scenario"] = {{"capacity_ah", options.pack.capacity_ah},
                     {"charge_current_a", options.pack.charge_current_a},
                     {"flight_min", options.flight_s / 60.0},
                     {"idle_min", options.idle_s / 60.0},
                     {"charge_max_min", options.charge_max_s / 60.0},
                     {"soc_start", options.soc_start},
                     {"missions_per_day", options.missions_per_day},
                     {"days", options.days},
                     {"dt_s", options.step_s},
                     {"study_days", result.study_days},
                     {"years", options.years > 0.0 ? nlohmann::json(options.years) : nlohmann::json(nullptr)},
                     {"temperature_c", options.temperature_c},
                     {"end_of_life_soh", options.end_of_life_soh},
                     {"chemistry", options.chemistry}};
  out["cases"] = nlohmann::json::array();
  for (const DutyStudyCase& c : result.cases) {
    out["cases"].push_back({{"flight_current_a", c.flight_current_a},
                            {"min_soc", c.run.minSoc()},
                            {"charge_end_min", c.run.missions.back().charge_end_s / 60.0},
                            {"fec_per_mission", c.run.fecPerMission()},
                            {"fec_per_day", c.run.fecPerDay()},
                            {"fec_total", c.run.fecTotal()},
                            {"charge_ah_total", c.run.final_state.charge_ah},
                            {"discharge_ah_total", c.run.final_state.discharge_ah},
                            {"reduction_pct", c.fec_reduction_pct},
                            {"ageing", ageingJson(result, c)}});
  }
  return out;
}

void writeDutySeriesCsv(const std::filesystem::path& file, const std::vector<battery::Sample>& samples,
                        const Provenance& provenance) {
  writeTextAtomically(file, [&](std::ostream& out) {
    out << provenance.csvComment() << '\n' << "t_s,current_a,soc,fec,fec_continuous,mode\n" << std::setprecision(10);
    for (const battery::Sample& s : samples)
      out << s.t_s << ',' << s.current_a << ',' << s.soc << ',' << s.fec << ',' << s.fec_continuous << ','
          << battery::toString(s.mode) << '\n';
  });
}

void writeDutyStudyCsv(const std::filesystem::path& dir, const battery::DutyStudyResult& result,
                       const Provenance& provenance) {
  const auto& cases = result.cases;
  for (size_t i = 0; i < cases.size(); ++i) {
    const std::string prefix = "case" + std::to_string(i + 1);
    writeDutySeriesCsv(dir / (prefix + "_mission.csv"), cases[i].run.first_mission, provenance);
    writeDutySeriesCsv(dir / (prefix + "_day.csv"), cases[i].run.first_day, provenance);
    writeDutySeriesCsv(dir / (prefix + "_run.csv"), cases[i].run.run, provenance);
  }
  for (size_t i = 0; i < cases.size(); ++i) {
    if (cases[i].ageing.empty()) continue;
    writeTextAtomically(dir / ("case" + std::to_string(i + 1) + "_soh.csv"), [&](std::ostream& out) {
      out << provenance.csvComment() << '\n' << "model,day,soh\n" << std::setprecision(10);
      for (const DutyStudyAgeing& a : cases[i].ageing)
        for (size_t day = 0; day < a.projection.soh_by_day.size(); ++day)
          out << a.projection.model << ',' << day + 1 << ',' << a.projection.soh_by_day[day] << '\n';
    });
  }
  writeTextAtomically(dir / "cases.csv", [&](std::ostream& out) {
    out << provenance.csvComment() << '\n' << "case,prefix,flight_current_a\n";
    for (size_t i = 0; i < cases.size(); ++i)
      out << i + 1 << ",case" << i + 1 << ',' << cases[i].flight_current_a << '\n';
  });
}

}  // namespace ceilplan::io
