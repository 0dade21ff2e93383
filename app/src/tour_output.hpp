#pragma once
// What `ceilplan tour` writes for one mode (tour.json, path.csv, the autopilot missions) and,
// for both modes, the comparison table. docs/tours.md describes every file.

#include "ceilplan/core/error.hpp"

#include "ceilplan/io/autopilot_export.hpp"
#include "mission_file.hpp"
#include "tour_run.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::app {

nlohmann::json tourJson(const TourResult& tour);

// t_s,x,y,z,speed_m_s,ceiling_gap_m,current_a,soc,sortie: the sorties back to back, each
// recharge's duration between them.
void writeTourPathCsv(const std::filesystem::path& file, const TourResult& tour);

// One autopilot mission per sortie: every leg's waypoints after home, a hold of the target's
// dwell at each viewpoint, home last. Throws ceilplan::InputError without a geodetic origin.
std::vector<io::AutopilotMission> autopilotMissions(const TourResult& tour, const MissionFile& mission, io::Autopilot autopilot);

// DIR/tour.json, DIR/path.csv, DIR/map_top.csv, DIR/map_side.csv and, with `autopilot`,
// DIR/mission.plan and DIR/mission.waypoints (per sortie when several).
void writeTourDirectory(const std::filesystem::path& dir, const TourResult& tour, const MissionFile& mission,
                        const environment::Environment& environment, std::optional<io::Autopilot> autopilot);

// The side-by-side table of two modes (ceiling first), as printed and as DIR/comparison.txt.
std::string comparisonTable(const TourResult& ceiling, const TourResult& free);
nlohmann::json comparisonJson(const TourResult& ceiling, const TourResult& free);

// One paragraph for the terminal: targets, sorties with their reasons, totals.
std::string tourSummary(const TourResult& tour);

}  // namespace ceilplan::app
