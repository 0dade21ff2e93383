#include "ceilplan/planner/planner_benchmark.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/planner/ompl_state.hpp"
#include "ceilplan/planner/planner_factory.hpp"

#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/tools/benchmark/Benchmark.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace ceilplan::planner {
namespace {

constexpr double kNotReached = std::numeric_limits<double>::infinity();
constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

double median(std::vector<double> values) {
  if (values.empty()) return kNone;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// A number OMPL logged for a run; NaN when absent or not a number ("inf" or "nan" for no solution).
double number(const std::map<std::string, std::string>& run, const std::string& key) {
  const auto found = run.find(key);
  if (found == run.end() || found->second.empty()) return kNone;
  try {
    return std::stod(found->second);
  } catch (const std::exception&) {
    return kNone;
  }
}

PlannerBenchmarkRow summarise(const ompl::tools::Benchmark::PlannerExperiment& experiment,
                              const PlanResult& reference) {
  std::vector<double> raw_ratio, final_ratio, first_s, reach_s;
  PlannerBenchmarkRow row;
  std::string best_key;
  for (const std::string& key : experiment.progressPropertyNames)
    if (key.rfind("best cost", 0) == 0) best_key = key;
  for (std::size_t r = 0; r < experiment.runs.size(); ++r) {
    const auto& run = experiment.runs[r];
    const double cost = number(run, "ceilplan cost REAL");
    if (!std::isfinite(cost)) continue;
    ++row.solved;
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
  row.planner = experiment.name;
  if (row.planner.rfind("geometric_", 0) == 0) row.planner.erase(0, std::string("geometric_").size());
  row.runs = experiment.runs.size();
  row.median_first_solution_s = median(first_s);
  row.median_raw_cost_ratio = median(raw_ratio);
  row.median_cost_ratio = median(final_ratio);
  row.best_cost_ratio = final_ratio.empty() ? kNone : *std::min_element(final_ratio.begin(), final_ratio.end());
  row.median_time_to_5pct_s = median(reach_s);
  return row;
}

// The ceiling-band sampler, installed for the benchmark's runs only.
class BandSampling {
 public:
  BandSampling(const FlightPlanner& planner, double band_fraction) : planner_(planner) {
    planner_.installBandSampler(band_fraction);
  }
  ~BandSampling() { planner_.clearBandSampler(); }
  BandSampling(const BandSampling&) = delete;
  BandSampling& operator=(const BandSampling&) = delete;

 private:
  const FlightPlanner& planner_;
};

}  // namespace

std::vector<std::string> samplingPlannerNames() {
  std::vector<std::string> names;
  for (const PlannerInfo& info : plannerCatalogue())
    if (info.kind == PlannerKind::Sampling) names.push_back(info.name);
  return names;
}

std::vector<std::string> plannerNamesOfList(const std::string& list) {
  std::vector<std::string> names;
  std::stringstream in(list);
  for (std::string name; std::getline(in, name, ',');)
    if (!name.empty()) names.push_back(name);
  return names;
}

std::string plannerList(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ",") + name;
  return list;
}

PlanResult planLatticeReference(const FlightPlanner& planner, PlanRequest request) {
  request.planner = referencePlannerName();
  try {
    return planner.plan(request);
  } catch (const NoPathError&) {
    rethrowWithContext("lattice reference: ");
  }
}

void PlannerBenchmarkOptions::validate() const {
  if (planners.empty()) throw InputError("give at least one planner name");
  for (const std::string& name : planners) plannerInfo(name);
  if (runs < 1) throw InputError("a benchmark needs at least one run per planner");
  if (!(time_limit_s > 0.0 && time_limit_s <= PlanRequest::kMaxTimeLimit_s))
    throw InputError("a run's time limit must be a number of seconds in (0, " +
                     formatNumber(PlanRequest::kMaxTimeLimit_s) + "], got " + formatNumber(time_limit_s));
}

std::vector<PlannerBenchmarkRow> benchmarkPlanners(const FlightPlanner& planner, const Eigen::Vector3d& start_m,
                                                   const Eigen::Vector3d& goal_m, const PlanResult& reference,
                                                   const PlannerBenchmarkOptions& options) {
  options.validate();
  ompl::geometric::SimpleSetup simple(planner.spaceInformation());
  ompl::base::ScopedState<> start_state(simple.getSpaceInformation()), goal_state(simple.getSpaceInformation());
  setPosition(start_state.get(), start_m);
  setPosition(goal_state.get(), goal_m);
  simple.setStartAndGoalStates(start_state, goal_state, 1e-6);
  simple.setOptimizationObjective(planner.objectivePtr());
  const BandSampling band_sampling(planner, options.band_fraction);
  ompl::tools::Benchmark benchmark(simple, options.experiment);
  for (const auto& [name, value] : options.log_properties) benchmark.addExperimentParameter(name, "VARCHAR", value);
  for (const std::string& name : options.planners)
    benchmark.addPlanner(makePlanner(name, simple.getSpaceInformation(), options.lattice));
  // OMPL's logs have no column for our objective: add the raw and post-processed costs.
  const RefinementOptions refinement;
  const FlightObjective& objective = planner.objective();
  benchmark.setPostRunEvent([&](const ompl::base::PlannerPtr& p, ompl::tools::Benchmark::RunProperties& run) {
    const auto definition = p->getProblemDefinition();
    if (!definition->hasExactSolution()) return;
    std::vector<Eigen::Vector3d> raw;
    for (const ompl::base::State* s : definition->getSolutionPath()->as<ompl::geometric::PathGeometric>()->getStates())
      raw.push_back(toPosition(s));
    const std::vector<Eigen::Vector3d> final_path = planner.postProcess(raw, refinement, options.refine);
    run["ceilplan raw cost REAL"] = std::to_string(objective.pathCost(raw));
    run["ceilplan cost REAL"] = std::to_string(objective.pathCost(final_path));
  });
  const ompl::tools::Benchmark::Request request(options.time_limit_s, 4096.0, options.runs, 0.05, false, false, false);
  benchmark.benchmark(request);
  if (options.log != nullptr) benchmark.saveResultsToStream(*options.log);

  std::vector<PlannerBenchmarkRow> rows;
  for (const auto& experiment : benchmark.getRecordedExperimentData().planners)
    rows.push_back(summarise(experiment, reference));
  return rows;
}

}  // namespace ceilplan::planner
