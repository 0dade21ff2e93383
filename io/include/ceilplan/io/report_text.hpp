#pragma once
/// @file
/// The terminal text of the commands that look at one thing (report_json.hpp has their JSON): a
/// position in a map (`probe`), a map (`mapinfo`), the current model (`current`), its fit to
/// measurements (`calibrate`), planners against a reference (`bench-planners`) and an imported map
/// (`import`), and the scene `mapgen` wrote. Infinite gaps print as "none".

#include "ceilplan/energy/calibration.hpp"
#include "ceilplan/energy/ceiling_gap_sweep.hpp"
#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/environment/map_statistics.hpp"
#include "ceilplan/environment/position_probe.hpp"
#include "ceilplan/environment/scenes.hpp"
#include "ceilplan/environment/unknown_space.hpp"
#include "ceilplan/environment/vehicle_geometry.hpp"
#include "ceilplan/io/map_import.hpp"
#include "ceilplan/planner/planner_benchmark.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::io {

/// One "key: value" line each for the gaps, clearance, validity, unknown space (`unknown_line`,
/// io::unknownSpaceLine) and what was assumed free, then one line per rotor.
std::string positionProbeText(const Eigen::Vector3d& body_m, const environment::PositionProbe& probe,
                              const environment::VehicleGeometry& vehicle, const std::string& unknown_line);

/// The map's resolution, extent, leaves, volumes, unknown space and share under a ceiling.
std::string mapStatisticsText(const std::string& map, const environment::MapStatistics& statistics);

/// The condition `current` was asked for: SOC, coverage, ground gap (absent: none), speed, climb.
std::string flightConditionText(const std::string& vehicle, double coverage, const std::optional<double>& ground_gap_m,
                                const energy::FlightCondition& flight);
/// The ceiling gap (absent: none) and every term of the breakdown.
std::string currentBreakdownText(const std::optional<double>& ceiling_gap_m, const energy::CurrentBreakdown& breakdown);
/// The free-air current and one row per gap: gap_m, gap in rotor radii, current, power, factor.
std::string currentSweepText(double rotor_radius_m, double free_air_current_a,
                             const std::vector<energy::GapPoint>& sweep);

/// The fit: vehicle, data file and its samples, RMSE, largest error and evaluations, then one row
/// per fitted parameter (value, allowed range, start, and whether it ended at its bound).
std::string calibrationText(const std::string& vehicle, const std::filesystem::path& data, std::size_t samples,
                            const energy::CalibrationResult& result);

/// bench-planners' first line: the mode, the objective and its unit, runs and time limit per
/// planner, the seed.
std::string plannerBenchmarkHeadline(const std::string& mode, const std::string& objective, const std::string& unit,
                                     const planner::PlannerBenchmarkOptions& options, std::uint32_t seed);
/// The lattice reference (at `lattice_spacing_m`): its raw and post-processed cost and time.
std::string latticeReferenceLine(const planner::PlanResult& reference, double lattice_spacing_m);

/// One row per planner (medians over the solved runs, ratios to the reference) and what they mean;
/// `time_limit_s` is each run's limit ("never" came within 5 % within it).
std::string plannerBenchmarkTable(const std::vector<planner::PlannerBenchmarkRow>& rows, double time_limit_s);

/// One line on the scene written to `map_file`: its name (a bridge's length when not the shipped
/// one), resolution, seed, voxels (`grid`), octree nodes, and the file with its size.
std::string generatedSceneLine(const std::string& scene, const environment::SceneOptions& options,
                               const environment::VoxelGrid& grid, std::size_t octree_nodes,
                               const std::filesystem::path& map_file);

/// What `import` built: source, resolution, the builder's figures, free-space assumption, extent,
/// the geodetic origin for the mission file when a CRS was given, and the file written.
std::string mapImportText(const MapImport& imported, const MapImportOptions& options,
                          const std::filesystem::path& map_file);

}  // namespace ceilplan::io
