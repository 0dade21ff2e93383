// `ceilplan plan`: one route from start to goal through a map, minimising an objective.

#include "command_registry.hpp"
#include "planning_flags.hpp"

#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/plan_files.hpp"
#include "ceilplan/io/unknown_space_report.hpp"
#include "ceilplan/mission/route_planning.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace ceilplan::app {
namespace {

struct PlanArguments {
  PlanningFlags planning;
  SearchArguments search;
  std::string start, goal, mode = "ceiling", out;
};

void runPlan(const PlanArguments& a) {
  const Eigen::Vector3d start = parsePoint(a.start, "--start"), goal = parsePoint(a.goal, "--goal");
  const mission::FlightMode mode = mission::flightModeFromName(a.mode);
  io::OutputSet out(a.out, planningInputs(a.planning));  // checked and staged before any work
  planner::seedOmpl(a.planning.options.seed);            // before anything makes an OMPL random generator
  const auto context = makePlanningContext(a.planning);
  const planner::ObjectiveChoice objective = context->objective(start, goal);
  if (objective.name == "ageing") print(io::ageingObjectiveLine(objective.ageing) + "\n");
  print("planning " + a.mode + " mode, objective " + a.planning.options.objective + ", " +
        a.search.describe(a.planning.options.seed) +
        "\nunknown space: " + io::unknownSpaceLine(context->environment()) + "\n");
  const mission::RoutePlan route = mission::planRoute(*context, mode, a.search.request(start, goal));
  io::writeRoutePlan(out.path(), route, *context, a.planning.map, a.planning.options.seed,
                     planningProvenance(a.planning, a.planning.options.seed));
  out.commit();
  print(io::routePlanText(route));
  print("wrote " + (out.finalPath() / "plan.json").string() + " and " + (out.finalPath() / "path.csv").string() + "\n");
}

const CommandRegistration registration(40, [](CLI::App& parent) {
  auto arguments = std::make_shared<PlanArguments>();
  CLI::App* command = parent.add_subcommand("plan", "Plan one route from start to goal through a map");
  addPlanningOptions(command, arguments->planning);
  command->add_option("--start", arguments->start, "start body position x,y,z (m)")->required();
  command->add_option("--goal", arguments->goal, "goal body position x,y,z (m)")->required();
  command
      ->add_option("--mode", arguments->mode,
                   "ceiling: full proximity model; free: proximity ignored, the standoff preferred")
      ->capture_default_str()
      ->check(CLI::IsMember(mission::flightModeNames()));
  addSearchOptions(command, arguments->search, arguments->planning);
  command->add_option("--out", arguments->out, "output directory (plan.json, path.csv)")->required();
  command->callback([arguments] { runPlan(*arguments); });
});

}  // namespace
}  // namespace ceilplan::app
