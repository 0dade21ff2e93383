#pragma once
/// @file
/// The JSON reports of the commands that look at one thing: a position in a map (`probe`), a map
/// (`mapinfo`), the current model (`current`) and planners against a reference
/// (`bench-planners`). Infinite gaps ("no surface") are null.

#include "ceilplan/energy/ceiling_gap_sweep.hpp"
#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/environment/environment.hpp"
#include "ceilplan/environment/map_statistics.hpp"
#include "ceilplan/environment/position_probe.hpp"
#include "ceilplan/environment/vehicle_geometry.hpp"
#include "ceilplan/planner/planner_benchmark.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace ceilplan::io {

/// at, ceiling_gap_m, ceiling_coverage, ceiling_mean_gap_m, the same for the ground, clearance_m,
/// valid, violation (null when valid), assumed_free, point_assumed_free and rotors: [{offset_m,
/// ceiling, ground}] in `vehicle`'s rotor order, each gap {nearest_gap_m, coverage, mean_gap_m}.
nlohmann::json positionProbeJson(const environment::PositionProbe& probe, const environment::VehicleGeometry& vehicle);
/// What `probe --json` writes: positionProbeJson in `environment`, with map (`map_file`), vehicle
/// (`vehicle_file`, or "built-in: NAME" when empty) and unknown (io::unknownSpaceJson).
nlohmann::json probeReportJson(const environment::PositionProbe& probe, const environment::Environment& environment,
                               const std::string& map_file, const std::string& vehicle_file);

/// map (its file), resolution_m, extent_m {min, max}, leaves {occupied, free}, volume_m3
/// {occupied, free, unknown}, unknown (io::unknownSpaceJson), ceiling {min_headroom_m,
/// min_area_m2}, ceiling_area_share.
nlohmann::json mapStatisticsJson(const std::string& map, const environment::MapStatistics& statistics);

/// `current` at one condition: vehicle, soc, coverage, ground_gap_m, speed_m_s, climb_m_s, gap_m
/// and the breakdown's terms: current_a, power_w, terminal_voltage_v, the powers (induced_w,
/// profile_w, parasitic_w, climb_w, avionics_w) and the factors (ceiling_factor, ground_factor,
/// induced_power_factor).
nlohmann::json currentReportJson(const std::string& vehicle, double ceiling_gap_m, double coverage,
                                 const energy::FlightCondition& flight, const energy::CurrentBreakdown& breakdown);
/// `current --sweep`: the condition, rotor_radius_m, free_air_current_a and sweep, one breakdown
/// per point with its gap_m.
nlohmann::json currentSweepReportJson(const std::string& vehicle, double coverage,
                                      const energy::FlightCondition& flight, double rotor_radius_m,
                                      double free_air_current_a, const std::vector<energy::GapPoint>& sweep);

/// reference {planner, spacing_m (the lattice's), time_s, raw_cost, cost} and planners [{planner,
/// runs, solved, median_first_solution_s, median_raw_cost_ratio, median_cost_ratio,
/// median_time_to_5pct_s}] (null where no run solved, or never came within 5 %).
nlohmann::json plannerBenchmarkJson(const planner::PlanResult& reference, double lattice_spacing_m,
                                    const std::vector<planner::PlannerBenchmarkRow>& rows);

}  // namespace ceilplan::io
