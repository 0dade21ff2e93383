// `ceilplan evaluate`: the figures of any path (a CSV of x, y, z) under the full model, and
// whether it is safe.

#include "command_registry.hpp"
#include "csv_table.hpp"
#include "output.hpp"
#include "plan_output.hpp"
#include "planning_setup.hpp"

#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/path_evaluation.hpp"
#include "ceilplan/core/error.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iomanip>
#include <iostream>
#include <string>

namespace ceilplan::app {
namespace {

struct EvaluateArguments {
  PlanningArguments planning;
  std::string path;
  std::string json;
};

// The rows of x, y, z; a point repeated on consecutive rows (path.csv's segment joints) once.
std::vector<Eigen::Vector3d> readWaypoints(const std::string& file) {
  const CsvTable table = CsvTable::read(file);
  const std::vector<double>&x = table.column("x"), &y = table.column("y"), &z = table.column("z");
  std::vector<Eigen::Vector3d> waypoints;
  for (std::size_t row = 0; row < table.rowCount(); ++row) {
    const Eigen::Vector3d p(x[row], y[row], z[row]);
    if (waypoints.empty() || (p - waypoints.back()).norm() > 1e-9) waypoints.push_back(p);
  }
  if (waypoints.size() < 2) throw ceilplan::InputError(file + ": a path needs at least 2 distinct points");
  return waypoints;
}

void runEvaluate(const EvaluateArguments& a) {
  const std::vector<Eigen::Vector3d> waypoints = readWaypoints(a.path);
  const PlanningSetup setup(a.planning);
  for (std::size_t k = 0; k < waypoints.size(); ++k)
    if (!setup.environment().contains(waypoints[k]))
      throw ceilplan::InputError(a.path + ": point " + std::to_string(k + 1) + " lies outside the map");
  const std::optional<std::string> problem = setup.baseRules().checkPathDensely(waypoints);
  const planner::PathEvaluation evaluation =
      planner::evaluatePath(setup.fullModel(), setup.battery().pack, setup.battery().start_soc, waypoints);
  const planner::FlightPlanner scorer(setup.baseRules(), setup.fullModel(),
                                      setup.objective(waypoints.front(), waypoints.back()));
  const double cost = scorer.objective().weights().of(evaluation.totals());

  std::printf("%zu points: %s\n%s cost %.6g %s\nvalid: %s\n", waypoints.size(), figuresLine(evaluation).c_str(),
              a.planning.objective.c_str(), cost, scorer.objective().unit().c_str(), problem ? "false" : "true");
  if (problem) std::printf("violation: %s\n", problem->c_str());
  if (!a.json.empty()) {
    nlohmann::json out = figuresJson(evaluation);
    out["valid"] = !problem;
    out["violation"] = problem ? nlohmann::json(*problem) : nlohmann::json(nullptr);
    out["objective"] = a.planning.objective;
    out["cost"] = cost;
    out["cost_unit"] = scorer.objective().unit();
    out["waypoints"] = waypointsJson(waypoints);
    writeTextAtomically(a.json, [&](std::ostream& stream) { stream << std::setw(2) << out << '\n'; });
  }
}

const CommandRegistration registration(41, [](CLI::App& parent) {
  auto arguments = std::make_shared<EvaluateArguments>();
  CLI::App* command = parent.add_subcommand("evaluate", "Figures and safety of any path under the full model");
  addPlanningOptions(command, arguments->planning);
  command->add_option("--path", arguments->path, "CSV with columns x, y, z (others ignored), one row per point")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--json", arguments->json, "also write the figures here");
  command->callback([arguments] { runEvaluate(*arguments); });
});

}  // namespace
}  // namespace ceilplan::app
