// `ceilplan bench-planners`: OMPL's benchmark harness on one query, every planner from the one
// factory (OMPL's and the lattice ones), with ceilplan's objective cost logged per run (raw and
// post-processed) and compared with the lattice reference.

#include "cli_checks.hpp"
#include "command_registry.hpp"
#include "output.hpp"
#include "planning_flags.hpp"

#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/ompl_state.hpp"
#include "ceilplan/planner/planner_factory.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/tools/benchmark/Benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

namespace ceilplan::app {
namespace {

constexpr double kNotReached = std::numeric_limits<double>::infinity();

// OMPL's sampling planners, comma-separated: the default list.
std::string samplingPlanners() {
  std::string list;
  for (const planner::PlannerInfo& info : planner::plannerCatalogue())
    if (info.kind == planner::PlannerKind::Sampling) list += (list.empty() ? "" : ",") + info.name;
  return list;
}

struct BenchArguments {
  PlanningFlags planning;
  SearchArguments search;
  std::string start, goal, planners = samplingPlanners();
  std::string mode = "ceiling";
  unsigned runs = 10;
  double reference_time_limit_s = 600.0;
  std::string json, log;
};

double median(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double number(const std::map<std::string, std::string>& run, const std::string& key) {
  const auto found = run.find(key);
  if (found == run.end() || found->second.empty()) return std::numeric_limits<double>::quiet_NaN();
  try {
    return std::stod(found->second);
  } catch (const std::exception&) {
    return std::numeric_limits<double>::quiet_NaN();  // OMPL writes "inf" or "nan" for no solution
  }
}

std::vector<std::string> splitNames(const std::string& list) {
  std::vector<std::string> names;
  std::stringstream in(list);
  for (std::string name; std::getline(in, name, ',');)
    if (!name.empty()) names.push_back(name);
  if (names.empty()) throw ceilplan::InputError("--planners: give at least one planner name");
  return names;
}

std::string text(double value, int decimals) {
  if (std::isnan(value)) return "-";
  if (std::isinf(value)) return "never";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

void runBench(const BenchArguments& a) {
  const Eigen::Vector3d start = parsePoint(a.start, "--start"), goal = parsePoint(a.goal, "--goal");
  if (!a.json.empty()) checkWritableFile(a.json);  // before the runs
  if (!a.log.empty()) checkWritableFile(a.log);
  const std::vector<std::string> names = splitNames(a.planners);
  for (const std::string& name : names) {
    try {
      planner::plannerInfo(name);
    } catch (const ceilplan::InputError& e) {
      throw ceilplan::InputError(std::string("--planners: ") + e.what());
    }
  }
  planner::seedOmpl(a.search.seed);
  const auto context = makePlanningContext(a.planning);
  const mission::PlanningContext::Mode planning = context->mode(mission::flightModeFromName(a.mode));
  const planner::FlightPlanner flight_planner(*planning.rules, *planning.model, context->objective(start, goal));
  const planner::FlightObjective& objective = flight_planner.objective();
  std::printf("bench-planners: %s mode, objective %s (%s), %u runs of %.1f s per planner, seed %u\n", a.mode.c_str(),
              a.planning.options.objective.c_str(), objective.unit().c_str(), a.runs, a.search.time_limit_s, a.search.seed);

  // The reference: the lattice optimum, post-processed like every other path.
  planner::PlanRequest reference_request = a.search.request(start, goal);
  reference_request.planner = planner::referencePlannerName();
  reference_request.time_limit_s = a.reference_time_limit_s;
  planner::PlanResult reference;
  try {
    reference = flight_planner.plan(reference_request);
  } catch (const ceilplan::NoPathError& e) {
    throw NoPathError(std::string("lattice reference: ") + e.what());
  }
  std::printf("lattice reference (spacing %s m): %.6g raw, %.6g post-processed, %.1f s\n",
              formatNumber(a.search.lattice_spacing_m).c_str(), reference.search_cost, reference.cost,
              reference.total_time_s);
  std::fflush(stdout);

  ompl::geometric::SimpleSetup simple(flight_planner.spaceInformation());
  ompl::base::ScopedState<> start_state(simple.getSpaceInformation()), goal_state(simple.getSpaceInformation());
  planner::setPosition(start_state.get(), start);
  planner::setPosition(goal_state.get(), goal);
  simple.setStartAndGoalStates(start_state, goal_state, 1e-6);
  simple.setOptimizationObjective(flight_planner.objectivePtr());
  flight_planner.installBandSampler(a.search.band_fraction);
  ompl::tools::Benchmark benchmark(simple, "ceilplan " + a.planning.map);
  for (const std::string& name : names)
    benchmark.addPlanner(planner::makePlanner(name, simple.getSpaceInformation(), reference_request.lattice));
  // OMPL's logs have no column for our objective: add the raw and post-processed costs.
  planner::RefinementOptions refinement;
  benchmark.setPostRunEvent([&](const ompl::base::PlannerPtr& p, ompl::tools::Benchmark::RunProperties& run) {
    const auto definition = p->getProblemDefinition();
    if (!definition->hasExactSolution()) return;
    std::vector<Eigen::Vector3d> raw;
    for (const ompl::base::State* s : definition->getSolutionPath()->as<ompl::geometric::PathGeometric>()->getStates())
      raw.push_back(planner::toPosition(s));
    const std::vector<Eigen::Vector3d> final_path = flight_planner.postProcess(raw, refinement, !a.search.no_refine);
    run["ceilplan raw cost REAL"] = formatNumber(objective.pathCost(raw), 17);
    run["ceilplan cost REAL"] = formatNumber(objective.pathCost(final_path), 17);
  });
  ompl::tools::Benchmark::Request request(a.search.time_limit_s, 4096.0, a.runs, 0.05, false, false, false);
  benchmark.benchmark(request);
  flight_planner.clearBandSampler();
  if (!a.log.empty())
    writeAtomically(a.log, [&](const std::filesystem::path& temporary) {
      if (!benchmark.saveResultsToFile(temporary.c_str())) throw Error("cannot write " + a.log);
    });

  std::printf("\n%-16s %7s %11s %12s %12s %12s %13s\n", "planner", "solved", "first [s]", "raw / ref", "final / ref",
              "best final", "to 5 % [s]");
  nlohmann::json json;
  json["reference"] = {{"planner", planner::referencePlannerName()},
                       {"spacing_m", a.search.lattice_spacing_m},
                       {"time_s", reference.total_time_s},
                       {"raw_cost", reference.search_cost}, {"cost", reference.cost}};
  json["planners"] = nlohmann::json::array();
  for (const auto& experiment : benchmark.getRecordedExperimentData().planners) {
    std::vector<double> raw_ratio, final_ratio, first_s, reach_s;
    int solved = 0;
    std::string best_key;
    for (const std::string& key : experiment.progressPropertyNames)
      if (key.rfind("best cost", 0) == 0) best_key = key;
    for (std::size_t r = 0; r < experiment.runs.size(); ++r) {
      const auto& run = experiment.runs[r];
      const double cost = number(run, "ceilplan cost REAL");
      if (!std::isfinite(cost)) continue;
      ++solved;
      raw_ratio.push_back(number(run, "ceilplan raw cost REAL") / reference.cost);
      final_ratio.push_back(cost / reference.cost);
      double first = kNotReached, reach = kNotReached;
      if (r < experiment.runsProgressData.size() && !best_key.empty())
        for (const auto& point : experiment.runsProgressData[r]) {
          const double best = number(point, best_key), t = number(point, "time REAL");
          if (std::isfinite(best) && first == kNotReached) first = t;
          if (std::isfinite(best) && best <= 1.05 * reference.search_cost && reach == kNotReached) reach = t;
        }
      first_s.push_back(first);
      reach_s.push_back(reach);
    }
    const double best_final = final_ratio.empty() ? std::numeric_limits<double>::quiet_NaN()
                                                  : *std::min_element(final_ratio.begin(), final_ratio.end());
    std::string name = experiment.name;
    if (name.rfind("geometric_", 0) == 0) name.erase(0, std::string("geometric_").size());
    std::printf("%-16s %3d/%-3zu %11s %12s %12s %12s %13s\n", name.c_str(), solved, experiment.runs.size(),
                text(median(first_s), 2).c_str(), text(median(raw_ratio), 4).c_str(),
                text(median(final_ratio), 4).c_str(), text(best_final, 4).c_str(), text(median(reach_s), 2).c_str());
    json["planners"].push_back({{"planner", name},
                                {"runs", experiment.runs.size()},
                                {"solved", solved},
                                {"median_first_solution_s", median(first_s)},
                                {"median_raw_cost_ratio", median(raw_ratio)},
                                {"median_cost_ratio", median(final_ratio)},
                                {"median_time_to_5pct_s", median(reach_s)}});
  }
  std::printf("medians over the solved runs; 'raw' and 'final' (after shortcuts and NLopt refinement) against the\n"
              "post-processed lattice reference; 'to 5 %%': when the planner's own best cost first came within 5 %% of\n"
              "the raw lattice optimum ('never': not within %.0f s)\n",
              a.search.time_limit_s);
  if (!a.json.empty())
    writeTextAtomically(a.json, [&](std::ostream& out) { out << std::setw(2) << json << '\n'; });
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
  command->add_option("--reference-time-limit-s", arguments->reference_time_limit_s, "lattice reference search time")
      ->capture_default_str()->check(positiveFinite());
  command->add_option("--json", arguments->json, "write the table as JSON");
  command->add_option("--log", arguments->log, "write OMPL's benchmark log (ompl_benchmark_statistics format)");
  command->callback([arguments] { runBench(*arguments); });
});

}  // namespace
}  // namespace ceilplan::app
