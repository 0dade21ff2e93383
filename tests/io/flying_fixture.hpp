#pragma once
// What the flying exports are built from in the tests: a `ceilplan tour --out DIR` directory
// (tour.json, path.csv, comparison.json) read back and mapped onto the export types, as
// docs/flying.md describes the tour's mapping. Used by the tests and by export_demo.

#include "ceilplan/environment/environment.hpp"
#include "ceilplan/environment/occupancy_map.hpp"
#include "ceilplan/io/report_html.hpp"
#include "ceilplan/mission/geodetic_origin.hpp"
#include "ceilplan/mission/sortie_route.hpp"
#include "ceilplan/mission/trajectory.hpp"
#include "ceilplan/planner/safety_rules.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace ceilplan::testing {

// The mission file's keys the exports need.
struct MissionFacts {
  std::filesystem::path map;
  std::filesystem::path vehicle;
  Eigen::Vector3d home_m = Eigen::Vector3d::Zero();
  mission::GeodeticOrigin origin;
  double cruise_m_s = 2.0;
  double climb_m_s = 1.0;
  double descent_m_s = 0.8;
  double reserve_soc = 0.25;
};
MissionFacts readMissionFacts(const std::filesystem::path& mission_file);

// One mode's tour output.
struct TourOutput {
  std::string mode;
  nlohmann::json tour;
  std::vector<io::ReportSample> samples;  // path.csv
  std::vector<mission::SortieRoute> routes;
};

// Reads DIR/tour.json and DIR/path.csv. Each sortie's route: every leg's waypoints after its
// first; at each target's viewpoint a hold of its dwell, the camera aimed at the target and a
// photo; each segment's speed the slowest the flight record flies on it.
TourOutput readTourOutput(const std::filesystem::path& dir, const MissionFacts& facts);

// The tour directory's modes: DIR/ceiling and DIR/free after --mode both, else DIR itself.
std::vector<TourOutput> readTourOutputs(const std::filesystem::path& dir, const MissionFacts& facts);

// The trajectory limits of a mission: its climb and descent, the default acceleration, jerk
// and yaw rate.
mission::TrajectoryLimits trajectoryLimits(const MissionFacts& facts);

// The map indexed for the mission's vehicle, and the tour's dense re-check (planner rules with
// the default 0.05 m rotor-to-ceiling gap). Unknown space is an obstacle unless `unknown_is_free`.
struct MapCheck {
  explicit MapCheck(const MissionFacts& facts, bool unknown_is_free = false);
  environment::OccupancyMap map;
  std::unique_ptr<environment::Environment> environment;
  std::unique_ptr<planner::SafetyRules> rules;
  // For TrajectoryOptions::path_is_safe.
  bool safe(const std::vector<Eigen::Vector3d>& positions) const { return !rules->checkPathDensely(positions); }
};

// report.html's model for the tour's modes: structure within 3 m of every route, targets and
// viewpoints, the comparison table when there are two modes.
io::ReportModel reportModel(const std::vector<TourOutput>& outputs, const MissionFacts& facts, const MapCheck& map,
                            const std::filesystem::path& tour_dir, const std::string& title);

// A coverage-style mock until the coverage planner lands: photo poses every metre along the
// plan's route where structure is within 3 m above, looking straight up, and the soffit within
// 1.5 m of them as patches coloured by the best GSD their footprints reach (uncovered red).
void addCoverageMock(io::ReportPlan& plan, const MapCheck& map);

}  // namespace ceilplan::testing
