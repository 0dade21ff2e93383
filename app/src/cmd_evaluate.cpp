// `ceilplan evaluate`: the figures of any path (a CSV of x, y, z) under the full model, and
// whether it is safe.

#include "command_registry.hpp"
#include "planning_flags.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/plan_files.hpp"
#include "ceilplan/mission/route_planning.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>

namespace ceilplan::app {
namespace {

struct EvaluateArguments {
  PlanningFlags planning;
  std::string path;
  std::string json;
};

void runEvaluate(const EvaluateArguments& a) {
  std::vector<io::Input> inputs = planningInputs(a.planning);
  inputs.push_back({"--path", a.path});
  io::OutputSet out({{"--json", a.json}}, inputs);
  const std::vector<Eigen::Vector3d> waypoints = io::readPathWaypoints(a.path);
  const auto context = makePlanningContext(a.planning);
  mission::RouteCheck check;
  try {
    check = mission::checkRoute(*context, waypoints);
  } catch (...) {
    rethrowWithContext(a.path + ": ");
  }
  std::printf("%s", io::routeCheckText(check, waypoints.size(), *context).c_str());
  if (a.json.empty()) return;
  io::Provenance provenance = planningProvenance(a.planning, std::nullopt);
  provenance.input("path", a.path);
  io::writeJsonFile(out.path("--json"), io::routeCheckJson(check, waypoints, *context, provenance));
  out.commit();
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
