#include "ceilplan/io/geo_export.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/io/atomic_file.hpp"
#include "ceilplan/io/autopilot_export.hpp"
#include "ceilplan/io/json_values.hpp"

#include <tinyxml2.h>

#include <cmath>

namespace ceilplan::io {
namespace {

void validate(const std::vector<mission::SortieRoute>& routes, const mission::GeodeticOrigin& origin) {
  origin.validate();
  if (routes.empty()) throw InputError("no route to export");
  for (const mission::SortieRoute& route : routes) route.validate();
}

// [lon, lat, height], as GeoJSON and KML order them.
nlohmann::json lonLatHeight(const mission::GeodeticOrigin& origin, const Eigen::Vector3d& local_m) {
  const Eigen::Vector3d g = toGeodetic(origin, local_m);
  return {g.y(), g.x(), g.z()};
}

std::string kmlCoordinate(const mission::GeodeticOrigin& origin, const Eigen::Vector3d& local_m) {
  const Eigen::Vector3d g = toGeodetic(origin, local_m);
  return formatFixed(g.y(), 9) + "," + formatFixed(g.x(), 9) + "," + formatFixed(g.z(), 4);
}

nlohmann::json optionalNumber(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

// The fields both formats give each waypoint.
nlohmann::json waypointProperties(const mission::SortieRoute& route, std::size_t k, double heading_deg) {
  const mission::RouteWaypoint& w = route.waypoints[k];
  return {{"kind", "waypoint"},
          {"sortie", route.sortie},
          {"index", k + 1},
          {"name", w.name},
          {"hold_s", w.hold_s},
          {"yaw_deg", heading_deg},
          {"speed_m_s", route.speedInto_m_s(k + 1)},
          {"gimbal_pitch_deg", optionalNumber(w.gimbal_pitch_deg)},
          {"take_photo", w.take_photo},
          {"contact_reading", w.contact_reading},
          {"height_above_home_m", w.position_m.z() - route.home_m.z()},
          {"map_m", {w.position_m.x(), w.position_m.y(), w.position_m.z()}}};
}

std::string waypointLabel(const mission::SortieRoute& route, std::size_t k) {
  const mission::RouteWaypoint& w = route.waypoints[k];
  return w.name.empty() ? "sortie " + std::to_string(route.sortie) + " waypoint " + std::to_string(k + 1) : w.name;
}

}  // namespace

nlohmann::json routeWaypointsJson(const mission::SortieRoute& route) {
  const std::vector<double> headings = mission::headingsInEffect_deg(route);
  nlohmann::json waypoints = nlohmann::json::array();
  for (std::size_t k = 0; k < route.waypoints.size(); ++k)
    waypoints.push_back(waypointProperties(route, k, headings[k]));
  return waypoints;
}

nlohmann::json routesGeoJson(const std::vector<mission::SortieRoute>& routes, const mission::GeodeticOrigin& origin) {
  validate(routes, origin);
  nlohmann::json features = nlohmann::json::array();
  features.push_back({{"type", "Feature"},
                      {"geometry", {{"type", "Point"}, {"coordinates", lonLatHeight(origin, routes.front().home_m)}}},
                      {"properties", {{"kind", "home"}, {"name", "home"}}}});
  for (const mission::SortieRoute& route : routes) {
    nlohmann::json line = nlohmann::json::array({lonLatHeight(origin, route.home_m)});
    double length = 0.0;
    Eigen::Vector3d previous = route.home_m;
    for (const mission::RouteWaypoint& w : route.waypoints) {
      line.push_back(lonLatHeight(origin, w.position_m));
      length += (w.position_m - previous).norm();
      previous = w.position_m;
    }
    features.push_back({{"type", "Feature"},
                        {"geometry", {{"type", "LineString"}, {"coordinates", line}}},
                        {"properties", {{"kind", "route"}, {"sortie", route.sortie}, {"length_m", length}}}});
    const std::vector<double> headings = mission::headingsInEffect_deg(route);
    for (std::size_t k = 0; k < route.waypoints.size(); ++k)
      features.push_back(
          {{"type", "Feature"},
           {"geometry", {{"type", "Point"}, {"coordinates", lonLatHeight(origin, route.waypoints[k].position_m)}}},
           {"properties", waypointProperties(route, k, headings[k])}});
  }
  return {{"type", "FeatureCollection"},
          {"ceilplan_origin",
           {{"lat_deg", origin.latitude_deg}, {"lon_deg", origin.longitude_deg}, {"alt_m", origin.altitude_m}}},
          {"features", features}};
}

std::string routesKml(const std::vector<mission::SortieRoute>& routes, const mission::GeodeticOrigin& origin,
                      const std::string& title) {
  validate(routes, origin);
  tinyxml2::XMLPrinter xml;
  xml.PushHeader(false, true);
  xml.OpenElement("kml");
  xml.PushAttribute("xmlns", "http://www.opengis.net/kml/2.2");
  xml.OpenElement("Document");
  const auto text = [&](const char* element, const std::string& value) {
    xml.OpenElement(element);
    xml.PushText(value.c_str());
    xml.CloseElement();
  };
  text("name", title);
  // Styles: the route in orange (KML colours are aabbggrr), waypoints as small pins.
  xml.OpenElement("Style");
  xml.PushAttribute("id", "route");
  xml.OpenElement("LineStyle");
  text("color", "ff0080ff");
  text("width", "3");
  xml.CloseElement();
  xml.CloseElement();
  const auto point = [&](const std::string& name, const std::string& description, const Eigen::Vector3d& local_m,
                         const nlohmann::json& data) {
    xml.OpenElement("Placemark");
    text("name", name);
    if (!description.empty()) text("description", description);
    if (!data.is_null()) {
      xml.OpenElement("ExtendedData");
      for (const auto& [key, value] : data.items()) {
        xml.OpenElement("Data");
        xml.PushAttribute("name", key.c_str());
        text("value", value.is_string() ? value.get<std::string>() : jsonText(value));
        xml.CloseElement();
      }
      xml.CloseElement();
    }
    xml.OpenElement("Point");
    text("altitudeMode", "absolute");
    text("coordinates", kmlCoordinate(origin, local_m));
    xml.CloseElement();
    xml.CloseElement();
  };
  point("home", "take-off and landing", routes.front().home_m, nullptr);
  for (const mission::SortieRoute& route : routes) {
    xml.OpenElement("Folder");
    text("name", "sortie " + std::to_string(route.sortie));
    xml.OpenElement("Placemark");
    text("name", "sortie " + std::to_string(route.sortie) + " route");
    text("styleUrl", "#route");
    xml.OpenElement("LineString");
    text("altitudeMode", "absolute");
    std::string coordinates = kmlCoordinate(origin, route.home_m);
    for (const mission::RouteWaypoint& w : route.waypoints) coordinates += " " + kmlCoordinate(origin, w.position_m);
    text("coordinates", coordinates);
    xml.CloseElement();
    xml.CloseElement();
    const std::vector<double> headings = mission::headingsInEffect_deg(route);
    for (std::size_t k = 0; k < route.waypoints.size(); ++k) {
      const mission::RouteWaypoint& w = route.waypoints[k];
      std::string description =
          "hold " + formatNumber(w.hold_s) + " s, heading " + formatNumber(headings[k], 4) + " deg";
      if (w.gimbal_pitch_deg) description += ", gimbal " + formatNumber(*w.gimbal_pitch_deg, 4) + " deg";
      if (w.take_photo) description += ", photo";
      if (w.contact_reading) description += ", contact reading";
      point(waypointLabel(route, k), description, w.position_m, waypointProperties(route, k, headings[k]));
    }
    xml.CloseElement();
  }
  xml.CloseElement();
  xml.CloseElement();
  return xml.CStr();
}

void writeRoutesGeoJson(const std::filesystem::path& file, const std::vector<mission::SortieRoute>& routes,
                        const mission::GeodeticOrigin& origin) {
  const std::string text = jsonText(routesGeoJson(routes, origin), 1) + "\n";
  writeTextAtomically(file, [&](std::ostream& out) { out << text; });
}

void writeRoutesKml(const std::filesystem::path& file, const std::vector<mission::SortieRoute>& routes,
                    const mission::GeodeticOrigin& origin, const std::string& title) {
  const std::string text = routesKml(routes, origin, title);
  writeTextAtomically(file, [&](std::ostream& out) { out << text; });
}

}  // namespace ceilplan::io
