#pragma once
// The terminal text of the commands that look at one thing (report_json.hpp has their JSON): a
// position in a map (`probe`), a map (`mapinfo`), the current model (`current`), planners against
// a reference (`bench-planners`) and an imported map (`import`). Infinite gaps print as "none".

#include "ceilplan/energy/ceiling_gap_sweep.hpp"
#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/environment/map_statistics.hpp"
#include "ceilplan/environment/position_probe.hpp"
#include "ceilplan/environment/unknown_space.hpp"
#include "ceilplan/environment/vehicle_geometry.hpp"
#include "ceilplan/io/map_import.hpp"
#include "ceilplan/planner/planner_benchmark.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::io {

// One "key: value" line each for the gaps, clearance, validity, unknown space (`unknown_line`,
// io::unknownSpaceLine) and what was assumed free, then one line per rotor.
std::string positionProbeText(const Eigen::Vector3d& body_m, const environment::PositionProbe& probe,
                              const environment::VehicleGeometry& vehicle, const std::string& unknown_line);

// The map's resolution, extent, leaves, volumes, unknown space and share under a ceiling.
std::string mapStatisticsText(const std::string& map, const environment::MapStatistics& statistics);

// The condition `current` was asked for: SOC, coverage, ground gap (absent: none), speed, climb.
std::string flightConditionText(const std::string& vehicle, double coverage, const std::optional<double>& ground_gap_m,
                                const energy::FlightCondition& flight);
// The ceiling gap (absent: none) and every term of the breakdown.
std::string currentBreakdownText(const std::optional<double>& ceiling_gap_m, const energy::CurrentBreakdown& breakdown);
// The free-air current and one row per gap: gap_m, gap in rotor radii, current, power, factor.
std::string currentSweepText(double rotor_radius_m, double free_air_current_a, const std::vector<energy::GapPoint>& sweep);

// One row per planner (medians over the solved runs, ratios to the reference) and what they mean;
// `time_limit_s` is each run's limit ("never" came within 5 % within it).
std::string plannerBenchmarkTable(const std::vector<planner::PlannerBenchmarkRow>& rows, double time_limit_s);

// What `import` built: source, resolution, the builder's figures, free-space assumption, extent,
// the geodetic origin for the mission file when a CRS was given, and the file written.
std::string mapImportText(const MapImport& imported, const MapImportOptions& options, const std::filesystem::path& map_file);

}  // namespace ceilplan::io
