#include "ceilplan/io/autopilot_export.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/io/atomic_file.hpp"

#include <GeographicLib/LocalCartesian.hpp>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace ceilplan::io {

namespace {

// MAVLink identifiers (common.xml) and QGroundControl's plan constants.
constexpr int kMavCmdNavWaypoint = 16;
constexpr int kMavFrameGlobal = 0;
constexpr int kMavFrameGlobalRelativeAlt = 3;
constexpr int kMavAutopilotArdupilotMega = 3;
constexpr int kMavAutopilotPx4 = 12;
constexpr int kMavTypeQuadrotor = 2;

void requireFinite(const Eigen::Vector3d& value, const std::string& what) {
  if (!value.allFinite()) throw ceilplan::InputError(what + " must be finite, got (" + formatNumber(value.x()) + ", " +
                                                      formatNumber(value.y()) + ", " + formatNumber(value.z()) + ")");
}

void requireNonNegative(double value, const std::string& what) {
  if (!std::isfinite(value) || value < 0.0)
    throw ceilplan::InputError(what + " must be finite and non-negative, got " + formatNumber(value));
}

const GeodeticOrigin& checkedOrigin(const AutopilotMission& mission) {
  if (!mission.origin)
    throw ceilplan::InputError(
        "cannot export to an autopilot without the map's geodetic origin: add origin: {lat, lon, alt} to the mission file");
  mission.origin->validate();
  requireFinite(mission.home_m, "home");
  if (mission.waypoints.empty()) throw ceilplan::InputError("cannot export a mission without waypoints");
  for (std::size_t k = 0; k < mission.waypoints.size(); ++k) {
    const ExportWaypoint& waypoint = mission.waypoints[k];
    const std::string what = "waypoint " + std::to_string(k + 1);
    requireFinite(waypoint.position_m, what);
    requireNonNegative(waypoint.hold_s, what + " hold time (s)");
    if (waypoint.yaw_deg && !std::isfinite(*waypoint.yaw_deg))
      throw ceilplan::InputError(what + " yaw must be finite, got " + formatNumber(*waypoint.yaw_deg));
  }
  requireNonNegative(mission.cruise_speed_m_s, "cruise speed (m/s)");
  requireNonNegative(mission.hover_speed_m_s, "hover speed (m/s)");
  requireNonNegative(mission.acceptance_radius_m, "acceptance radius (m)");
  requireNonNegative(mission.pass_radius_m, "pass radius (m)");
  return *mission.origin;
}

// A waypoint in the autopilot's terms: latitude, longitude, altitude relative to home.
struct GlobalWaypoint {
  double latitude_deg;
  double longitude_deg;
  double relative_altitude_m;
  double hold_s;
  std::optional<double> yaw_deg;
};

struct GlobalMission {
  Eigen::Vector3d home;  // latitude, longitude, altitude AMSL
  std::vector<GlobalWaypoint> waypoints;
};

GlobalMission toGlobal(const AutopilotMission& mission) {
  const GeodeticOrigin& origin = checkedOrigin(mission);
  GlobalMission global;
  global.home = toGeodetic(origin, mission.home_m);
  for (const ExportWaypoint& waypoint : mission.waypoints) {
    const Eigen::Vector3d position = toGeodetic(origin, waypoint.position_m);
    global.waypoints.push_back(
        {position.x(), position.y(), position.z() - global.home.z(), waypoint.hold_s, waypoint.yaw_deg});
  }
  return global;
}

}  // namespace

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
  for (const GlobalWaypoint& waypoint : global.waypoints) {
    items.push_back({{"type", "SimpleItem"},
                     {"command", kMavCmdNavWaypoint},
                     {"frame", kMavFrameGlobalRelativeAlt},
                     {"autoContinue", true},
                     {"doJumpId", jump_id++},
                     {"params",
                      {waypoint.hold_s, mission.acceptance_radius_m, mission.pass_radius_m,
                       waypoint.yaw_deg ? nlohmann::json(*waypoint.yaw_deg) : nlohmann::json(nullptr),
                       waypoint.latitude_deg, waypoint.longitude_deg, waypoint.relative_altitude_m}}});
  }
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
          {"rallyPoints", {{"points", nlohmann::json::array()}, {"version", 2}}}};
}

std::string qgcWpl(const AutopilotMission& mission) {
  const GlobalMission global = toGlobal(mission);
  std::string text = "QGC WPL 110\n";
  char row[256];
  // Eight decimals of a degree are about a millimetre.
  std::snprintf(row, sizeof row, "0\t1\t%d\t%d\t0\t0\t0\t0\t%.8f\t%.8f\t%.4f\t1\n", kMavFrameGlobal, kMavCmdNavWaypoint,
                global.home.x(), global.home.y(), global.home.z());
  text += row;
  int index = 1;
  for (const GlobalWaypoint& waypoint : global.waypoints) {
    std::snprintf(row, sizeof row, "%d\t0\t%d\t%d\t%.3f\t%.3f\t%.3f\t%.3f\t%.8f\t%.8f\t%.4f\t1\n", index++,
                  kMavFrameGlobalRelativeAlt, kMavCmdNavWaypoint, waypoint.hold_s, mission.acceptance_radius_m,
                  mission.pass_radius_m, waypoint.yaw_deg.value_or(0.0), waypoint.latitude_deg, waypoint.longitude_deg,
                  waypoint.relative_altitude_m);
    text += row;
  }
  return text;
}

void writeQgcPlan(const std::filesystem::path& file, const AutopilotMission& mission) {
  const std::string text = qgcPlan(mission).dump(2) + "\n";
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
