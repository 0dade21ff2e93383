#pragma once
/// @file
/// The DJI aircraft and payload a tour's KMZ is written for, and the failsafe settings it carries
/// (mission file key `dji:`, docs/flying.md "DJI aircraft and payloads"). Names, not DJI's enum
/// numbers: io::djiWpmlOptions turns them into the values of DJI's product-support table.

#include <array>
#include <optional>
#include <string>

namespace ceilplan::mission {

/// The DJI aircraft, payload and failsafes a mission's KMZ is written for (mission key `dji:`, docs/flying.md).
struct DjiAircraft {
  std::string drone = "m350_rtk";         ///< m300_rtk, m350_rtk, m30, m30t, m3e, m3t, m3d, m3td, m4e, m4t
  std::string payload = "h20";            ///< h20, h20t, h20n, h30, h30t, or the drone's own camera ("builtin")
  std::string payload_position = "main";  ///< main (left, underslung), right, upper (M300/M350 RTK only)
  /// The payload's gimbal pitch range in this position, degrees (+90 straight up). None: the
  /// range DJI publishes for the payload (H20 series), mirrored on the upper mount.
  std::optional<std::array<double, 2>> gimbal_pitch_range_deg;
  /// Height above take-off that return-to-home climbs to first (WPML globalRTHHeight, DJI's
  /// range [2, 1500] m). Under a deck a climb strikes it: the lowest DJI allows by default.
  double rth_height_m = 2.0;
  std::string finish_action = "autoLand";  ///< goHome, autoLand, noAction, gotoFirstWaypoint
  std::string rc_lost_action = "hover";    ///< goBack, landing, hover
};

}  // namespace ceilplan::mission
