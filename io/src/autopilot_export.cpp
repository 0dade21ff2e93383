#include "ceilplan/io/autopilot_export.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/io/atomic_file.hpp"
#include "ceilplan/io/json_values.hpp"

#include <GeographicLib/LocalCartesian.hpp>

#include <array>
#include <cmath>
#include <cstdio>

namespace ceilplan::io {

namespace {

constexpr int kMavAutopilotArdupilotMega = 3;
constexpr int kMavAutopilotPx4 = 12;
constexpr int kMavTypeQuadrotor = 2;

void requireNonNegative(double value, const std::string& what) {
  if (!std::isfinite(value) || value < 0.0)
    throw ceilplan::InputError(what + " must be finite and non-negative, got " + formatNumber(value));
}

const GeodeticOrigin& checkedOrigin(const AutopilotMission& mission) {
  if (!mission.origin)
    throw ceilplan::InputError(
        "cannot export to an autopilot without the map's geodetic origin: add origin: {lat, lon, alt} to the mission "
        "file");
  mission.origin->validate();
  if (mission.waypoints.empty()) throw ceilplan::InputError("cannot export a mission without waypoints");
  mission.validate();
  requireNonNegative(mission.hover_speed_m_s, "hover speed (m/s)");
  requireNonNegative(mission.acceptance_radius_m, "acceptance radius (m)");
  requireNonNegative(mission.pass_radius_m, "pass radius (m)");
  return *mission.origin;
}

// One mission item: a MAVLink command with its frame and seven parameters (for a waypoint,
// params 4-6 are latitude, longitude and altitude relative to home).
struct MissionItem {
  int command;
  int frame;
  std::array<double, 7> params;
};

struct GlobalMission {
  Eigen::Vector3d home;  // latitude, longitude, altitude AMSL
  std::vector<MissionItem> items;
};

GlobalMission toGlobal(const AutopilotMission& mission) {
  const GeodeticOrigin& origin = checkedOrigin(mission);
  const double nan = std::nan("");
  GlobalMission global;
  global.home = toGeodetic(origin, mission.home_m);
  const std::vector<double> headings = mission::headingsInEffect_deg(mission);
  const std::vector<double> pitches = mission::gimbalPitchesInEffect_deg(mission);
  std::optional<double> pitch_set;
  // From the ground: a vertical climb to the route's take-off height, heading as it stands.
  global.items.push_back({mav::kNavTakeoff,
                          mav::kFrameGlobalRelativeAlt,
                          {0, 0, 0, nan, global.home.x(), global.home.y(), mission.takeoffHeight_m()}});
  // Speeds from the flight record differ by rounding where nothing changes (2.2356910794284737
  // against 2.235691079428473): a change counts from 1 cm/s against the speed last commanded.
  // The first is always commanded: the vehicle's own default (PX4's MPC_XY_CRUISE, 5 m/s) is not
  // the plan's, and the .plan's cruiseSpeed never reaches the vehicle.
  constexpr double kSpeedStep_m_s = 0.01;
  std::optional<double> speed_set;
  int photos = 0;
  const bool lands = mission.endsAtHome();
  for (std::size_t k = 0; k < mission.waypoints.size(); ++k) {
    const ExportWaypoint& w = mission.waypoints[k];
    const double speed = mission.speedInto_m_s(k);
    if (!speed_set || std::abs(speed - *speed_set) >= kSpeedStep_m_s) {
      global.items.push_back(
          {mav::kDoChangeSpeed, mav::kFrameMission, {mav::kSpeedTypeGroundSpeed, speed, -1, 0, 0, 0, 0}});
      speed_set = speed;
    }
    if (w.gimbal_pitch_deg && pitch_set != pitches[k]) {
      global.items.push_back({mav::kDoGimbalManagerPitchYaw,
                              mav::kFrameMission,
                              {pitches[k], 0.0, nan, nan, mav::kGimbalFlagsHorizonFollow, 0, 0}});
      pitch_set = pitches[k];
    }
    // The last waypoint of a route that ends at home: above home at the landing height, then down.
    const bool last = k + 1 == mission.waypoints.size();
    const Eigen::Vector3d flown_m =
        last && lands ? Eigen::Vector3d(mission.home_m + mission.landingHeight_m() * Eigen::Vector3d::UnitZ())
                      : w.position_m;
    const Eigen::Vector3d position = toGeodetic(origin, flown_m);
    global.items.push_back({mav::kNavWaypoint,
                            mav::kFrameGlobalRelativeAlt,
                            {w.hold_s, mission.acceptance_radius_m, mission.pass_radius_m, headings[k], position.x(),
                             position.y(), position.z() - global.home.z()}});
    if (w.take_photo)
      global.items.push_back(
          {mav::kImageStartCapture, mav::kFrameMission, {0, 0, 1, static_cast<double>(++photos), 0, 0, nan}});
    if (w.trigger_distance_m) {
      const double distance = *w.trigger_distance_m;
      global.items.push_back(
          {mav::kDoSetCamTriggDist, mav::kFrameMission, {distance, 0, distance > 0.0 ? 1.0 : 0.0, 0, 0, 0, 0}});
    }
  }
  if (lands)
    global.items.push_back(
        {mav::kNavLand, mav::kFrameGlobalRelativeAlt, {0, 0, 0, nan, global.home.x(), global.home.y(), 0.0}});
  return global;
}

nlohmann::json numberOrNull(double value) {
  return std::isnan(value) ? nlohmann::json(nullptr) : nlohmann::json(value);
}

}  // namespace

AutopilotMission autopilotMission(const mission::SortieRoute& route, const GeodeticOrigin& origin,
                                  Autopilot autopilot) {
  AutopilotMission mission;
  static_cast<mission::SortieRoute&>(mission) = route;
  mission.origin = origin;
  mission.autopilot = autopilot;
  return mission;
}

Eigen::Vector3d toGeodetic(const GeodeticOrigin& origin, const Eigen::Vector3d& local_m) {
  const GeographicLib::LocalCartesian frame(origin.latitude_deg, origin.longitude_deg, origin.altitude_m);
  double latitude = 0, longitude = 0, height = 0;
  frame.Reverse(local_m.x(), local_m.y(), local_m.z(), latitude, longitude, height);
  return {latitude, longitude, height};
}

Eigen::Vector3d toLocal(const GeodeticOrigin& origin, const Eigen::Vector3d& geodetic) {
  const GeographicLib::LocalCartesian frame(origin.latitude_deg, origin.longitude_deg, origin.altitude_m);
  double x = 0, y = 0, z = 0;
  frame.Forward(geodetic.x(), geodetic.y(), geodetic.z(), x, y, z);
  return {x, y, z};
}

nlohmann::json qgcPlan(const AutopilotMission& mission) {
  const GlobalMission global = toGlobal(mission);
  nlohmann::json items = nlohmann::json::array();
  int jump_id = 1;
  for (const MissionItem& item : global.items) {
    nlohmann::json params = nlohmann::json::array();
    for (double p : item.params) params.push_back(numberOrNull(p));
    items.push_back({{"type", "SimpleItem"},
                     {"command", item.command},
                     {"frame", item.frame},
                     {"autoContinue", true},
                     {"doJumpId", jump_id++},
                     {"params", params}});
  }
  const GeodeticOrigin& origin = *mission.origin;
  return {{"fileType", "Plan"},
          {"version", 1},
          {"groundStation", "ceilplan"},
          {"mission",
           {{"version", 2},
            {"firmwareType", mission.autopilot == Autopilot::PX4 ? kMavAutopilotPx4 : kMavAutopilotArdupilotMega},
            {"vehicleType", kMavTypeQuadrotor},
            {"cruiseSpeed", mission.cruise_speed_m_s},
            {"hoverSpeed", mission.hover_speed_m_s},
            {"plannedHomePosition", {global.home.x(), global.home.y(), global.home.z()}},
            {"items", items}}},
          {"geoFence", {{"circles", nlohmann::json::array()}, {"polygons", nlohmann::json::array()}, {"version", 2}}},
          {"rallyPoints", {{"points", nlohmann::json::array()}, {"version", 2}}},
          // Ignored by QGroundControl; where the map frame lies, for setting the EKF origin
          // without GNSS (docs/flying.md).
          {"ceilplan",
           {{"ekf_origin",
             {{"lat_deg", origin.latitude_deg}, {"lon_deg", origin.longitude_deg}, {"alt_m", origin.altitude_m}}},
            {"map_frame", "ENU: x east, y north, z up, metres from ekf_origin"},
            {"sortie", mission.sortie}}}};
}

std::string qgcWpl(const AutopilotMission& mission) {
  const GlobalMission global = toGlobal(mission);
  std::string text = "QGC WPL 110\n";
  char row[320];
  // Eight decimals of a degree are about a millimetre.
  std::snprintf(row, sizeof row, "0\t1\t%d\t%d\t0\t0\t0\t0\t%.8f\t%.8f\t%.4f\t1\n", mav::kFrameGlobal,
                mav::kNavWaypoint, global.home.x(), global.home.y(), global.home.z());
  text += row;
  int index = 1;
  for (const MissionItem& item : global.items) {
    const auto& p = item.params;
    std::snprintf(row, sizeof row, "%d\t0\t%d\t%d\t%.3f\t%.3f\t%.3f\t%.3f\t%.8f\t%.8f\t%.4f\t1\n", index++, item.frame,
                  item.command, p[0], p[1], p[2], p[3], p[4], p[5], p[6]);
    text += row;
  }
  return text;
}

void writeQgcPlan(const std::filesystem::path& file, const AutopilotMission& mission) {
  const std::string text = jsonText(qgcPlan(mission), 2) + "\n";
  writeTextAtomically(file, [&](std::ostream& out) { out << text; });
}

void writeQgcWpl(const std::filesystem::path& file, const AutopilotMission& mission) {
  const std::string text = qgcWpl(mission);
  writeTextAtomically(file, [&](std::ostream& out) { out << text; });
}

std::filesystem::path sortieFileName(const std::filesystem::path& file, int sortie, int sortie_count) {
  if (sortie < 1 || sortie > sortie_count)
    throw ceilplan::InputError("sortie " + std::to_string(sortie) + " is not in 1.." + std::to_string(sortie_count));
  if (sortie_count == 1) return file;
  return file.parent_path() / (file.stem().string() + "_sortie" + std::to_string(sortie) + file.extension().string());
}

}  // namespace ceilplan::io
