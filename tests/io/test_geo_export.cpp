// KML and GeoJSON: parsed back with tinyxml2 and nlohmann::json, every required element is
// there, and each coordinate converts back to the route within 1 cm.

#include "ceilplan/core/error.hpp"
#include "ceilplan/io/autopilot_export.hpp"
#include "ceilplan/io/geo_export.hpp"
#include "export_parsers.hpp"
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace ceilplan::io {
namespace {

using testing::children;
using testing::childText;

const mission::GeodeticOrigin kOrigin{47.3769, 8.5417, 408.0};

std::vector<mission::SortieRoute> twoSorties() {
  mission::SortieRoute one;
  one.home_m = {-4, 0, 0.5};
  one.waypoints = {{{-4, 0, 3}}, {{10, 2, 5.5}, 15.0, 30.0}, {{-4, 0, 0.5}}};
  one.waypoints[1].name = "crown <north> & wall";  // escaped in XML
  one.waypoints[1].gimbal_pitch_deg = 75.0;
  one.waypoints[1].take_photo = true;
  mission::SortieRoute two = one;
  two.sortie = 2;
  two.waypoints[1] = {{20, -3, 4.0}, 10.0};
  return {one, two};
}

Eigen::Vector3d local(const nlohmann::json& lon_lat_height) {
  return toLocal(kOrigin,
                 {lon_lat_height[1].get<double>(), lon_lat_height[0].get<double>(), lon_lat_height[2].get<double>()});
}

TEST(GeoJson, FeaturesForEverySortieConvertBackWithinOneCentimetre) {
  const auto routes = twoSorties();
  const std::filesystem::path dir = testing::scratchDirectory("geojson");
  writeRoutesGeoJson(dir / "route.geojson", routes, kOrigin);
  const nlohmann::json json = nlohmann::json::parse(testing::readWholeFile(dir / "route.geojson"));
  EXPECT_EQ(json.at("type"), "FeatureCollection");
  const nlohmann::json& features = json.at("features");
  ASSERT_EQ(features.size(), 1 + 2 * (1 + 3));  // home, then per sortie a route and three waypoints
  EXPECT_EQ(features[0]["properties"]["kind"], "home");
  EXPECT_LT((local(features[0]["geometry"]["coordinates"]) - routes[0].home_m).norm(), 0.01);
  std::size_t f = 1;
  for (const mission::SortieRoute& route : routes) {
    const nlohmann::json& line = features[f++];
    EXPECT_EQ(line.at("type"), "Feature");
    EXPECT_EQ(line["geometry"]["type"], "LineString");
    EXPECT_EQ(line["properties"]["sortie"], route.sortie);
    const nlohmann::json& coordinates = line["geometry"]["coordinates"];
    ASSERT_EQ(coordinates.size(), route.waypoints.size() + 1);
    EXPECT_LT((local(coordinates[0]) - route.home_m).norm(), 0.01);
    for (std::size_t k = 0; k < route.waypoints.size(); ++k) {
      EXPECT_LT((local(coordinates[k + 1]) - route.waypoints[k].position_m).norm(), 0.01);
      const nlohmann::json& point = features[f++];
      EXPECT_EQ(point["geometry"]["type"], "Point");
      EXPECT_LT((local(point["geometry"]["coordinates"]) - route.waypoints[k].position_m).norm(), 0.01);
      const nlohmann::json& p = point["properties"];
      EXPECT_EQ(p["kind"], "waypoint");
      EXPECT_EQ(p["sortie"], route.sortie);
      EXPECT_EQ(p["index"], k + 1);
      EXPECT_EQ(p["hold_s"], route.waypoints[k].hold_s);
      EXPECT_EQ(p["take_photo"], route.waypoints[k].take_photo);
      EXPECT_NEAR(p["height_above_home_m"].get<double>(), route.waypoints[k].position_m.z() - route.home_m.z(), 1e-12);
      EXPECT_TRUE(p["yaw_deg"].is_number());
      EXPECT_EQ(p["speed_m_s"], route.speedInto_m_s(k + 1));
      EXPECT_EQ(p["map_m"][0], route.waypoints[k].position_m.x());
    }
  }
  EXPECT_EQ(features[3]["properties"]["gimbal_pitch_deg"], 75.0);
  EXPECT_EQ(features[3]["properties"]["yaw_deg"], 30.0);
  EXPECT_TRUE(features[2]["properties"]["gimbal_pitch_deg"].is_null());
}

TEST(Kml, DocumentWithAFolderPerSortieConvertsBackWithinOneCentimetre) {
  const auto routes = twoSorties();
  const std::filesystem::path dir = testing::scratchDirectory("kml");
  writeRoutesKml(dir / "route.kml", routes, kOrigin, "tunnel crown");
  tinyxml2::XMLDocument xml;
  ASSERT_EQ(xml.LoadFile((dir / "route.kml").c_str()), tinyxml2::XML_SUCCESS) << xml.ErrorStr();
  const tinyxml2::XMLElement* kml = xml.RootElement();
  EXPECT_STREQ(kml->Name(), "kml");
  EXPECT_STREQ(kml->Attribute("xmlns"), "http://www.opengis.net/kml/2.2");
  const tinyxml2::XMLElement* document = kml->FirstChildElement("Document");
  ASSERT_NE(document, nullptr);
  EXPECT_EQ(childText(document, "name"), "tunnel crown");
  const auto parse = [](const std::string& text) {
    std::vector<Eigen::Vector3d> points;
    std::stringstream in(text);
    for (std::string triple; in >> triple;) {
      double lon, lat, height;
      EXPECT_EQ(std::sscanf(triple.c_str(), "%lf,%lf,%lf", &lon, &lat, &height), 3) << triple;
      points.push_back(toLocal(kOrigin, {lat, lon, height}));
    }
    return points;
  };
  const auto home = children(document, "Placemark");
  ASSERT_EQ(home.size(), 1u);
  EXPECT_LT((parse(childText(home[0]->FirstChildElement("Point"), "coordinates"))[0] - routes[0].home_m).norm(), 0.01);
  const auto folders = children(document, "Folder");
  ASSERT_EQ(folders.size(), routes.size());
  for (std::size_t s = 0; s < routes.size(); ++s) {
    const auto placemarks = children(folders[s], "Placemark");
    ASSERT_EQ(placemarks.size(), routes[s].waypoints.size() + 1);
    const tinyxml2::XMLElement* line = placemarks[0]->FirstChildElement("LineString");
    ASSERT_NE(line, nullptr);
    EXPECT_EQ(childText(line, "altitudeMode"), "absolute");
    const std::vector<Eigen::Vector3d> points = parse(childText(line, "coordinates"));
    ASSERT_EQ(points.size(), routes[s].waypoints.size() + 1);
    for (std::size_t k = 0; k < routes[s].waypoints.size(); ++k) {
      EXPECT_LT((points[k + 1] - routes[s].waypoints[k].position_m).norm(), 0.01);
      const tinyxml2::XMLElement* point = placemarks[k + 1]->FirstChildElement("Point");
      ASSERT_NE(point, nullptr);
      EXPECT_EQ(childText(point, "altitudeMode"), "absolute");
      EXPECT_LT((parse(childText(point, "coordinates"))[0] - routes[s].waypoints[k].position_m).norm(), 0.01);
      EXPECT_FALSE(childText(placemarks[k + 1], "name").empty());
      EXPECT_EQ(children(placemarks[k + 1]->FirstChildElement("ExtendedData"), "Data").size(),
                12u);  // contact_reading too
    }
  }
  EXPECT_EQ(childText(children(folders[0], "Placemark")[2], "name"), "crown <north> & wall");
}

TEST(GeoExport, RefusesBadInput) {
  auto routes = twoSorties();
  mission::GeodeticOrigin bad = kOrigin;
  bad.longitude_deg = 200;
  EXPECT_THROW(routesGeoJson(routes, bad), InputError);
  EXPECT_THROW(routesKml({}, kOrigin, "x"), InputError);
  routes[1].waypoints[0].hold_s = -1;
  EXPECT_THROW(routesKml(routes, kOrigin, "x"), InputError);
}

}  // namespace
}  // namespace ceilplan::io
