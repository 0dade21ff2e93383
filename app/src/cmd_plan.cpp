// `ceilplan plan`: one route from start to goal through a map, minimising an objective.

#include "cli_checks.hpp"
#include "command_registry.hpp"
#include "errors.hpp"
#include "output.hpp"
#include "plan_output.hpp"
#include "planning_setup.hpp"

#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/path_evaluation.hpp"
#include "ceilplan/planner/planner_factory.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iomanip>
#include <string>

namespace ceilplan::app {
namespace {

struct PlanArguments {
  PlanningArguments planning;
  std::string start, goal, mode = "ceiling", planner, out;
  double time_limit_s = 5.0;
  std::uint32_t seed = 1;
  double band_fraction = 0.5;
  bool no_refine = false;
  int lattice_stride = 2;
};

void runPlan(const PlanArguments& a) {
  const Eigen::Vector3d start = parsePoint(a.start, "--start"), goal = parsePoint(a.goal, "--goal");
  const PlanningMode mode = modeFromName(a.mode);
  planner::seedOmpl(a.seed);  // before anything makes an OMPL random generator
  const PlanningSetup setup(a.planning);
  const PlanningSetup::Mode planning = setup.mode(mode, start, goal);
  const planner::FlightPlanner flight_planner(*planning.rules, *planning.model, setup.objective(start, goal));

  planner::PlanRequest request;
  request.start_m = start;
  request.goal_m = goal;
  request.planner = a.planner;
  request.time_limit_s = a.time_limit_s;
  request.band_fraction = a.band_fraction;
  request.refine = !a.no_refine;
  request.lattice.stride_voxels = a.lattice_stride;
  std::printf("planning %s mode, objective %s, planner %s, seed %u, %.1f s\n", a.mode.c_str(),
              a.planning.objective.c_str(), (a.planner.empty() ? planner::defaultPlannerName() : a.planner).c_str(),
              a.seed, a.time_limit_s);
  std::fflush(stdout);
  planner::PlanResult result;
  try {
    result = flight_planner.plan(request);
  } catch (const planner::NoPathFound& e) {
    throw NoPathError(e.what());
  }
  // Every figure comes from the full model with the SOC integrated along the path.
  const planner::PathEvaluation evaluation =
      planner::evaluatePath(setup.fullModel(), setup.battery().pack, setup.battery().start_soc, result.waypoints);

  nlohmann::json plan = figuresJson(evaluation);
  plan["waypoints"] = waypointsJson(result.waypoints);
  plan["planner"] = result.planner;
  plan["seed"] = a.seed;
  plan["objective"] = a.planning.objective;
  plan["cost"] = result.cost;
  plan["cost_unit"] = flight_planner.objective().unit();
  plan["search_cost"] = result.search_cost;
  plan["mode"] = a.mode;
  plan["map"] = a.planning.map;
  plan["vehicle"] = setup.vehicleName();
  plan["battery"] = setup.battery().source;
  plan["start_soc"] = setup.battery().start_soc;
  plan["search_time_s"] = result.search_time_s;
  plan["total_time_s"] = result.total_time_s;
  const std::filesystem::path out(a.out);
  writeTextAtomically(out / "plan.json", [&](std::ostream& stream) { stream << std::setw(2) << plan << '\n'; });
  writePathCsv(out / "path.csv", evaluation);
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
  command->add_option("--planner", arguments->planner, "planner (default " + planner::defaultPlannerName() + ")")
      ->check(CLI::IsMember(planner::plannerNames()));
  command->add_option("--time-limit-s", arguments->time_limit_s, "search time")->capture_default_str()->check(positiveFinite());
  command->add_option("--seed", arguments->seed, "random seed (> 0)")->capture_default_str()->check(CLI::Range(1u, 4294967295u));
  command->add_option("--band-fraction", arguments->band_fraction, "share of samples aimed under ceilings")
      ->capture_default_str()->check(CLI::Range(0.0, 1.0));
  command->add_flag("--no-refine", arguments->no_refine, "skip shortcutting and NLopt refinement");
  command->add_option("--lattice-stride", arguments->lattice_stride, "lattice planner: spacing in voxels")
      ->capture_default_str()->check(CLI::Range(1, 16));
  command->add_option("--out", arguments->out, "output directory (plan.json, path.csv)")->required();
  command->callback([arguments] { runPlan(*arguments); });
});

}  // namespace
}  // namespace ceilplan::app
