// `ceilplan plan`: one route from start to goal through a map, minimising an objective.

#include "command_registry.hpp"
#include "errors.hpp"
#include "plan_output.hpp"
#include "planning_setup.hpp"

#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/path_evaluation.hpp"
#include "ceilplan/core/error.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <string>

namespace ceilplan::app {
namespace {

struct PlanArguments {
  PlanningArguments planning;
  SearchArguments search;
  std::string start, goal, mode = "ceiling", out;
};

void runPlan(const PlanArguments& a) {
  const Eigen::Vector3d start = parsePoint(a.start, "--start"), goal = parsePoint(a.goal, "--goal");
  const PlanningMode mode = modeFromName(a.mode);
  planner::seedOmpl(a.search.seed);  // before anything makes an OMPL random generator
  const PlanningSetup setup(a.planning);
  const PlanningSetup::Mode planning = setup.mode(mode, start, goal);
  const planner::ObjectiveChoice objective = setup.objective(start, goal);
  const planner::FlightPlanner flight_planner(*planning.rules, *planning.model, objective);
  if (objective.name == "ageing")
    std::printf("ageing objective: %s model at %.1f %% depth of discharge: %.4g per Ah, %.4g per s of capacity\n",
                objective.ageing.model.c_str(), 100 * objective.ageing.depth_of_discharge, objective.ageing.loss_per_ah,
                objective.ageing.loss_per_s);
  std::printf("planning %s mode, objective %s, planner %s, seed %u, %.1f s\n", a.mode.c_str(),
              a.planning.objective.c_str(), a.search.plannerName().c_str(), a.search.seed, a.search.time_limit_s);
  std::fflush(stdout);
  planner::PlanResult result;
  try {
    result = flight_planner.plan(a.search.request(start, goal));
  } catch (const ceilplan::NoPathError& e) {
    throw NoPathError(e.what());
  }
  // Every figure comes from the full model with the SOC integrated along the path.
  const planner::PathEvaluation evaluation =
      planner::evaluatePath(setup.fullModel(), setup.battery().pack, setup.battery().start_soc, result.waypoints);
  nlohmann::json extra{{"seed", a.search.seed},
                             {"objective", a.planning.objective},
                             {"cost_unit", flight_planner.objective().unit()},
                             {"mode", a.mode},
                             {"map", a.planning.map},
                             {"vehicle", setup.vehicleName()},
                             {"battery", setup.battery().source},
                             {"start_soc", setup.battery().start_soc}};
  if (objective.name == "ageing")
    extra["ageing"] = {{"model", objective.ageing.model},
                       {"depth_of_discharge", objective.ageing.depth_of_discharge},
                       {"loss_per_ah", objective.ageing.loss_per_ah},
                       {"loss_per_s", objective.ageing.loss_per_s}};
  const std::filesystem::path out(a.out);
  writePlanDirectory(out, result, evaluation, extra);
  std::printf("%zu waypoints; cost %.6g %s (search %.6g) after %.2f s\n%s\nwrote %s and %s\n", result.waypoints.size(),
              result.cost, flight_planner.objective().unit().c_str(), result.search_cost, result.total_time_s,
              figuresLine(evaluation).c_str(), (out / "plan.json").c_str(), (out / "path.csv").c_str());
}

const CommandRegistration registration(40, [](CLI::App& parent) {
  auto arguments = std::make_shared<PlanArguments>();
  CLI::App* command = parent.add_subcommand("plan", "Plan one route from start to goal through a map");
  addPlanningOptions(command, arguments->planning);
  command->add_option("--start", arguments->start, "start body position x,y,z (m)")->required();
  command->add_option("--goal", arguments->goal, "goal body position x,y,z (m)")->required();
  command->add_option("--mode", arguments->mode, "ceiling: full proximity model; free: proximity ignored, standoff kept")
      ->capture_default_str()
      ->check(CLI::IsMember({"ceiling", "free"}));
  addSearchOptions(command, arguments->search);
  command->add_option("--out", arguments->out, "output directory (plan.json, path.csv)")->required();
  command->callback([arguments] { runPlan(*arguments); });
});

}  // namespace
}  // namespace ceilplan::app
