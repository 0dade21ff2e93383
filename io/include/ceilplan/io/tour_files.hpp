#pragma once
// What `ceilplan tour` writes for one mode (tour.json, path.csv, the autopilot missions) and,
// for both modes, the comparison table. docs/tours.md describes every file.

#include "ceilplan/io/autopilot_export.hpp"
#include "ceilplan/mission/mission.hpp"
#include "ceilplan/mission/tour_planner.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::io {

nlohmann::json tourJson(const mission::TourResult& tour);

// t_s,x,y,z,speed_m_s,ceiling_gap_m,current_a,soc,sortie: the sorties back to back, each
// recharge's duration between them.
void writeTourPathCsv(const std::filesystem::path& file, const mission::TourResult& tour);

// One autopilot mission per sortie: every leg's waypoints after home, a hold of the target's
// dwell at each viewpoint, home last. Throws ceilplan::InputError without a geodetic origin.
std::vector<AutopilotMission> autopilotMissions(const mission::TourResult& tour, const mission::Mission& mission, Autopilot autopilot);

// DIR/tour.json, DIR/path.csv, DIR/map_top.csv, DIR/map_side.csv and, with `autopilot`,
// DIR/mission.plan and DIR/mission.waypoints (per sortie when several).
void writeTourDirectory(const std::filesystem::path& dir, const mission::TourResult& tour, const mission::Mission& mission,
                        const environment::Environment& environment, std::optional<Autopilot> autopilot);

// The side-by-side table of two modes (ceiling first), as printed and as DIR/comparison.txt.
std::string comparisonTable(const mission::TourResult& ceiling, const mission::TourResult& free);
nlohmann::json comparisonJson(const mission::TourResult& ceiling, const mission::TourResult& free);
// DIR/comparison.txt, DIR/comparison.json and map views covering both routes.
void writeTourComparison(const std::filesystem::path& dir, const mission::TourResult& ceiling,
                         const mission::TourResult& free, const environment::Environment& environment);

// One paragraph for the terminal: targets, sorties with their reasons, totals.
std::string tourSummary(const mission::TourResult& tour);

}  // namespace ceilplan::io
