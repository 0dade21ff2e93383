#pragma once
// Writes a route in the local map frame (x east, y north, z up, metres from the geodetic
// origin) as mission files autopilots and ground stations read: a QGroundControl .plan (JSON)
// and a QGC WPL 110 text file. Altitudes are relative to home, as the vehicle arms there.

#include "ceilplan/core/error.hpp"
#include "ceilplan/mission/geodetic_origin.hpp"

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::io {

using mission::GeodeticOrigin;

struct ExportWaypoint {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  // map frame
  double hold_s = 0.0;                                    // hover here this long (inspection dwell)
  std::optional<double> yaw_deg;                          // heading, degrees from north; none: autopilot's choice
};

enum class Autopilot { PX4, ArduPilot };

struct AutopilotMission {
  std::vector<ExportWaypoint> waypoints;  // in flying order, home not repeated
  Eigen::Vector3d home_m = Eigen::Vector3d::Zero();
  std::optional<GeodeticOrigin> origin;   // required: the export fails clearly without it
  Autopilot autopilot = Autopilot::PX4;
  double cruise_speed_m_s = 2.0;
  double hover_speed_m_s = 0.5;
  double acceptance_radius_m = 0.2;  // a waypoint counts as reached within this distance
  double pass_radius_m = 0.0;        // 0: fly through the waypoint itself
};

// Geodetic position of a map-frame point: {latitude_deg, longitude_deg, ellipsoidal height
// taken as altitude AMSL (m)}, via GeographicLib::LocalCartesian (ENU) at the origin.
Eigen::Vector3d toGeodetic(const GeodeticOrigin& origin, const Eigen::Vector3d& local_m);
// The inverse.
Eigen::Vector3d toLocal(const GeodeticOrigin& origin, const Eigen::Vector3d& geodetic);

// The QGroundControl plan (fileType "Plan", version 1, mission version 2, one SimpleItem
// NAV_WAYPOINT (16) per waypoint, frame 3 = altitude relative to home). Throws
// ceilplan::InputError naming the problem: missing origin, bad numbers, no waypoints.
nlohmann::json qgcPlan(const AutopilotMission& mission);
// "QGC WPL 110", then row 0 = home (absolute altitude), then one row per waypoint, 12
// TAB-separated fields each.
std::string qgcWpl(const AutopilotMission& mission);

// Both written atomically (whole or not at all).
void writeQgcPlan(const std::filesystem::path& file, const AutopilotMission& mission);
void writeQgcWpl(const std::filesystem::path& file, const AutopilotMission& mission);

// The file for sortie `sortie` (1-based) of `sortie_count`: `file` itself for a single sortie,
// else the stem with "_sortieN" (mission.plan -> mission_sortie2.plan).
std::filesystem::path sortieFileName(const std::filesystem::path& file, int sortie, int sortie_count);

}  // namespace ceilplan::io
