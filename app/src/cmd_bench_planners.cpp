// `ceilplan bench-planners`: OMPL's benchmark harness on one query, every planner from the one
// factory (OMPL's and the lattice ones), with ceilplan's objective cost logged per run (raw and
// post-processed) and compared with the lattice reference.

#include "cli_checks.hpp"
#include "command_registry.hpp"
#include "output.hpp"
#include "planning_flags.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/report_json.hpp"
#include "ceilplan/io/report_text.hpp"
#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/planner_benchmark.hpp"
#include "ceilplan/planner/planner_factory.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace ceilplan::app {
namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ",") + name;
  return list;
}

struct BenchArguments {
  PlanningFlags planning;
  SearchArguments search;
  std::string start, goal, planners = joined(planner::samplingPlannerNames());
  std::string mode = "ceiling";
  unsigned runs = 10;
  std::string json, log;
};

std::vector<std::string> splitNames(const std::string& list) {
  std::vector<std::string> names;
  std::stringstream in(list);
  for (std::string name; std::getline(in, name, ',');)
    if (!name.empty()) names.push_back(name);
  return names;
}

void runBench(const BenchArguments& a) {
  const Eigen::Vector3d start = parsePoint(a.start, "--start"), goal = parsePoint(a.goal, "--goal");
  if (!a.json.empty()) io::checkWritableFile(a.json);  // before the runs
  if (!a.log.empty()) io::checkWritableFile(a.log);
  planner::PlannerBenchmarkOptions options;
  options.planners = splitNames(a.planners);
  options.runs = a.runs;
  options.time_limit_s = a.search.time_limit_s;
  options.band_fraction = a.search.band_fraction;
  options.refine = !a.search.no_refine;
  options.experiment = "ceilplan " + a.planning.map;
  options.log_file = a.log;
  try {
    options.validate();  // the other fields are range-checked as flags
  } catch (const InputError&) {
    rethrowWithContext("--planners: ");
  }
  planner::seedOmpl(a.search.seed);
  const auto context = makePlanningContext(a.planning);
  const mission::PlanningContext::Mode planning = context->mode(mission::flightModeFromName(a.mode));
  const planner::FlightPlanner flight_planner(*planning.rules, *planning.model, context->objective(start, goal));
  std::printf("bench-planners: %s mode, objective %s (%s), %u runs of %.1f s per planner, seed %u\n", a.mode.c_str(),
              a.planning.options.objective.c_str(), flight_planner.objective().unit().c_str(), a.runs,
              a.search.time_limit_s, a.search.seed);

  // The reference: the lattice optimum, post-processed like every other path.
  planner::PlanRequest reference_request = a.search.request(start, goal);
  reference_request.planner = planner::referencePlannerName();
  planner::PlanResult reference;
  try {
    reference = flight_planner.plan(reference_request);
  } catch (const ceilplan::NoPathError&) {
    rethrowWithContext("lattice reference: ");
  }
  std::printf("lattice reference (spacing %s m): %.6g raw, %.6g post-processed, %.1f s\n",
              formatNumber(a.search.lattice_spacing_m).c_str(), reference.search_cost, reference.cost,
              reference.total_time_s);
  std::fflush(stdout);

  options.lattice = reference_request.lattice;
  const std::vector<planner::PlannerBenchmarkRow> rows =
      planner::benchmarkPlanners(flight_planner, start, goal, reference, options);
  std::cout << io::plannerBenchmarkTable(rows, a.search.time_limit_s);
  if (!a.json.empty()) io::writeJsonFile(a.json, io::plannerBenchmarkJson(reference, a.search.lattice_spacing_m, rows));
}

const CommandRegistration registration(43, [](CLI::App& parent) {
  auto arguments = std::make_shared<BenchArguments>();
  CLI::App* command = parent.add_subcommand(
      "bench-planners", "Benchmark planners on one query against the lattice reference (ompl::tools::Benchmark)");
  addPlanningOptions(command, arguments->planning);
  command->add_option("--start", arguments->start, "start body position x,y,z (m)")->required();
  command->add_option("--goal", arguments->goal, "goal body position x,y,z (m)")->required();
  command->add_option("--mode", arguments->mode)->capture_default_str()->check(CLI::IsMember({"ceiling", "free"}));
  addSearchOptions(command, arguments->search);
  command->add_option("--planners", arguments->planners, "comma-separated planner names (lattice and roadmap too)")
      ->capture_default_str();
  command->add_option("--runs", arguments->runs, "runs per planner")->capture_default_str()->check(CLI::Range(1u, 10000u));
  command->add_option("--json", arguments->json, "write the table as JSON");
  command->add_option("--log", arguments->log, "write OMPL's benchmark log (ompl_benchmark_statistics format)");
  command->callback([arguments] { runBench(*arguments); });
});

}  // namespace
}  // namespace ceilplan::app
