#pragma once
/// @file
/// OMPL's benchmark harness (ompl::tools::Benchmark) on one query of a FlightPlanner, with the
/// flight objective's cost of every run logged raw and post-processed and compared with a
/// reference plan, usually the lattice optimum (`ceilplan bench-planners`, docs/planner.md).
/// Every planner comes from the one factory (makePlanner), OMPL's and the lattice ones.

#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/lattice_settings.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace ceilplan::planner {

/// OMPL's sampling planners in the catalogue: the default list.
std::vector<std::string> samplingPlannerNames();

/// A comma-separated list of planner names as a command line gives it ("BITstar,PRMstar"),
/// empty names skipped; plannerList joins names into one.
std::vector<std::string> plannerNamesOfList(const std::string& list);
/// `names` joined with commas.
std::string plannerList(const std::vector<std::string>& names);

/// What benchmarkPlanners runs: planners, runs, time limit and the log.
struct PlannerBenchmarkOptions {
  std::vector<std::string> planners = samplingPlannerNames();  ///< any of plannerNames()
  LatticeSettings lattice;                                     ///< for the lattice planners among them
  unsigned runs = 10;                                          ///< per planner
  double time_limit_s = 5.0;                                   ///< per run
  double band_fraction = 0.0;                                  ///< share of samples from the ceiling band (0: uniform)
  bool refine = true;                                          ///< post-process with NLopt refinement, as plan() does
  std::string experiment = "ceilplan";                         ///< experiment name in the log
  /// OMPL's benchmark log (ompl_benchmark_statistics format) is written here; null: none. A stream,
  /// not a file name: the caller writes it with its other outputs, all or nothing.
  std::ostream* log = nullptr;
  /// Name and one-line text of each experiment property the log records besides OMPL's own
  /// (where the run came from: version, command line, inputs).
  std::vector<std::pair<std::string, std::string>> log_properties;

  /// Throws ceilplan::InputError for no planner, an unknown name (plannerInfo's message), no run
  /// or a time limit that is not positive.
  void validate() const;
};

/// One planner's runs. Medians are over the solved runs (NaN when none solved); ratios are
/// against the reference's post-processed cost.
struct PlannerBenchmarkRow {
  std::string planner;             ///< its name, without OMPL's "geometric_" prefix
  std::size_t runs = 0;            ///< runs made
  int solved = 0;                  ///< runs that found a path
  double median_first_solution_s;  ///< median time to the first solution
  double median_raw_cost_ratio;    ///< the planner's own path, before post-processing
  double median_cost_ratio;        ///< after shortcuts and refinement
  double best_cost_ratio;          ///< the best run's cost ratio
  /// When the planner's own best cost first came within 5 % of the reference's raw (search)
  /// cost; infinite for a run that never did.
  double median_time_to_5pct_s;
};

/// The reference runs are compared with: the lattice optimum (referencePlannerName) of
/// `request`'s query at its lattice settings, post-processed as `request` asks like every run.
/// Throws ceilplan::NoPathError, its message prefixed "lattice reference: ", when there is none.
PlanResult planLatticeReference(const FlightPlanner& planner, PlanRequest request);

/// Runs every planner `runs` times from `start_m` to `goal_m` under `planner`'s objective and
/// validity checker. Throws ceilplan::InputError for bad options.
std::vector<PlannerBenchmarkRow> benchmarkPlanners(const FlightPlanner& planner, const Eigen::Vector3d& start_m,
                                                   const Eigen::Vector3d& goal_m, const PlanResult& reference,
                                                   const PlannerBenchmarkOptions& options);

}  // namespace ceilplan::planner
