#pragma once
/// @file
/// Writes a sortie's route (mission/sortie_route.hpp) in the local map frame (x east, y north,
/// z up, metres from the geodetic origin) as mission files autopilots and ground stations read:
/// a QGroundControl .plan (JSON) and a QGC WPL 110 text file. Altitudes are relative to home, as
/// the vehicle arms there.
///
/// Item sequence (docs/flying.md): MAV_CMD_NAV_TAKEOFF (22) at home to the route's take-off
/// height; then per waypoint MAV_CMD_DO_CHANGE_SPEED (178) before the first and where the speed
/// into it differs from the speed last commanded by 1 cm/s or more; MAV_CMD_DO_GIMBAL_MANAGER_PITCHYAW (1000) where the
/// gimbal pitch changes, so the gimbal turns on the way; MAV_CMD_NAV_WAYPOINT (16) with the hold
/// time (a contact reading's whole dwell) and the heading in effect as yaw; then
/// MAV_CMD_IMAGE_START_CAPTURE (2000) for a photo (after the hold, so the vehicle has settled)
/// and MAV_CMD_DO_SET_CAM_TRIGG_DIST (206) where a distance trigger starts or stops. A route that
/// ends at home flies its last waypoint above home at the landing height and ends with
/// MAV_CMD_NAV_LAND (21) there.
///
/// Without GNSS, PX4 flies these global waypoints from its local position once the EKF origin is
/// set to the mission's geodetic origin; the .plan carries that origin under "ceilplan".

#include "ceilplan/core/error.hpp"
#include "ceilplan/mission/geodetic_origin.hpp"
#include "ceilplan/mission/sortie_route.hpp"

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::io {

using mission::GeodeticOrigin;
/// A waypoint of an exported route: the route's own waypoint type.
using ExportWaypoint = mission::RouteWaypoint;

/// The autopilot a .plan file is written for: its firmwareType, as QGroundControl reads it.
enum class Autopilot {
  PX4,       ///< MAV_AUTOPILOT_PX4
  ArduPilot  ///< MAV_AUTOPILOT_ARDUPILOTMEGA
};

/// The route (home, waypoints, cruise speed) plus what the autopilot file needs besides.
struct AutopilotMission : mission::SortieRoute {
  std::optional<GeodeticOrigin> origin;  ///< required: the export fails clearly without it
  Autopilot autopilot = Autopilot::PX4;  ///< the autopilot the file is for
  double hover_speed_m_s = 0.5;          ///< speed near a target
  double acceptance_radius_m = 0.2;      ///< a waypoint counts as reached within this distance
  double pass_radius_m = 0.0;            ///< 0: fly through the waypoint itself
};

// MAVLink command and frame numbers (common.xml) the files use.
namespace mav {
constexpr int kNavWaypoint = 16;                ///< MAV_CMD_NAV_WAYPOINT
constexpr int kNavLand = 21;                    ///< MAV_CMD_NAV_LAND
constexpr int kNavTakeoff = 22;                 ///< MAV_CMD_NAV_TAKEOFF
constexpr int kDoChangeSpeed = 178;             ///< MAV_CMD_DO_CHANGE_SPEED
constexpr int kDoSetCamTriggDist = 206;         ///< MAV_CMD_DO_SET_CAM_TRIGG_DIST
constexpr int kDoGimbalManagerPitchYaw = 1000;  ///< MAV_CMD_DO_GIMBAL_MANAGER_PITCHYAW
constexpr int kImageStartCapture = 2000;        ///< MAV_CMD_IMAGE_START_CAPTURE
constexpr int kFrameGlobal = 0;                 ///< MAV_FRAME_GLOBAL
constexpr int kFrameMission = 2;                ///< MAV_FRAME_MISSION
constexpr int kFrameGlobalRelativeAlt = 3;      ///< MAV_FRAME_GLOBAL_RELATIVE_ALT
constexpr int kSpeedTypeGroundSpeed = 1;        ///< DO_CHANGE_SPEED speed type: ground speed
/// GIMBAL_MANAGER_FLAGS_ROLL_LOCK | GIMBAL_MANAGER_FLAGS_PITCH_LOCK: pitch against the horizon,
/// yaw following the vehicle (whose heading the waypoints set).
constexpr int kGimbalFlagsHorizonFollow = 4 | 8;
}  // namespace mav

/// The route with its export settings.
AutopilotMission autopilotMission(const mission::SortieRoute& route, const GeodeticOrigin& origin,
                                  Autopilot autopilot = Autopilot::PX4);

/// Geodetic position of a map-frame point: {latitude_deg, longitude_deg, ellipsoidal height
/// taken as altitude AMSL (m)}, via GeographicLib::LocalCartesian (ENU) at the origin.
Eigen::Vector3d toGeodetic(const GeodeticOrigin& origin, const Eigen::Vector3d& local_m);
/// The inverse.
Eigen::Vector3d toLocal(const GeodeticOrigin& origin, const Eigen::Vector3d& geodetic);

/// The QGroundControl plan (fileType "Plan", version 1, mission version 2, SimpleItems as above,
/// NAV_WAYPOINT in frame 3 = altitude relative to home, the others in frame 2 = mission; NaN
/// parameters as null, as QGroundControl writes them). Throws ceilplan::InputError naming the
/// problem: missing origin, bad numbers, no waypoints.
nlohmann::json qgcPlan(const AutopilotMission& mission);
/// "QGC WPL 110", then row 0 = home (absolute altitude), then one row per item, 12
/// TAB-separated fields each (NaN written "nan").
std::string qgcWpl(const AutopilotMission& mission);

/// Both written atomically (whole or not at all).
void writeQgcPlan(const std::filesystem::path& file, const AutopilotMission& mission);
/// The WPL 110 text of `mission`, written atomically.
void writeQgcWpl(const std::filesystem::path& file, const AutopilotMission& mission);

/// The file for sortie `sortie` (1-based) of `sortie_count`: `file` itself for a single sortie,
/// else the stem with "_sortieN" (mission.plan -> mission_sortie2.plan).
std::filesystem::path sortieFileName(const std::filesystem::path& file, int sortie, int sortie_count);

}  // namespace ceilplan::io
