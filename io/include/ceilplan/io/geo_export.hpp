#pragma once
/// @file
/// Each sortie's route and waypoints for GIS and Google Earth: GeoJSON (RFC 7946) and KML 2.2.
/// Positions go from the map frame to WGS84 through GeographicLib's LocalCartesian at the
/// mission's geodetic origin (as the autopilot files). Heights are the origin's altitude plus the
/// map's z: KML's altitudeMode "absolute" (above sea level, as the origin's altitude is given);
/// no geoid model is applied, so GeoJSON's third coordinate carries the same number.

#include "ceilplan/mission/geodetic_origin.hpp"
#include "ceilplan/mission/sortie_route.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace ceilplan::io {

/// A FeatureCollection: per sortie, a LineString "route" (home, then every waypoint) and a Point
/// per waypoint (properties: kind "waypoint", sortie, index from 1, name, hold_s, yaw_deg (the
/// heading in effect), speed_m_s (towards the next), gimbal_pitch_deg (or null), take_photo,
/// height_above_home_m, map_m [x, y, z]); one Point "home". Coordinates [lon, lat, height].
/// Throws ceilplan::InputError for an invalid route or origin.
nlohmann::json routesGeoJson(const std::vector<mission::SortieRoute>& routes, const mission::GeodeticOrigin& origin);

/// The route's waypoints with the fields both formats give each (above, without coordinates), in
/// the map frame: what Python's Tour.sorties carry.
nlohmann::json routeWaypointsJson(const mission::SortieRoute& route);

/// A KML document `title`: a Folder per sortie with the route as a LineString and a Placemark per
/// waypoint (name, description, ExtendedData with the same fields as GeoJSON), and home.
std::string routesKml(const std::vector<mission::SortieRoute>& routes, const mission::GeodeticOrigin& origin,
                      const std::string& title);

/// Both written atomically (whole or not at all).
void writeRoutesGeoJson(const std::filesystem::path& file, const std::vector<mission::SortieRoute>& routes,
                        const mission::GeodeticOrigin& origin);
/// routes.kml: every sortie's route, titled `title`, written atomically.
void writeRoutesKml(const std::filesystem::path& file, const std::vector<mission::SortieRoute>& routes,
                    const mission::GeodeticOrigin& origin, const std::string& title);

}  // namespace ceilplan::io
