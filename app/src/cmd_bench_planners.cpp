// `ceilplan bench-planners`: OMPL's benchmark harness on one query, every planner from the one
// factory (OMPL's and the lattice ones), with ceilplan's objective cost logged per run (raw and
// post-processed) and compared with the lattice reference.

#include "cli_checks.hpp"
#include "command_registry.hpp"
#include "output.hpp"
#include "planning_flags.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/io/atomic_file.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/report_json.hpp"
#include "ceilplan/io/report_text.hpp"
#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/planner_benchmark.hpp"

#include <CLI/CLI.hpp>

#include <sstream>
#include <string>
#include <vector>

namespace ceilplan::app {
namespace {

struct BenchArguments {
  PlanningFlags planning;
  SearchArguments search;
  std::string start, goal, planners = planner::plannerList(planner::samplingPlannerNames());
  std::string mode = "ceiling";
  unsigned runs = 10;
  std::string json, log;
};

void runBench(const BenchArguments& a) {
  const Eigen::Vector3d start = parsePoint(a.start, "--start"), goal = parsePoint(a.goal, "--goal");
  // Checked and staged before the runs; the table and the log appear together or not at all.
  io::OutputSet out({{"--json", a.json}, {"--log", a.log}}, planningInputs(a.planning));
  planner::PlannerBenchmarkOptions options;
  options.planners = planner::plannerNamesOfList(a.planners);
  options.runs = a.runs;
  options.time_limit_s = a.search.time_limit_s;
  options.band_fraction = a.search.band_fraction;
  options.refine = !a.search.no_refine;
  options.experiment = "ceilplan " + a.planning.map;
  std::ostringstream log;
  if (!a.log.empty()) options.log = &log;
  try {
    options.validate();  // the other fields are range-checked as flags
  } catch (const InputError&) {
    rethrowWithContext("--planners: ");
  }
  planner::seedOmpl(a.planning.options.seed);
  const auto context = makePlanningContext(a.planning);
  const io::Provenance provenance = planningProvenance(a.planning, a.planning.options.seed);  // the inputs read, named
  for (const auto& [name, value] : provenance.fields())
    options.log_properties.emplace_back("provenance_" + name, value);
  const mission::PlanningContext::Mode planning = context->mode(mission::flightModeFromName(a.mode));
  const planner::FlightPlanner flight_planner(*planning.rules, *planning.model, context->objective(start, goal));
  print(io::plannerBenchmarkHeadline(a.mode, a.planning.options.objective, flight_planner.objective().unit(), options,
                                     a.planning.options.seed));

  const planner::PlanRequest request = a.search.request(start, goal);
  const planner::PlanResult reference = planner::planLatticeReference(flight_planner, request);
  print(io::latticeReferenceLine(reference, request.lattice.spacing_m));

  options.lattice = request.lattice;
  const std::vector<planner::PlannerBenchmarkRow> rows =
      planner::benchmarkPlanners(flight_planner, start, goal, reference, options);
  print(io::plannerBenchmarkTable(rows, a.search.time_limit_s));
  if (!a.json.empty())
    io::writeJsonFile(
        out.path("--json"),
        io::withProvenance(io::plannerBenchmarkJson(reference, a.search.lattice_spacing_m, rows), provenance));
  if (!a.log.empty()) io::writeTextAtomically(out.path("--log"), [&](std::ostream& file) { file << log.str(); });
  out.commit();
}

const CommandRegistration registration(43, [](CLI::App& parent) {
  auto arguments = std::make_shared<BenchArguments>();
  CLI::App* command = parent.add_subcommand(
      "bench-planners", "Benchmark planners on one query against the lattice reference (ompl::tools::Benchmark)");
  addPlanningOptions(command, arguments->planning);
  command->add_option("--start", arguments->start, "start body position x,y,z (m)")->required();
  command->add_option("--goal", arguments->goal, "goal body position x,y,z (m)")->required();
  command->add_option("--mode", arguments->mode)->capture_default_str()->check(CLI::IsMember({"ceiling", "free"}));
  addSearchOptions(command, arguments->search, arguments->planning);
  command->add_option("--planners", arguments->planners, "comma-separated planner names (lattice and roadmap too)")
      ->capture_default_str();
  command->add_option("--runs", arguments->runs, "runs per planner")
      ->capture_default_str()
      ->check(CLI::Range(1u, 10000u));
  command->add_option("--json", arguments->json, "write the table as JSON");
  command->add_option("--log", arguments->log, "write OMPL's benchmark log (ompl_benchmark_statistics format)");
  command->callback([arguments] { runBench(*arguments); });
});

}  // namespace
}  // namespace ceilplan::app
