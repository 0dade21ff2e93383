#include "ceilplan/mission/route_planning.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/mission/duty_projection.hpp"

#include <algorithm>
#include <cmath>

namespace ceilplan::mission {
namespace {

battery::DutyResult projectDuty(const PlanningContext& context, const RoutePlan& route, int repeats,
                                const DutyOptions& options) {
  const BatterySpec& battery = context.battery();
  battery::DutyCycle duty;
  duty.mission.segments = flightProfile(route.evaluation, repeats);
  duty.mission.segments.push_back(battery::Segment::idle(60.0 * options.idle_min));
  duty.mission.segments.push_back(
      battery::Segment::charge(battery.pack.charge_current_a, 60.0 * options.charge_max_min, battery.start_soc));
  duty.missions_per_day = options.missions_per_day;
  duty.days = options.days;
  duty.initial_soc = battery.start_soc;
  battery::DutyOptions duty_options;
  duty_options.record_first_day = false;
  try {
    return battery::simulateDuty(battery.pack, duty, duty_options);
  } catch (const battery::DepletionError& e) {
    throw InfeasibleError(flightModeName(route.mode) + " mode: flying the plan " + std::to_string(repeats) +
                          " times per mission depletes the pack (" + e.what() + "); lower the flight time per mission");
  }
}

}  // namespace

RoutePlan planRoute(const PlanningContext& context, FlightMode mode, const planner::PlanRequest& request,
                    const std::string& objective) {
  RoutePlan route;
  route.mode = mode;
  const PlanningContext::Mode planning = context.mode(mode);
  route.objective = context.objective(request.start_m, request.goal_m, objective);
  const planner::FlightPlanner flight_planner(*planning.rules, *planning.model, route.objective);
  route.cost_unit = flight_planner.objective().unit();
  route.plan = flight_planner.plan(request);
  const BatterySpec& battery = context.battery();
  route.evaluation = planner::evaluatePath(context.fullModel(), battery.pack, battery.start_soc, route.plan.waypoints);
  if (mode == FlightMode::Free)
    route.standoff = planner::standoffReport(context.environment(), route.plan.waypoints, context.options().standoff_m);
  return route;
}

std::vector<Eigen::Vector3d> distinctWaypoints(const std::vector<Eigen::Vector3d>& points_m) {
  std::vector<Eigen::Vector3d> waypoints;
  for (std::size_t k = 0; k < points_m.size(); ++k) {
    const Eigen::Vector3d& p = points_m[k];
    if (!p.allFinite()) throw InputError("point " + std::to_string(k + 1) + " has a non-finite coordinate");
    if (waypoints.empty() || (p - waypoints.back()).norm() > 1e-9) waypoints.push_back(p);
  }
  if (waypoints.size() < 2) throw InputError("a path needs at least 2 distinct points");
  return waypoints;
}

RouteCheck checkRoute(const PlanningContext& context, const std::vector<Eigen::Vector3d>& points_m) {
  const std::vector<Eigen::Vector3d> waypoints_m = distinctWaypoints(points_m);
  for (std::size_t k = 0; k < waypoints_m.size(); ++k)
    if (!context.environment().contains(waypoints_m[k]))
      throw InputError("point " + std::to_string(k + 1) + " " + formatPoint(waypoints_m[k]) + " lies outside the map");
  RouteCheck check;
  check.violation = context.baseRules().checkPathDensely(waypoints_m);
  const BatterySpec& battery = context.battery();
  check.evaluation = planner::evaluatePath(context.fullModel(), battery.pack, battery.start_soc, waypoints_m);
  const planner::FlightPlanner scorer(context.baseRules(), context.fullModel(),
                                      context.objective(waypoints_m.front(), waypoints_m.back()));
  check.cost = scorer.objective().weights().of(check.evaluation.totals());
  check.cost_unit = scorer.objective().unit();
  return check;
}

void DutyOptions::validate() const {
  const auto requireMinutes = [](double minutes, const char* name, bool zero_allowed) {
    if (!(std::isfinite(minutes) && minutes <= kMaxMinutes && (zero_allowed ? minutes >= 0.0 : minutes > 0.0)))
      throw InputError(std::string("duty: ") + name + " must be a finite number of minutes in " +
                       (zero_allowed ? "[0, " : "(0, ") + formatNumber(kMaxMinutes) + "] (a day), got " +
                       formatNumber(minutes));
  };
  requireMinutes(flight_min, "flight_min", true);
  requireMinutes(idle_min, "idle_min", true);
  requireMinutes(charge_max_min, "charge_max_min", false);
  if (missions_per_day < 1 || missions_per_day > 1000)
    throw InputError("duty: missions_per_day must be in [1, 1000], got " + std::to_string(missions_per_day));
  if (days < 1 || days > 3650) throw InputError("duty: days must be in [1, 3650], got " + std::to_string(days));
}

RouteComparison compareRoutes(const PlanningContext& context, const planner::PlanRequest& request,
                              const DutyOptions& duty) {
  duty.validate();
  RouteComparison comparison;
  const auto withMode = [](const std::exception& e, FlightMode mode) {
    return flightModeName(mode) + " mode: " + e.what();
  };
  try {
    comparison.free = planRoute(context, FlightMode::Free, request);
  } catch (const NoPathError& e) {
    throw NoPathError(withMode(e, FlightMode::Free));
  }
  planner::PlanRequest ceiling_request = request;
  ceiling_request.candidates.push_back(comparison.free.plan.waypoints);
  try {
    comparison.ceiling = planRoute(context, FlightMode::Ceiling, ceiling_request);
  } catch (const NoPathError& e) {
    throw NoPathError(withMode(e, FlightMode::Ceiling));
  }
  // Both missions do the same work: the route, as many times as the slower plan fits.
  const double slower_s = std::max(comparison.ceiling.evaluation.duration_s, comparison.free.evaluation.duration_s);
  const double repeats = std::floor(60.0 * duty.flight_min / slower_s);
  if (repeats > DutyOptions::kMaxRepeats)
    throw InputError("a flight time of " + formatNumber(duty.flight_min) + " min per mission would fly the " +
                     formatNumber(slower_s, 3) + " s route " + formatNumber(repeats) + " times, more than " +
                     std::to_string(DutyOptions::kMaxRepeats) + "; give a shorter flight time");
  comparison.repeats = std::max(1, static_cast<int>(repeats));
  comparison.ceiling_duty = projectDuty(context, comparison.ceiling, comparison.repeats, duty);
  comparison.free_duty = projectDuty(context, comparison.free, comparison.repeats, duty);
  return comparison;
}

}  // namespace ceilplan::mission
