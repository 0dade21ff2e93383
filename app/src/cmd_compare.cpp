// `ceilplan compare`: the same query planned in ceiling mode and in free mode, both scored with
// the full model, with each plan's month-long duty projection (the founding paper's study).

#include "cli_checks.hpp"
#include "command_registry.hpp"
#include "duty_projection.hpp"
#include "errors.hpp"
#include "map_views.hpp"
#include "output.hpp"
#include "plan_output.hpp"
#include "planning_setup.hpp"

#include "ceilplan/battery/duty_cycle.hpp"
#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/path_evaluation.hpp"
#include "ceilplan/core/error.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <string>

namespace ceilplan::app {
namespace {

struct CompareArguments {
  PlanningArguments planning;
  SearchArguments search;
  std::string start, goal, out;
  double flight_min = 20.0;  // the paper's mission
  double idle_min = 5.0;
  double charge_max_min = 20.0;
  int missions_per_day = 15;
  int days = 30;
};

struct ModeResult {
  std::string name;
  planner::PlanResult plan;
  planner::PathEvaluation evaluation;
  int repeats = 1;
  battery::DutyResult duty;
};

ModeResult planMode(const CompareArguments& a, const PlanningSetup& setup, PlanningMode mode,
                    const Eigen::Vector3d& start, const Eigen::Vector3d& goal,
                    const std::vector<std::vector<Eigen::Vector3d>>& candidates = {}) {
  ModeResult result;
  result.name = modeName(mode);
  const PlanningSetup::Mode planning = setup.mode(mode, start, goal);
  const planner::FlightPlanner flight_planner(*planning.rules, *planning.model, setup.objective(start, goal));
  try {
    planner::PlanRequest request = a.search.request(start, goal);
    request.candidates = candidates;
    result.plan = flight_planner.plan(request);
  } catch (const ceilplan::NoPathError& e) {
    throw NoPathError(result.name + " mode: " + e.what());
  }
  const BatteryChoice& battery = setup.battery();
  result.evaluation = planner::evaluatePath(setup.fullModel(), battery.pack, battery.start_soc, result.plan.waypoints);
  writePlanDirectory(std::filesystem::path(a.out) / result.name, result.plan, result.evaluation,
                     {{"mode", result.name}, {"seed", a.search.seed}, {"objective", a.planning.objective}});
  return result;
}

// The paper's month: each mission flies the route `repeats` times, idles, charges back.
void projectDuty(const CompareArguments& a, const BatteryChoice& battery, ModeResult& result, int repeats) {
  result.repeats = repeats;
  battery::DutyCycle duty;
  duty.mission.segments = flightProfile(result.evaluation, result.repeats);
  duty.mission.segments.push_back(battery::Segment::idle(60.0 * a.idle_min));
  duty.mission.segments.push_back(
      battery::Segment::charge(battery.pack.charge_current_a, 60.0 * a.charge_max_min, battery.start_soc));
  duty.missions_per_day = a.missions_per_day;
  duty.days = a.days;
  duty.initial_soc = battery.start_soc;
  battery::DutyOptions options;
  options.record_first_day = false;
  try {
    result.duty = battery::simulateDuty(battery.pack, duty, options);
  } catch (const battery::DepletionError& e) {
    throw std::runtime_error(result.name + " mode: flying the plan " + std::to_string(result.repeats) +
                             " times per mission depletes the pack (" + e.what() + "); lower --flight-min");
  }
}

std::string cell(double value, int decimals) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

void runCompare(const CompareArguments& a) {
  const Eigen::Vector3d start = parsePoint(a.start, "--start"), goal = parsePoint(a.goal, "--goal");
  planner::seedOmpl(a.search.seed);
  const PlanningSetup setup(a.planning);
  std::printf("comparing ceiling and free modes: objective %s, planner %s, seed %u, %.1f s each\n",
              a.planning.objective.c_str(), a.search.plannerName().c_str(), a.search.seed, a.search.time_limit_s);
  std::fflush(stdout);
  // Free mode first: ceiling mode is shown its route, so it is never worse under the full model.
  ModeResult free_mode = planMode(a, setup, PlanningMode::Free, start, goal);
  ModeResult ceiling_mode = planMode(a, setup, PlanningMode::Ceiling, start, goal, {free_mode.plan.waypoints});
  if (ceiling_mode.plan.from_candidate)
    std::printf("ceiling mode found nothing better than the free-mode route: it flies that route, post-processed\n");
  std::vector<ModeResult> modes{std::move(ceiling_mode), std::move(free_mode)};
  // Both missions do the same work: the route, as many times as the slower plan fits in
  // --flight-min.
  const double slower_s = std::max(modes[0].evaluation.duration_s, modes[1].evaluation.duration_s);
  const int repeats = std::max(1, static_cast<int>(std::floor(60.0 * a.flight_min / slower_s)));
  for (ModeResult& m : modes) projectDuty(a, setup.battery(), m, repeats);
  const ModeResult &ceiling = modes[0], &free = modes[1];
  const auto reduction = [](double with, double without) { return 100.0 * (1.0 - with / without); };

  std::printf("\nboth plans scored with the full model (start SOC %.0f %%)\n", 100.0 * setup.battery().start_soc);
  std::printf("%-34s %14s %14s %12s\n", "", "ceiling", "free", "reduction %");
  const auto row = [&](const char* label, double c, double f, int decimals, bool with_reduction) {
    std::printf("%-34s %14s %14s %12s\n", label, cell(c, decimals).c_str(), cell(f, decimals).c_str(),
                with_reduction ? cell(reduction(c, f), 2).c_str() : "");
  };
  row("length [m]", ceiling.evaluation.length_m, free.evaluation.length_m, 2, false);
  row("time [s]", ceiling.evaluation.duration_s, free.evaluation.duration_s, 1, true);
  row("charge [Ah]", ceiling.evaluation.charge_ah, free.evaluation.charge_ah, 5, true);
  row("energy [Wh]", ceiling.evaluation.energy_wh, free.evaluation.energy_wh, 3, true);
  row("mean current [A]", ceiling.evaluation.mean_current_a, free.evaluation.mean_current_a, 3, true);
  row("FEC (flight + recharge)", ceiling.evaluation.fec, free.evaluation.fec, 6, true);
  row("lowest SOC [%]", 100 * ceiling.evaluation.min_soc, 100 * free.evaluation.min_soc, 2, false);
  row("time under the ceiling [s]", ceiling.evaluation.time_under_ceiling_s, free.evaluation.time_under_ceiling_s, 1, false);
  std::printf("\nduty projection: each mission flies the route %d times (the slower plan fills %.0f min), idles "
              "%.0f min, charges back at %.1f A; %d missions a day for %d days\n",
              repeats, a.flight_min, a.idle_min, setup.battery().pack.charge_current_a, a.missions_per_day, a.days);
  row("FEC per mission", ceiling.duty.fecPerMission(), free.duty.fecPerMission(), 4, true);
  row("FEC over the study", ceiling.duty.fecTotal(), free.duty.fecTotal(), 2, true);
  row("lowest SOC over the study [%]", 100 * ceiling.duty.minSoc(), 100 * free.duty.minSoc(), 1, false);

  nlohmann::json json;
  json["objective"] = a.planning.objective;
  json["seed"] = a.search.seed;
  json["planner"] = a.search.plannerName();
  json["duty"] = {{"flight_min", a.flight_min}, {"idle_min", a.idle_min}, {"charge_max_min", a.charge_max_min},
                  {"missions_per_day", a.missions_per_day}, {"days", a.days}};
  for (const ModeResult& m : modes) {
    nlohmann::json entry = figuresJson(m.evaluation);
    entry["cost"] = m.plan.cost;
    entry["repeats_per_mission"] = m.repeats;
    entry["fec_per_mission"] = m.duty.fecPerMission();
    entry["fec_total"] = m.duty.fecTotal();
    entry["duty_min_soc"] = m.duty.minSoc();
    json[m.name] = entry;
  }
  json["reduction_pct"] = {{"charge", reduction(ceiling.evaluation.charge_ah, free.evaluation.charge_ah)},
                           {"energy", reduction(ceiling.evaluation.energy_wh, free.evaluation.energy_wh)},
                           {"fec_total", reduction(ceiling.duty.fecTotal(), free.duty.fecTotal())}};
  const std::filesystem::path out(a.out);
  writeTextAtomically(out / "compare.json", [&](std::ostream& stream) { stream << std::setw(2) << json << '\n'; });
  std::vector<Eigen::Vector3d> routes;
  for (const ModeResult& m : modes) routes.insert(routes.end(), m.plan.waypoints.begin(), m.plan.waypoints.end());
  writeMapViews(out, setup.environment(), routes);
  std::printf("\nwrote %s/{compare.json, ceiling/, free/, map_top.csv, map_side.csv}; figures: scripts/plot-compare %s\n",
              out.c_str(), out.c_str());
}

const CommandRegistration registration(42, [](CLI::App& parent) {
  auto arguments = std::make_shared<CompareArguments>();
  CLI::App* command =
      parent.add_subcommand("compare", "Plan in ceiling and free mode, score both with the full model, project the duty");
  addPlanningOptions(command, arguments->planning);
  command->add_option("--start", arguments->start, "start body position x,y,z (m)")->required();
  command->add_option("--goal", arguments->goal, "goal body position x,y,z (m)")->required();
  addSearchOptions(command, arguments->search);
  command->add_option("--flight-min", arguments->flight_min,
                      "duty: the slower plan is repeated to fill this flight time per mission, the other flies as often (0: once)")
      ->capture_default_str()->check(nonNegativeFinite());
  command->add_option("--idle-min", arguments->idle_min, "duty: idle time after the flight")
      ->capture_default_str()->check(nonNegativeFinite());
  command->add_option("--charge-max-min", arguments->charge_max_min, "duty: longest charge back to the start SOC")
      ->capture_default_str()->check(positiveFinite());
  command->add_option("--missions-per-day", arguments->missions_per_day)->capture_default_str()->check(CLI::Range(1, 1000));
  command->add_option("--days", arguments->days)->capture_default_str()->check(CLI::Range(1, 3650));
  command->add_option("--out", arguments->out, "output directory")->required();
  command->callback([arguments] { runCompare(*arguments); });
});

}  // namespace
}  // namespace ceilplan::app
