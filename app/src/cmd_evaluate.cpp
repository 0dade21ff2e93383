// `ceilplan evaluate`: the figures of any path (a CSV of x, y, z) under the full model, and
// whether it is safe.

#include "command_registry.hpp"
#include "output.hpp"
#include "planning_flags.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/plan_files.hpp"
#include "ceilplan/io/unknown_space_report.hpp"
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

void runEvaluate(const EvaluateArguments& a) {
  if (!a.json.empty()) io::checkWritableFile(a.json);
  const std::vector<Eigen::Vector3d> waypoints = io::readPathWaypoints(a.path);
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
  std::printf("unknown space: %s\n", io::unknownSpaceLine(context->environment()).c_str());
  if (!a.json.empty()) {
    nlohmann::json out = io::figuresJson(check.evaluation);
    out["valid"] = !check.violation;
    out["violation"] = check.violation ? nlohmann::json(*check.violation) : nlohmann::json(nullptr);
    out["objective"] = a.planning.options.objective;
    out["cost"] = check.cost;
    out["cost_unit"] = check.cost_unit;
    out["waypoints"] = io::waypointsJson(waypoints);
    out["unknown_space"] = io::unknownSpaceJson(context->environment());
    io::Provenance provenance = planningProvenance(a.planning, std::nullopt);
    provenance.input("path", a.path);
    out["provenance"] = provenance.json();
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
