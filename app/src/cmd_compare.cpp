// `ceilplan compare`: the same query planned in ceiling mode and in free mode, both scored with
// the full model, with each plan's month-long duty projection (the founding paper's study).

#include "cli_checks.hpp"
#include "command_registry.hpp"
#include "planning_flags.hpp"

#include "ceilplan/core/install_paths.hpp"
#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/plan_files.hpp"
#include "ceilplan/io/unknown_space_report.hpp"
#include "ceilplan/mission/route_planning.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace ceilplan::app {
namespace {

struct CompareArguments {
  PlanningFlags planning;
  SearchArguments search;
  std::string start, goal, out;
  mission::DutyOptions duty;
};

void runCompare(const CompareArguments& a) {
  const Eigen::Vector3d start = parsePoint(a.start, "--start"), goal = parsePoint(a.goal, "--goal");
  io::OutputSet out(a.out, planningInputs(a.planning));  // checked and staged before any work
  planner::seedOmpl(a.planning.options.seed);
  const auto context = makePlanningContext(a.planning);
  print("comparing ceiling and free modes: objective " + a.planning.options.objective + ", " +
        a.search.describe(a.planning.options.seed) +
        "\nunknown space: " + io::unknownSpaceLine(context->environment()) + "\n");
  const mission::RouteComparison comparison = mission::compareRoutes(*context, a.search.request(start, goal), a.duty);
  if (comparison.ceiling.plan.from_candidate)
    print("ceiling mode found nothing better than the free-mode route: it flies that route, post-processed\n");
  print("\n" + io::routeComparisonTable(comparison, a.duty, context->battery()));
  if (comparison.free.standoff) print("\nfree mode's " + io::standoffLine(*comparison.free.standoff) + "\n");
  io::writeRouteComparison(out.path(), comparison, a.duty, *context, a.search.plannerName(), a.planning.options.seed,
                           planningProvenance(a.planning, a.planning.options.seed));
  out.commit();
  print("\nwrote " + a.out + "/{compare.json, ceiling/, free/, map_top.csv, map_side.csv}; figures: " +
        plotCommand("plot-compare") + " " + a.out + "\n");
}

const CommandRegistration registration(42, [](CLI::App& parent) {
  auto arguments = std::make_shared<CompareArguments>();
  CLI::App* command = parent.add_subcommand(
      "compare", "Plan in ceiling and free mode, score both with the full model, project the duty");
  addPlanningOptions(command, arguments->planning);
  command->add_option("--start", arguments->start, "start body position x,y,z (m)")->required();
  command->add_option("--goal", arguments->goal, "goal body position x,y,z (m)")->required();
  addSearchOptions(command, arguments->search, arguments->planning);
  mission::DutyOptions& duty = arguments->duty;
  command
      ->add_option(
          "--flight-min", duty.flight_min,
          "duty: the slower plan is repeated to fill this flight time per mission (up to a day), the other flies as "
          "often (0: once)")
      ->capture_default_str()
      ->check(nonNegativeFinite() & atMost(mission::DutyOptions::kMaxMinutes));
  command->add_option("--idle-min", duty.idle_min, "duty: idle time after the flight, up to a day")
      ->capture_default_str()
      ->check(nonNegativeFinite() & atMost(mission::DutyOptions::kMaxMinutes));
  command
      ->add_option("--charge-max-min", duty.charge_max_min, "duty: longest charge back to the start SOC, up to a day")
      ->capture_default_str()
      ->check(positiveFinite() & atMost(mission::DutyOptions::kMaxMinutes));
  command->add_option("--missions-per-day", duty.missions_per_day)->capture_default_str()->check(CLI::Range(1, 1000));
  command->add_option("--days", duty.days)->capture_default_str()->check(CLI::Range(1, 3650));
  command->add_option("--out", arguments->out, "output directory")->required();
  command->callback([arguments] { runCompare(*arguments); });
});

}  // namespace
}  // namespace ceilplan::app
