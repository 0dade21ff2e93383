#pragma once
// What planning commands write: plan.json figures and path.csv rows, from a PathEvaluation.

#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/path_evaluation.hpp"

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <vector>

namespace ceilplan::app {

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

}  // namespace ceilplan::app
