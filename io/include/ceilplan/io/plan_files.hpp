#pragma once
/// @file
/// What planning commands write: plan.json figures and path.csv rows, from a PathEvaluation.

#include "ceilplan/environment/environment.hpp"
#include "ceilplan/io/provenance.hpp"
#include "ceilplan/mission/route_planning.hpp"
#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/path_evaluation.hpp"
#include "ceilplan/planner/standoff.hpp"

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace ceilplan::io {

/// length_m, duration_s, charge_ah, energy_wh, fec, mean_current_a, min_soc, min_clearance_m,
/// min_ceiling_gap_m (null: no ceiling), time_under_ceiling_s.
nlohmann::json figuresJson(const planner::PathEvaluation& evaluation);

/// `waypoints_m` as a JSON array of [x, y, z].
nlohmann::json waypointsJson(const std::vector<Eigen::Vector3d>& waypoints_m);

/// A provenance comment line, then t_s,x,y,z,speed_m_s,ceiling_gap_m,current_a,soc,ground_gap_m
/// (an empty gap field: no surface). Atomic.
void writePathCsv(const std::filesystem::path& file, const planner::PathEvaluation& evaluation,
                  const Provenance& provenance);

/// DIR/plan.json (figures, waypoints, planner, cost and `extra`'s keys) and DIR/path.csv.
void writePlanDirectory(const std::filesystem::path& dir, const planner::PlanResult& plan,
                        const planner::PathEvaluation& evaluation, const nlohmann::json& extra,
                        const Provenance& provenance);

/// The keys `ceilplan plan` adds to plan.json: seed, objective, cost_unit, mode, map, vehicle,
/// battery, start_soc and unknown_space, and where they apply the standoff report (free mode) and
/// the rates the ageing objective was linearised at (model, depth_of_discharge, loss_per_ah,
/// loss_per_s).
nlohmann::json routePlanJson(const mission::RoutePlan& route, const mission::PlanningContext& context,
                             const std::string& map_file, std::uint64_t seed);
/// DIR/plan.json (writePlanDirectory's keys and routePlanJson's) and DIR/path.csv.
void writeRoutePlan(const std::filesystem::path& dir, const mission::RoutePlan& route,
                    const mission::PlanningContext& context, const std::string& map_file, std::uint64_t seed,
                    const Provenance& provenance);

/// What `ceilplan evaluate --json` writes: the figures, valid, violation (null: none), the
/// context's objective, cost, cost_unit, waypoints, unknown_space and provenance.
nlohmann::json routeCheckJson(const mission::RouteCheck& check, const std::vector<Eigen::Vector3d>& waypoints_m,
                              const mission::PlanningContext& context, const Provenance& provenance);

/// The points of a path CSV: columns x, y, z (path.csv of plan and tour) or x_m, y_m, z_m
/// (trajectory.csv), other columns ignored, whatever they hold; a point repeated on consecutive
/// rows (path.csv's segment joints, hovering) is kept once. Throws ceilplan::InputError naming
/// the file, line and column, or for fewer than 2 distinct points.
std::vector<Eigen::Vector3d> readPathWaypoints(const std::filesystem::path& file);

/// One line of figures for a terminal.
std::string figuresLine(const planner::PathEvaluation& evaluation);

/// The rates the ageing objective was linearised at, as one line: model, depth of discharge,
/// loss per Ah and per second.
std::string ageingObjectiveLine(const planner::AgeingRates& ageing);
/// `ceilplan plan`'s lines on the route: waypoints, cost (and the search's) in its unit, planning
/// time, the figures and, in free mode, the standoff line.
std::string routePlanText(const mission::RoutePlan& route);
/// `ceilplan evaluate`'s lines: the path's points and figures, its cost under the context's
/// objective, whether it is valid (and the violation) and what the map's unknown space counts as.
std::string routeCheckText(const mission::RouteCheck& check, std::size_t points,
                           const mission::PlanningContext& context);

/// What every standoff figure of the JSON outputs measures (their key `standoff_measures`).
inline constexpr const char* kStandoffMeasures =
    "the gap between the airframe's bounding sphere and the nearest structure (planner::standoffAt); negative where "
    "the sphere overlaps a structure, as close under a ceiling, while the airframe itself keeps its clearance";
/// A standoff figure (planner::standoffAt) in words, a negative one as the overlap it is: "the
/// airframe's bounding sphere 0.42 m from the nearest structure", "the airframe's bounding sphere
/// 0.07 m into the nearest structure (the sphere overlaps it; the airframe itself keeps its
/// clearance)".
std::string standoffText(double standoff_m);

/// Free mode's standoff report: standoff_m (asked for), length_m, narrowed_m, min_standoff_m and
/// `narrowed`, the spans with less ({from_m, to_m, min_standoff_m, at: [x, y, z]}, along the
/// path), and standoff_measures (kStandoffMeasures).
nlohmann::json standoffJson(const planner::StandoffReport& report);
/// One line for a terminal, e.g. "standoff 1 m: kept over 9.30 of 12.52 m, narrowed over 3.22 m
/// in 2 places; closest: the airframe's bounding sphere 0.18 m from the nearest structure at
/// (1.00, 0.70, 5.20)".
std::string standoffLine(const planner::StandoffReport& report);

/// Both modes side by side with the duty projection, as `ceilplan compare` prints it.
std::string routeComparisonTable(const mission::RouteComparison& comparison, const mission::DutyOptions& duty,
                                 const mission::BatterySpec& battery);
/// compare.json: `extra`'s keys, the duty settings, each mode's figures, cost and duty, and the
/// reductions in percent.
nlohmann::json routeComparisonJson(const mission::RouteComparison& comparison, const mission::DutyOptions& duty,
                                   const nlohmann::json& extra);
/// DIR/compare.json, DIR/ceiling/ and DIR/free/ (plan directories) and the map views of both
/// routes; each JSON file names the context's objective, the `planner`, the `seed` and the map's
/// unknown space.
void writeRouteComparison(const std::filesystem::path& dir, const mission::RouteComparison& comparison,
                          const mission::DutyOptions& duty, const mission::PlanningContext& context,
                          const std::string& planner, std::uint64_t seed, const Provenance& provenance);

}  // namespace ceilplan::io
