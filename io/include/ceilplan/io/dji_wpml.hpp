#pragma once
/// @file
/// A sortie as a DJI waypoint mission: a KMZ archive holding wpmz/template.kml and
/// wpmz/waylines.wpml, elements as DJI's WPML reference names them (DJI Cloud API, "WPML":
/// template.kml, waylines.wpml, common elements; namespace http://www.dji.com/wpmz/1.0.2).
///
/// Each waypoint carries its height in the chosen reference and its speed towards the next
/// (waypointSpeed, clamped to DJI's [1, 15] m/s), the heading in effect (smoothTransition), and
/// straight flight that stops at the waypoint (globalWaypointTurnMode
/// toPointAndStopWithDiscontinuityCurvature: no corner is cut). Its action group runs on arrival,
/// in order: rotateYaw (where the route gives a heading), gimbalRotate (where the pitch changes),
/// hover (the hold, and the whole of a contact reading), takePhoto (a photo pose). A distance
/// trigger becomes an action group with a multipleDistance trigger over the waypoints it spans.
/// A route that ends at home ends at its landing height above home, and finishAction lands.
/// docs/flying.md.

#include "ceilplan/mission/dji_aircraft.hpp"
#include "ceilplan/mission/geodetic_origin.hpp"
#include "ceilplan/mission/sortie_route.hpp"

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::io {

/// Which height reference the KMZ's heights use.
enum class DjiHeightMode {
  /// Heights above the take-off point (WPML relativeToStartPoint in both files): exact, needs no
  /// geoid. The default.
  RelativeToTakeoff,
  /// Heights above sea level (template.kml EGM96) and above the WGS84 ellipsoid (waylines.wpml
  /// WGS84 = sea level + geoid_separation_m, which must then be given).
  SeaLevel,
};

/// The aircraft and payload: enum values from DJI's Cloud API product-support table (docs/flying.md).
/// Defaults: a Matrice 350 RTK (droneEnumValue 89, sub 0) with a Zenmuse H20 (payloadEnumValue 42)
/// on the main gimbal (gimbalindex 0), whose tilt range is -120 to +30 degrees (DJI H20
/// specifications): it cannot look straight up at a soffit; on the upper mount it can.
struct DjiWpmlOptions {
  int drone_enum = 89;       ///< droneEnumValue
  int drone_sub_enum = 0;    ///< droneSubEnumValue
  int payload_enum = 42;     ///< payloadEnumValue
  int payload_position = 0;  ///< gimbalindex: 0 main (left, underslung), 1 right, 2 upper (M300/M350 RTK)
  std::array<double, 2> gimbal_pitch_range_deg{-120.0, 30.0};  ///< gimbal pitch range of the payload, degrees (+90 up)
  DjiHeightMode height_mode = DjiHeightMode::RelativeToTakeoff;  ///< which height reference the files use
  std::optional<double> geoid_separation_m;                      ///< ellipsoid above geoid at the site (SeaLevel only)
  std::string finish_action = "autoLand";                        ///< goHome | autoLand | noAction | gotoFirstWaypoint
  std::string rc_lost_action = "hover";                          ///< executeRCLostAction: goBack | landing | hover
  double rth_height_m = 2.0;                                     ///< globalRTHHeight, [2, 1500] m

  /// Throws ceilplan::InputError naming the bad field.
  void validate() const;
};

/// The names the mission file's `dji:` keys take (mission::DjiAircraft).
const std::vector<std::string>& djiDroneNames();
/// The payload names the `dji:` key takes.
const std::vector<std::string>& djiPayloadNames();

/// The enum values and pitch range of an aircraft, payload and mount. Throws
/// ceilplan::InputError for a payload the drone does not carry, a mount it does not have, or a
/// payload whose pitch range is not built in and not given.
DjiWpmlOptions djiWpmlOptions(const mission::DjiAircraft& aircraft);

/// Where a value of the route lies outside the range DJI's WPML tables allow and was written as
/// the nearest allowed value instead.
struct DjiClamp {
  int sortie = 1;            ///< 1-based
  std::size_t waypoint = 0;  ///< 1-based; 0: a route-wide element
  std::string element;       ///< e.g. "wpml:waypointSpeed"
  double planned = 0.0;      ///< the value planned
  double written = 0.0;      ///< the value written
};

/// A DJI WPML mission (the two files of a KMZ) and what was clamped to fit DJI's ranges.
struct DjiWpml {
  std::string template_kml;      ///< wpmz/template.kml
  std::string waylines_wpml;     ///< wpmz/waylines.wpml
  std::vector<DjiClamp> clamps;  ///< the same in both files
};

/// Throws ceilplan::InputError for an invalid route, origin or options, and for a gimbal pitch
/// outside the payload's range (naming the waypoint).
DjiWpml djiWpml(const mission::SortieRoute& route, const mission::GeodeticOrigin& origin,
                const DjiWpmlOptions& options = {});

/// The KMZ (zip, deflated), written atomically.
void writeDjiKmz(const std::filesystem::path& file, const mission::SortieRoute& route,
                 const mission::GeodeticOrigin& origin, const DjiWpmlOptions& options = {});

}  // namespace ceilplan::io
