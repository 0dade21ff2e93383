#pragma once
/// @file
/// Where a mission's map frame (x east, y north, z up, metres) lies on the Earth.

namespace ceilplan::mission {

/// WGS84 latitude and longitude (degrees) and altitude above mean sea level (metres) of the map
/// frame's origin.
struct GeodeticOrigin {
  double latitude_deg = 0.0;   ///< WGS84 latitude, degrees
  double longitude_deg = 0.0;  ///< WGS84 longitude, degrees
  double altitude_m = 0.0;     ///< above mean sea level

  /// Throws ceilplan::InputError for a latitude outside [-90, 90], a longitude outside
  /// [-180, 180] or a non-finite altitude.
  void validate() const;
};

}  // namespace ceilplan::mission
