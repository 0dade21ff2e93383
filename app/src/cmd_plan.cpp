// `ceilplan plan`: one route from start to goal through a map, minimising an objective.

#include "command_registry.hpp"
#include "planning_flags.hpp"

#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/plan_files.hpp"
#include "ceilplan/io/unknown_space_report.hpp"
#include "ceilplan/mission/route_planning.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
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
  io::OutputSet out(a.out);  // checked and staged before any work
  planner::seedOmpl(a.search.seed);  // before anything makes an OMPL random generator
  const auto context = makePlanningContext(a.planning);
  const planner::ObjectiveChoice objective = context->objective(start, goal);
  if (objective.name == "ageing")
    std::printf("ageing objective: %s model at %.1f %% depth of discharge: %.4g per Ah, %.4g per s of capacity\n",
                objective.ageing.model.c_str(), 100 * objective.ageing.depth_of_discharge, objective.ageing.loss_per_ah,
                objective.ageing.loss_per_s);
  std::printf("planning %s mode, objective %s, %s\nunknown space: %s\n", a.mode.c_str(),
              a.planning.options.objective.c_str(), a.search.describe().c_str(),
              io::unknownSpaceLine(context->environment()).c_str());
  std::fflush(stdout);
  const mission::RoutePlan route = mission::planRoute(*context, mode, a.search.request(start, goal));
  nlohmann::json extra{{"seed", a.search.seed},
                       {"objective", a.planning.options.objective},
                       {"cost_unit", route.cost_unit},
                       {"mode", a.mode},
                       {"map", a.planning.map},
                       {"vehicle", context->vehicle().name},
                       {"battery", context->battery().description},
                       {"start_soc", context->battery().start_soc},
                       {"unknown_space", io::unknownSpaceJson(context->environment())}};
  if (route.standoff) extra["standoff"] = io::standoffJson(*route.standoff);
  if (objective.name == "ageing")
    extra["ageing"] = {{"model", objective.ageing.model},
                       {"depth_of_discharge", objective.ageing.depth_of_discharge},
                       {"loss_per_ah", objective.ageing.loss_per_ah},
                       {"loss_per_s", objective.ageing.loss_per_s}};
  io::writePlanDirectory(out.path(), route.plan, route.evaluation, extra, planningProvenance(a.planning, a.search.seed));
  out.commit();
  std::printf("%zu waypoints; cost %.6g %s (search %.6g) after %.2f s\n%s\n", route.plan.waypoints.size(),
              route.plan.cost, route.cost_unit.c_str(), route.plan.search_cost, route.plan.total_time_s,
              io::figuresLine(route.evaluation).c_str());
  if (route.standoff) std::printf("%s\n", io::standoffLine(*route.standoff).c_str());
  std::printf("wrote %s and %s\n", (out.finalPath() / "plan.json").c_str(), (out.finalPath() / "path.csv").c_str());
}

const CommandRegistration registration(40, [](CLI::App& parent) {
  auto arguments = std::make_shared<PlanArguments>();
  CLI::App* command = parent.add_subcommand("plan", "Plan one route from start to goal through a map");
  addPlanningOptions(command, arguments->planning);
  command->add_option("--start", arguments->start, "start body position x,y,z (m)")->required();
  command->add_option("--goal", arguments->goal, "goal body position x,y,z (m)")->required();
  command->add_option("--mode", arguments->mode, "ceiling: full proximity model; free: proximity ignored, the standoff preferred")
      ->capture_default_str()
      ->check(CLI::IsMember(mission::flightModeNames()));
  addSearchOptions(command, arguments->search);
  command->add_option("--out", arguments->out, "output directory (plan.json, path.csv)")->required();
  command->callback([arguments] { runPlan(*arguments); });
});

}  // namespace
}  // namespace ceilplan::app
