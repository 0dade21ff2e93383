#pragma once
// What planning commands write: plan.json figures and path.csv rows, from a PathEvaluation.

#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/path_evaluation.hpp"
#include "ceilplan/environment/environment.hpp"
#include "ceilplan/mission/route_planning.hpp"

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <vector>

namespace ceilplan::io {

// length_m, duration_s, charge_ah, energy_wh, fec, mean_current_a, min_soc, min_clearance_m,
// min_ceiling_gap_m (null: no ceiling), time_under_ceiling_s.
nlohmann::json figuresJson(const planner::PathEvaluation& evaluation);

nlohmann::json waypointsJson(const std::vector<Eigen::Vector3d>& waypoints_m);

// t_s,x,y,z,speed_m_s,ceiling_gap_m,current_a,soc (an empty gap field: no ceiling). Atomic.
void writePathCsv(const std::filesystem::path& file, const planner::PathEvaluation& evaluation);

// DIR/plan.json (figures, waypoints, planner, cost and `extra`'s keys) and DIR/path.csv.
void writePlanDirectory(const std::filesystem::path& dir, const planner::PlanResult& plan,
                        const planner::PathEvaluation& evaluation, const nlohmann::json& extra);

// One line of figures for a terminal.
std::string figuresLine(const planner::PathEvaluation& evaluation);

// Both modes side by side with the duty projection, as `ceilplan compare` prints it.
std::string routeComparisonTable(const mission::RouteComparison& comparison, const mission::DutyOptions& duty,
                                 const mission::BatterySpec& battery);
// compare.json: `extra`'s keys, the duty settings, each mode's figures, cost and duty, and the
// reductions in percent.
nlohmann::json routeComparisonJson(const mission::RouteComparison& comparison, const mission::DutyOptions& duty,
                                   const nlohmann::json& extra);
// DIR/compare.json, DIR/ceiling/ and DIR/free/ (plan directories) and the map views of both routes.
void writeRouteComparison(const std::filesystem::path& dir, const mission::RouteComparison& comparison,
                          const mission::DutyOptions& duty, const nlohmann::json& extra,
                          const environment::Environment& environment);

}  // namespace ceilplan::io
