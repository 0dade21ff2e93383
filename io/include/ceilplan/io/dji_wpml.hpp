#pragma once
// A sortie as a DJI waypoint mission: a KMZ archive holding wpmz/template.kml and
// wpmz/waylines.wpml, elements as DJI's WPML reference names them (DJI Cloud API, "WPML":
// template.kml, waylines.wpml, common elements; namespace http://www.dji.com/wpmz/1.0.2).
//
// Each waypoint carries its height in the chosen reference and its speed towards the next
// (waypointSpeed), the heading in effect (smoothTransition), and straight flight that stops at
// the waypoint (toPointAndStopWithDiscontinuityCurvature: no corner is cut). Its action group
// runs on arrival, in order: rotateYaw (where the route gives a heading), gimbalRotate (where
// the pitch changes), hover (the hold), takePhoto (a photo pose). A distance trigger becomes an
// action group with a multipleDistance trigger over the waypoints it spans. docs/flying.md.

#include "ceilplan/mission/geodetic_origin.hpp"
#include "ceilplan/mission/sortie_route.hpp"

#include <array>
#include <filesystem>
#include <optional>
#include <string>

namespace ceilplan::io {

enum class DjiHeightMode {
  // Heights above the take-off point (WPML relativeToStartPoint in both files): exact, needs no
  // geoid. The default.
  RelativeToTakeoff,
  // Heights above sea level (template.kml EGM96) and above the WGS84 ellipsoid (waylines.wpml
  // WGS84 = sea level + geoid_separation_m, which must then be given).
  SeaLevel,
};

// The aircraft and payload: enum values from DJI's Cloud API product list. Defaults: a Matrice
// 350 RTK (droneEnumValue 89, sub 0) with a Zenmuse H20 (payloadEnumValue 42) on gimbal 0,
// whose tilt range is -120 to +30 degrees (DJI H20 specifications): it can look up at a soffit.
struct DjiWpmlOptions {
  int drone_enum = 89;
  int drone_sub_enum = 0;
  int payload_enum = 42;
  int payload_position = 0;  // gimbal mount index (0: main / left)
  std::array<double, 2> gimbal_pitch_range_deg{-120.0, 30.0};
  DjiHeightMode height_mode = DjiHeightMode::RelativeToTakeoff;
  std::optional<double> geoid_separation_m;  // ellipsoid above geoid at the site (SeaLevel only)
  std::string finish_action = "autoLand";    // goHome | autoLand | noAction | gotoFirstWaypoint
  std::string rc_lost_action = "hover";      // executeRCLostAction: goBack | landing | hover

  // Throws ceilplan::InputError naming the bad field.
  void validate() const;
};

struct DjiWpml {
  std::string template_kml;
  std::string waylines_wpml;
};

// Throws ceilplan::InputError for an invalid route, origin or options, and for a gimbal pitch
// outside the payload's range (naming the waypoint).
DjiWpml djiWpml(const mission::SortieRoute& route, const mission::GeodeticOrigin& origin,
                const DjiWpmlOptions& options = {});

// The KMZ (zip, deflated), written atomically.
void writeDjiKmz(const std::filesystem::path& file, const mission::SortieRoute& route,
                 const mission::GeodeticOrigin& origin, const DjiWpmlOptions& options = {});

}  // namespace ceilplan::io
