#include "ceilplan/io/report_json.hpp"

#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/unknown_space_report.hpp"

namespace ceilplan::io {
namespace {

nlohmann::json rotorGapJson(const environment::RotorGap& gap) {
  return {{"nearest_gap_m", finiteOrNull(gap.nearest_gap_m)},
          {"coverage", gap.coverage},
          {"mean_gap_m", finiteOrNull(gap.mean_gap_m)}};
}

nlohmann::json pointJson(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

nlohmann::json currentBreakdownJson(const energy::CurrentBreakdown& breakdown) {
  return {{"current_a", breakdown.current_a},
          {"power_w", breakdown.power_w},
          {"terminal_voltage_v", breakdown.terminal_voltage_v},
          {"induced_w", breakdown.induced_w},
          {"profile_w", breakdown.profile_w},
          {"parasitic_w", breakdown.parasitic_w},
          {"climb_w", breakdown.climb_w},
          {"avionics_w", breakdown.avionics_w},
          {"ceiling_factor", breakdown.ceiling_factor},
          {"ground_factor", breakdown.ground_factor},
          {"induced_power_factor", breakdown.induced_power_factor}};
}

nlohmann::json flightConditionJson(const std::string& vehicle, double coverage, const energy::FlightCondition& flight) {
  return {{"vehicle", vehicle},
          {"soc", flight.soc},
          {"coverage", coverage},
          {"ground_gap_m", finiteOrNull(flight.ground_gap_m)},
          {"speed_m_s", flight.speed_m_s},
          {"headwind_m_s", flight.headwind_m_s},
          {"airspeed_m_s", flight.airspeedM_s()},
          {"climb_m_s", flight.climb_m_s}};
}

}  // namespace

nlohmann::json positionProbeJson(const environment::PositionProbe& probe, const environment::VehicleGeometry& vehicle) {
  nlohmann::json rotors = nlohmann::json::array();
  for (std::size_t r = 0; r < vehicle.rotor_positions_m.size(); ++r) {
    const Eigen::Vector2d& offset = vehicle.rotor_positions_m[r];
    rotors.push_back({{"offset_m", {offset.x(), offset.y()}},
                      {"ceiling", rotorGapJson(probe.ceiling.rotors[r])},
                      {"ground", rotorGapJson(probe.ground.rotors[r])}});
  }
  return {{"at", pointJson(probe.body_m)},
          {"ceiling_gap_m", finiteOrNull(probe.ceiling.nearest_gap_m)},
          {"ceiling_coverage", probe.ceiling.coverage},
          {"ceiling_mean_gap_m", finiteOrNull(probe.ceiling.mean_gap_m)},
          {"ground_gap_m", finiteOrNull(probe.ground.nearest_gap_m)},
          {"ground_coverage", probe.ground.coverage},
          {"ground_mean_gap_m", finiteOrNull(probe.ground.mean_gap_m)},
          {"clearance_m", finiteOrNull(probe.clearance_m)},
          {"valid", !probe.violation},
          {"violation", probe.violation ? nlohmann::json(probe.violation->describe()) : nlohmann::json(nullptr)},
          {"assumed_free", probe.assumes_free},
          {"point_assumed_free", probe.point_assumed_free},
          {"rotors", rotors}};
}

nlohmann::json probeReportJson(const environment::PositionProbe& probe, const environment::Environment& environment,
                               const std::string& map_file, const std::string& vehicle_file) {
  nlohmann::json report = positionProbeJson(probe, environment.vehicle());
  report["map"] = map_file;
  report["vehicle"] = vehicle_file.empty() ? "built-in: " + environment.vehicle().name : vehicle_file;
  report["unknown"] = unknownSpaceJson(environment);
  return report;
}

nlohmann::json mapStatisticsJson(const std::string& map, const environment::MapStatistics& statistics) {
  return {{"map", map},
          {"resolution_m", statistics.resolution_m},
          {"extent_m", {{"min", pointJson(statistics.extent_m.min())}, {"max", pointJson(statistics.extent_m.max())}}},
          {"leaves", {{"occupied", statistics.occupied_leaves}, {"free", statistics.free_leaves}}},
          {"volume_m3",
           {{"occupied", statistics.occupied_volume_m3},
            {"free", statistics.free_volume_m3},
            {"unknown", statistics.unknown_volume_m3}}},
          {"unknown", unknownSpaceJson(statistics.unknown, statistics.unknown_summary)},
          {"ceiling",
           {{"min_headroom_m", statistics.ceiling.min_headroom_m}, {"min_area_m2", statistics.ceiling.min_area_m2}}},
          {"ceiling_area_share", statistics.ceiling_area_share}};
}

nlohmann::json currentReportJson(const std::string& vehicle, double ceiling_gap_m, double coverage,
                                 const energy::FlightCondition& flight, const energy::CurrentBreakdown& breakdown) {
  nlohmann::json report = flightConditionJson(vehicle, coverage, flight);
  report["gap_m"] = finiteOrNull(ceiling_gap_m);
  report.update(currentBreakdownJson(breakdown));
  return report;
}

nlohmann::json currentSweepReportJson(const std::string& vehicle, double coverage,
                                      const energy::FlightCondition& flight, double rotor_radius_m,
                                      double free_air_current_a, const std::vector<energy::GapPoint>& sweep) {
  nlohmann::json report = flightConditionJson(vehicle, coverage, flight);
  report["rotor_radius_m"] = rotor_radius_m;
  report["free_air_current_a"] = free_air_current_a;
  report["sweep"] = nlohmann::json::array();
  for (const energy::GapPoint& point : sweep) {
    nlohmann::json row = currentBreakdownJson(point.breakdown);
    row["gap_m"] = point.gap_m;
    report["sweep"].push_back(std::move(row));
  }
  return report;
}

nlohmann::json plannerBenchmarkJson(const planner::PlanResult& reference, double lattice_spacing_m,
                                    const std::vector<planner::PlannerBenchmarkRow>& rows) {
  nlohmann::json json;
  json["reference"] = {{"planner", reference.planner},
                       {"spacing_m", lattice_spacing_m},
                       {"time_s", reference.total_time_s},
                       {"raw_cost", reference.search_cost},
                       {"cost", reference.cost}};
  json["planners"] = nlohmann::json::array();
  for (const planner::PlannerBenchmarkRow& row : rows)
    json["planners"].push_back({{"planner", row.planner},
                                {"runs", row.runs},
                                {"solved", row.solved},
                                {"median_first_solution_s", row.median_first_solution_s},
                                {"median_raw_cost_ratio", row.median_raw_cost_ratio},
                                {"median_cost_ratio", row.median_cost_ratio},
                                {"median_time_to_5pct_s", row.median_time_to_5pct_s}});
  return json;
}

}  // namespace ceilplan::io
