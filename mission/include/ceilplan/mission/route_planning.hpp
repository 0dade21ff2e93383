#pragma once
/// @file
/// Single routes as users ask for them: plan one between two points in a flight mode, score and
/// check any given path, and compare the two modes on the same query with the founding paper's
/// month-long duty projection. Every figure comes from the full model with the state of charge
/// integrated along the path.

#include "ceilplan/battery/duty_cycle.hpp"
#include "ceilplan/mission/flight_mode.hpp"
#include "ceilplan/mission/planning_context.hpp"
#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/path_evaluation.hpp"
#include "ceilplan/planner/standoff.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace ceilplan::mission {

/// One planned route: what the planner returned and its figures under the full model.
struct RoutePlan {
  FlightMode mode = FlightMode::Ceiling;  ///< the mode it was planned in
  planner::PlanResult plan;               ///< the planner's result: waypoints, cost, planner, seed
  planner::PathEvaluation evaluation;     ///< full model, from the battery's start SOC
  planner::ObjectiveChoice objective;     ///< with the ageing rates it was linearised at
  std::string cost_unit;                  ///< of plan.cost
  /// Free mode: where the route kept less than the conventional standoff (none in ceiling mode).
  std::optional<planner::StandoffReport> standoff;
};

/// Plans from request.start_m to request.goal_m under `objective` (empty: the context's).
/// Throws ceilplan::InputError for a bad request (start or goal outside the map or not valid),
/// ceilplan::NoPathError when no path is found.
RoutePlan planRoute(const PlanningContext& context, FlightMode mode, const planner::PlanRequest& request,
                    const std::string& objective = {});

/// The figures and the safety of a given path (checkRoute).
struct RouteCheck {
  planner::PathEvaluation evaluation;    ///< full model, from the battery's start SOC
  std::optional<std::string> violation;  ///< the dense re-check's first violation; none: safe
  double cost = 0.0;                     ///< under the context's objective
  std::string cost_unit;                 ///< of `cost`
};

/// `points_m` without each point within 1e-9 m of the one before it. Throws ceilplan::InputError
/// for a non-finite coordinate, or when fewer than 2 distinct points remain.
std::vector<Eigen::Vector3d> distinctWaypoints(const std::vector<Eigen::Vector3d>& points_m);

/// The figures and the safety of any path, repeated points dropped (distinctWaypoints). Throws
/// ceilplan::InputError for fewer than 2 distinct points, or naming a point outside the map.
RouteCheck checkRoute(const PlanningContext& context, const std::vector<Eigen::Vector3d>& points_m);

/// The founding paper's month for a route: each mission flies it as often as the slower mode
/// fits in flight_min, idles, charges back.
struct DutyOptions {
  static constexpr double kMaxMinutes = 1440.0;  ///< each time below, up to a day
  static constexpr int kMaxRepeats = 10000;      ///< flights of the route per mission

  double flight_min = 20.0;      ///< the paper's mission
  double idle_min = 5.0;         ///< after each mission, before the charge
  double charge_max_min = 20.0;  ///< the charger's longest session
  int missions_per_day = 15;     ///< the paper's 15
  int days = 30;                 ///< length of the projection

  /// Throws ceilplan::InputError naming the field: a time outside [0, kMaxMinutes] (charge_max_min
  /// above 0), or missions_per_day outside [1, 1000] or days outside [1, 3650].
  void validate() const;
};

/// Both modes on one query (compareRoutes), with the founding paper's month for each.
struct RouteComparison {
  RoutePlan ceiling;                 ///< the ceiling-mode route, shown the free route
  RoutePlan free;                    ///< the free-mode route
  int repeats = 1;                   ///< flights of the route per mission, the same for both modes
  battery::DutyResult ceiling_duty;  ///< the month flying the ceiling route
  battery::DutyResult free_duty;     ///< the month flying the free route
};

/// Free mode first; ceiling mode is shown the free route, so it is never worse under the full
/// model. Throws as planRoute, ceilplan::InputError for `duty` that DutyOptions::validate refuses
/// (before planning) or a route so short that flight_min would fly it more than kMaxRepeats
/// times, and ceilplan::InfeasibleError when the duty depletes the pack.
RouteComparison compareRoutes(const PlanningContext& context, const planner::PlanRequest& request,
                              const DutyOptions& duty);

}  // namespace ceilplan::mission
