#pragma once
/// @file
/// One planning query end to end: checks the request, runs the chosen planner (any planner of
/// planner_factory.hpp; OMPL's sampling planners with the ceiling-band sampler), post-processes
/// the path with the objective (shortcuts, NLopt refinement) and re-checks it densely. A path
/// that fails the dense re-check is an error, never a result.

#include "ceilplan/core/error.hpp"
#include "ceilplan/planner/flight_objective.hpp"
#include "ceilplan/planner/lattice_settings.hpp"
#include "ceilplan/planner/objective_factory.hpp"
#include "ceilplan/planner/path_refinement.hpp"
#include "ceilplan/planner/safety_rules.hpp"

#include <ompl/base/SpaceInformation.h>
#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace ceilplan::planner {

/// Its defaults are every front end's (the CLI's flags, Python's keywords), so one query gives
/// one route whichever asks.
struct PlanRequest {
  /// where the route starts, map coordinates
  Eigen::Vector3d start_m = Eigen::Vector3d::Zero();
  /// where it ends
  Eigen::Vector3d goal_m = Eigen::Vector3d::Zero();
  std::string planner;  ///< empty: defaultPlannerName()
  /// For a sampling search; the deterministic ones run to completion, and so does the
  /// post-processing (RefinementOptions::max_evaluations bounds it, not a clock).
  double time_limit_s = 5.0;
  /// The longest search: a day. OMPL's clock overflows on far larger limits and stops at once.
  static constexpr double kMaxTimeLimit_s = 86400.0;
  double band_fraction =
      0.0;             ///< share of samples aimed at the ceiling band (0, the default: uniform; docs/planner.md)
  bool refine = true;  ///< shortcuts + NLopt refinement
  RefinementOptions refinement;                      ///< post-processing limits
  LatticeSettings lattice = queryLatticeSettings();  ///< the lattice planners' spacing
  /// Known routes from start to goal (e.g. the free-mode plan): each that is valid under these
  /// rules is post-processed too, and returned if cheaper than what the search found, so a
  /// plan is never worse than a route it was shown.
  std::vector<std::vector<Eigen::Vector3d>> candidates;
};

/// What FlightPlanner::plan returns: the route and what the search took.
struct PlanResult {
  std::vector<Eigen::Vector3d> waypoints;  ///< the route, start to goal, map coordinates
  std::string planner;                     ///< the planner that found it
  double cost = 0.0;                       ///< under the planning objective, after post-processing
  double search_cost = 0.0;                ///< as the planner returned it
  double search_time_s = 0.0;              ///< time in the search
  double total_time_s = 0.0;               ///< time in all, post-processing included
  bool from_candidate = false;             ///< one of PlanRequest::candidates beat the search
};

/// Single-query planning through one map under one set of safety rules, cost model and objective (planRoute builds one
/// per query).
class FlightPlanner {
 public:
  /// `rules` and `model` must outlive the planner.
  FlightPlanner(const SafetyRules& rules, const FlightCostModel& model, const ObjectiveChoice& objective);

  /// The objective it plans with.
  const FlightObjective& objective() const { return *objective_; }
  /// The same, shared.
  const std::shared_ptr<FlightObjective>& objectivePtr() const { return objective_; }
  /// The safety rules it plans under.
  const SafetyRules& rules() const { return rules_; }

  /// Shortcuts and NLopt refinement (PlanRequest::refine), then the dense re-check: the
  /// post-processing plan() applies to a raw path. Throws ceilplan::Error if neither the
  /// result nor the raw path passes the re-check.
  std::vector<Eigen::Vector3d> postProcess(const std::vector<Eigen::Vector3d>& raw, const RefinementOptions& options,
                                           bool refine = true) const;
  /// OMPL's space information: the state space with the validity checker and motion validator.
  const ompl::base::SpaceInformationPtr& spaceInformation() const { return si_; }

  /// Throws ceilplan::InputError for a bad request (start or goal outside the map or invalid,
  /// time limit <= 0, unknown planner), ceilplan::NoPathError when there is no path, and
  /// ceilplan::Error if a path fails the dense re-check.
  PlanResult plan(const PlanRequest& request) const;

  /// Makes the space sample the ceiling band (share `band_fraction`) until cleared; plan() does
  /// this itself, benchmarks that drive OMPL directly call it.
  void installBandSampler(double band_fraction) const;
  /// Puts the space's default sampler back.
  void clearBandSampler() const;

  /// Checks a point the way plan() checks start and goal; `what` names it in the message.
  void requireValidEndpoint(const Eigen::Vector3d& point_m, const std::string& what) const;

 private:
  const SafetyRules& rules_;
  const FlightCostModel& model_;
  ompl::base::SpaceInformationPtr si_;
  std::shared_ptr<FlightObjective> objective_;
};

/// Seeds OMPL's random generators. Call it once, before constructing any FlightPlanner (OMPL
/// makes generators as soon as a space is set up, and a seed set afterwards is ignored). Only
/// the first call in a process takes effect; returns false if an earlier call used another
/// seed. Throws ceilplan::InputError on seed 0 (checkSeed).
bool seedOmpl(std::uint32_t seed);

/// Throws ceilplan::InputError for seed 0, which OMPL refuses; every seed ceilplan takes (--seed,
/// a mission's `seed`, Python's seed) is checked the same way.
void checkSeed(std::uint32_t seed);

}  // namespace ceilplan::planner
