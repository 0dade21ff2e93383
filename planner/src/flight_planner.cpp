#include "ceilplan/planner/flight_planner.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/planner/blockage.hpp"
#include "ceilplan/planner/ceiling_band_sampler.hpp"
#include "ceilplan/planner/motion_validator.hpp"
#include "ceilplan/planner/ompl_state.hpp"
#include "ceilplan/planner/planner_factory.hpp"
#include "ceilplan/planner/state_validity_checker.hpp"

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <chrono>
#include <cmath>
#include <mutex>
#include <optional>

namespace ceilplan::planner {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void checkSeed(std::uint32_t seed) {
  if (seed == 0) throw ceilplan::InputError("seed must be > 0 (OMPL refuses 0)");
}

bool seedOmpl(std::uint32_t seed) {
  checkSeed(seed);
  static std::mutex mutex;
  static std::optional<std::uint32_t> used;
  std::lock_guard<std::mutex> lock(mutex);
  if (used) return *used == seed;
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  ompl::RNG::setSeed(seed);
  used = seed;
  return true;
}

FlightPlanner::FlightPlanner(const SafetyRules& rules, const FlightCostModel& model, const ObjectiveChoice& objective)
    : rules_(rules), model_(model) {
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  si_ = std::make_shared<ompl::base::SpaceInformation>(makePositionSpace(rules_.environment()));
  si_->setStateValidityChecker(std::make_shared<FlightStateValidityChecker>(si_, rules_));
  si_->setMotionValidator(std::make_shared<FlightMotionValidator>(si_, rules_));
  si_->setup();
  objective_ = makeObjective(objective, si_, model_);
}

void FlightPlanner::requireValidEndpoint(const Eigen::Vector3d& p, const std::string& what) const {
  if (!p.allFinite()) throw ceilplan::InputError(what + " has a non-finite coordinate");
  const environment::Environment& environment = rules_.environment();
  if (!environment.contains(p)) {
    const Eigen::AlignedBox3d box = environment.grid().frame().bounds();
    throw ceilplan::InputError(what + " " + formatPoint(p) + " lies outside the map " + formatPoint(box.min()) + " - " +
                               formatPoint(box.max()));
  }
  if (const auto violation = environment.stateViolation(p))
    throw ceilplan::InputError(what + " " + formatPoint(p) + " is not a valid state: " + violation->describe());
  if (!rules_.isStateValid(p))
    throw ceilplan::InputError(what + " " + formatPoint(p) + " is too close to a ceiling (rotor plane within " +
                               formatNumber(rules_.minCeilingGap_m()) + " m) or violates the standoff");
}

void FlightPlanner::installBandSampler(double band_fraction) const {
  // The band sampler serves every planner: directly, or through the objective's informed
  // sampler (RejectionBandSampler).
  const CeilingBandOptions band{
      band_fraction, rules_.minCeilingGap_m(),
      model_.options().speeds.near_ceiling_gap_radii * rules_.environment().vehicle().rotor_radius_m};
  const environment::Environment& environment = rules_.environment();
  si_->getStateSpace()->setStateSamplerAllocator([&environment, band](const ompl::base::StateSpace* space) {
    return std::make_shared<CeilingBandSampler>(space, environment, band);
  });
}

void FlightPlanner::clearBandSampler() const { si_->getStateSpace()->clearStateSamplerAllocator(); }

std::vector<Eigen::Vector3d> FlightPlanner::postProcess(const std::vector<Eigen::Vector3d>& raw,
                                                        const RefinementOptions& options, bool refine) const {
  std::vector<Eigen::Vector3d> best = raw;
  if (refine) best = refinePath(shortcutPath(best, rules_, *objective_), rules_, *objective_, options);
  if (const auto problem = rules_.checkPathDensely(best)) {
    if (rules_.checkPathDensely(raw))
      throw ceilplan::Error("the planned path fails the dense re-check: " + *problem +
                            " (a bug: please report it with the map and the command)");
    best = raw;  // post-processing slipped past the motion checks: keep the raw path
  }
  return best;
}

PlanResult FlightPlanner::plan(const PlanRequest& request) const {
  const auto started = std::chrono::steady_clock::now();
  if (!(request.time_limit_s > 0.0 && request.time_limit_s <= PlanRequest::kMaxTimeLimit_s))
    throw ceilplan::InputError("time limit must be a number of seconds in (0, " +
                               formatNumber(PlanRequest::kMaxTimeLimit_s) + "], got " +
                               formatNumber(request.time_limit_s));
  if (!(request.band_fraction >= 0.0 && request.band_fraction <= 1.0))
    throw ceilplan::InputError("band fraction must be a share in [0, 1], got " + formatNumber(request.band_fraction));
  request.lattice.validate();  // whichever planner: the same request is refused by every front end
  requireValidEndpoint(request.start_m, "start");
  requireValidEndpoint(request.goal_m, "goal");
  if ((request.goal_m - request.start_m).norm() < 1e-6)
    throw ceilplan::InputError("start and goal coincide: nothing to plan");
  PlanResult result;
  result.planner = request.planner.empty() ? defaultPlannerName() : request.planner;
  const PlannerInfo& info = plannerInfo(result.planner);  // rejects unknown names early

  const bool sampling = info.kind == PlannerKind::Sampling;
  if (sampling) installBandSampler(request.band_fraction);
  auto definition = std::make_shared<ompl::base::ProblemDefinition>(si_);
  ompl::base::ScopedState<> start(si_), goal(si_);
  setPosition(start.get(), request.start_m);
  setPosition(goal.get(), request.goal_m);
  definition->setStartAndGoalStates(start, goal, 1e-6);
  definition->setOptimizationObjective(objective_);
  const ompl::base::PlannerPtr planner = makePlanner(result.planner, si_, request.lattice);
  planner->setProblemDefinition(definition);
  planner->setup();
  // A deterministic search runs to completion, so its answer does not depend on the machine's speed
  // or load; only the sampling planners are anytime and stop at the clock, read at each check
  // (OMPL's solve(seconds) watches it from a thread of its own, which a limit on threads or
  // memory can refuse).
  const ompl::base::PlannerStatus status =
      planner->solve(info.deterministic() ? ompl::base::plannerNonTerminatingCondition()
                                          : ompl::base::timedPlannerTerminationCondition(request.time_limit_s));
  if (sampling) clearBandSampler();
  if (status != ompl::base::PlannerStatus::EXACT_SOLUTION || !definition->hasExactSolution()) {
    if (!info.deterministic())
      throw ceilplan::NoPathError("no path found by " + result.planner + " within " +
                                  formatNumber(request.time_limit_s) + " s (status: " + status.asString() +
                                  "); raise --time-limit-s, or try --planner " + referencePlannerName() +
                                  ", which says where the way is blocked");
    const auto* reporter = dynamic_cast<const BlockageReporter*>(planner.get());
    const std::optional<Blockage> blockage = reporter ? reporter->lastBlockage() : std::nullopt;
    throw ceilplan::NoPathError("no collision-free route joins start and goal (" + result.planner + ")" +
                                (blockage ? ": " + blockage->describe() : std::string()));
  }
  const auto path = definition->getSolutionPath()->as<ompl::geometric::PathGeometric>();
  for (const ompl::base::State* state : path->getStates()) result.waypoints.push_back(toPosition(state));
  result.search_time_s = secondsSince(started);
  result.search_cost = objective_->pathCost(result.waypoints);

  result.waypoints = postProcess(result.waypoints, request.refinement, request.refine);
  result.cost = objective_->pathCost(result.waypoints);
  for (const std::vector<Eigen::Vector3d>& candidate : request.candidates) {
    if (candidate.size() < 2 || (candidate.front() - request.start_m).norm() > 1e-9 ||
        (candidate.back() - request.goal_m).norm() > 1e-9)
      throw ceilplan::InputError("a candidate route must run from the start to the goal");
    bool valid = true;
    for (std::size_t k = 1; k < candidate.size() && valid; ++k)
      valid = rules_.isMotionValid(candidate[k - 1], candidate[k]);
    // The motion checks sample; a candidate the dense re-check refuses is no route (not a bug).
    if (!valid || rules_.checkPathDensely(candidate)) continue;
    const std::vector<Eigen::Vector3d> improved = postProcess(candidate, request.refinement, request.refine);
    const double cost = objective_->pathCost(improved);
    if (cost < result.cost) {
      result.waypoints = improved;
      result.cost = cost;
      result.from_candidate = true;
    }
  }
  result.total_time_s = secondsSince(started);
  return result;
}

}  // namespace ceilplan::planner
