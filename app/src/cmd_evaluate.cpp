// `ceilplan evaluate`: the figures of any path (a CSV of x, y, z) under the full model, and
// whether it is safe.

#include "command_registry.hpp"
#include "csv_table.hpp"
#include "output.hpp"
#include "planning_flags.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/io/plan_files.hpp"
#include "ceilplan/mission/route_planning.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iomanip>
#include <iostream>
#include <string>

namespace ceilplan::app {
namespace {

struct EvaluateArguments {
  PlanningFlags planning;
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
  const auto context = makePlanningContext(a.planning);
  mission::RouteCheck check;
  try {
    check = mission::checkRoute(*context, waypoints);
  } catch (...) {
    rethrowWithContext(a.path + ": ");
  }
  std::printf("%zu points: %s\n%s cost %.6g %s\nvalid: %s\n", waypoints.size(), io::figuresLine(check.evaluation).c_str(),
              a.planning.options.objective.c_str(), check.cost, check.cost_unit.c_str(), check.violation ? "false" : "true");
  if (check.violation) std::printf("violation: %s\n", check.violation->c_str());
  if (!a.json.empty()) {
    nlohmann::json out = io::figuresJson(check.evaluation);
    out["valid"] = !check.violation;
    out["violation"] = check.violation ? nlohmann::json(*check.violation) : nlohmann::json(nullptr);
    out["objective"] = a.planning.options.objective;
    out["cost"] = check.cost;
    out["cost_unit"] = check.cost_unit;
    out["waypoints"] = io::waypointsJson(waypoints);
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
