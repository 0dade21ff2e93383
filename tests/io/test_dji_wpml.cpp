// DJI WPML: the KMZ holds wpmz/template.kml and wpmz/waylines.wpml; both parse as XML with the
// elements DJI's reference requires, heights and speeds per waypoint, the actions in order, and
// every waypoint converts back to the route within 1 cm.

#include "ceilplan/core/error.hpp"
#include "ceilplan/io/autopilot_export.hpp"
#include "ceilplan/io/dji_wpml.hpp"
#include "export_parsers.hpp"
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <set>
#include <tuple>

namespace ceilplan::io {
namespace {

using testing::childNumber;
using testing::children;
using testing::childText;

const mission::GeodeticOrigin kOrigin{52.218, 0.0923, 12.0};

// Under a deck: up to the soffit, a photo looking up, a slow pass with a distance trigger, home.
mission::SortieRoute soffitSortie() {
  mission::SortieRoute route;
  route.home_m = {-4, 0, 0.5};
  route.cruise_speed_m_s = 2.0;
  route.waypoints = {{{-4, 0, 3}}, {{6, 0, 5.9}, 12.0, 90.0}, {{30, 0, 5.9}}, {{46, -2.8, 5.2}}, {{-4, 0, 0.5}}};
  route.waypoints[1].gimbal_pitch_deg = 30.0;
  route.waypoints[1].take_photo = true;
  route.waypoints[1].name = "deck_bay_06";
  route.waypoints[1].speed_m_s = 1.0;
  route.waypoints[1].trigger_distance_m = 2.0;
  route.waypoints[2].trigger_distance_m = 0.0;
  route.waypoints[3].yaw_deg = 200.0;
  return route;
}

struct Files {
  tinyxml2::XMLDocument template_kml, waylines;
};

void parseKmz(const std::filesystem::path& kmz, Files& files) {
  const auto entries = testing::readZip(kmz);
  ASSERT_EQ(entries.size(), 2u);
  ASSERT_TRUE(entries.count("wpmz/template.kml"));
  ASSERT_TRUE(entries.count("wpmz/waylines.wpml"));
  ASSERT_EQ(files.template_kml.Parse(entries.at("wpmz/template.kml").c_str()), tinyxml2::XML_SUCCESS);
  ASSERT_EQ(files.waylines.Parse(entries.at("wpmz/waylines.wpml").c_str()), tinyxml2::XML_SUCCESS);
}

void checkMissionConfig(const tinyxml2::XMLElement* document, const DjiWpmlOptions& options) {
  const tinyxml2::XMLElement* config = document->FirstChildElement("wpml:missionConfig");
  ASSERT_NE(config, nullptr);
  EXPECT_EQ(childText(config, "wpml:flyToWaylineMode"), "safely");
  EXPECT_EQ(childText(config, "wpml:finishAction"), options.finish_action);
  EXPECT_EQ(childText(config, "wpml:exitOnRCLost"), "executeLostAction");
  EXPECT_EQ(childText(config, "wpml:executeRCLostAction"), options.rc_lost_action);
  EXPECT_NEAR(childNumber(config, "wpml:takeOffSecurityHeight"), 2.5, 1e-9);  // the first waypoint's height
  EXPECT_EQ(childNumber(config, "wpml:globalTransitionalSpeed"), 2.0);
  EXPECT_EQ(childNumber(config, "wpml:globalRTHHeight"), options.rth_height_m);  // required, [2, 1500]
  const tinyxml2::XMLElement* drone = config->FirstChildElement("wpml:droneInfo");
  EXPECT_EQ(childNumber(drone, "wpml:droneEnumValue"), options.drone_enum);
  EXPECT_EQ(childNumber(drone, "wpml:droneSubEnumValue"), options.drone_sub_enum);
  const tinyxml2::XMLElement* payload = config->FirstChildElement("wpml:payloadInfo");
  EXPECT_EQ(childNumber(payload, "wpml:payloadEnumValue"), options.payload_enum);
  EXPECT_EQ(childNumber(payload, "wpml:payloadPositionIndex"), options.payload_position);
}

std::vector<std::string> actionFunctions(const tinyxml2::XMLElement* group) {
  std::vector<std::string> functions;
  int id = 0;
  for (const auto* action : children(group, "wpml:action")) {
    EXPECT_EQ(childNumber(action, "wpml:actionId"), id++);
    EXPECT_NE(action->FirstChildElement("wpml:actionActuatorFuncParam"), nullptr);
    functions.push_back(childText(action, "wpml:actionActuatorFunc"));
  }
  return functions;
}

TEST(DjiWpml, KmzHoldsBothFilesWithEveryRequiredElement) {
  const mission::SortieRoute route = soffitSortie();
  const std::filesystem::path dir = testing::scratchDirectory("dji");
  const DjiWpmlOptions options;
  writeDjiKmz(dir / "mission.kmz", route, kOrigin, options);
  Files files;
  parseKmz(dir / "mission.kmz", files);
  const std::vector<double> headings = mission::headingsInEffect_deg(route);
  const Eigen::Vector3d home = toGeodetic(kOrigin, route.home_m);
  for (const bool is_template : {true, false}) {
    SCOPED_TRACE(is_template ? "template.kml" : "waylines.wpml");
    const tinyxml2::XMLElement* kml = (is_template ? files.template_kml : files.waylines).RootElement();
    ASSERT_NE(kml, nullptr);
    EXPECT_STREQ(kml->Name(), "kml");
    EXPECT_STREQ(kml->Attribute("xmlns"), "http://www.opengis.net/kml/2.2");
    EXPECT_STREQ(kml->Attribute("xmlns:wpml"), "http://www.dji.com/wpmz/1.0.2");
    const tinyxml2::XMLElement* document = kml->FirstChildElement("Document");
    ASSERT_NE(document, nullptr);
    checkMissionConfig(document, options);
    const tinyxml2::XMLElement* folder = document->FirstChildElement("Folder");
    ASSERT_NE(folder, nullptr);
    EXPECT_EQ(childNumber(folder, "wpml:templateId"), 0);
    EXPECT_EQ(childNumber(folder, "wpml:autoFlightSpeed"), 2.0);
    if (is_template) {
      EXPECT_EQ(childText(folder, "wpml:templateType"), "waypoint");
      const tinyxml2::XMLElement* system = folder->FirstChildElement("wpml:waylineCoordinateSysParam");
      EXPECT_EQ(childText(system, "wpml:coordinateMode"), "WGS84");
      EXPECT_EQ(childText(system, "wpml:heightMode"), "relativeToStartPoint");
      EXPECT_EQ(childText(folder, "wpml:gimbalPitchMode"), "usePointSetting");
      EXPECT_NE(folder->FirstChildElement("wpml:globalWaypointHeadingParam"), nullptr);
      // DJI's required element; globalWaypointTurnParam is not one DJI defines.
      EXPECT_EQ(childText(folder, "wpml:globalWaypointTurnMode"), "toPointAndStopWithDiscontinuityCurvature");
      EXPECT_EQ(folder->FirstChildElement("wpml:globalWaypointTurnParam"), nullptr);
      EXPECT_EQ(folder->FirstChildElement("wpml:globalUseStraightLine"), nullptr);  // for the turning modes only
      EXPECT_EQ(folder->FirstChildElement("wpml:caliFlightEnable"), nullptr);       // a mapping template's
    } else {
      EXPECT_EQ(childText(folder, "wpml:executeHeightMode"), "relativeToStartPoint");
      EXPECT_EQ(childNumber(folder, "wpml:waylineId"), 0);
      EXPECT_GT(childNumber(folder, "wpml:distance"), 100.0);
      EXPECT_GT(childNumber(folder, "wpml:duration"), 12.0);
    }
    const auto placemarks = children(folder, "Placemark");
    ASSERT_EQ(placemarks.size(), route.waypoints.size());
    for (std::size_t k = 0; k < placemarks.size(); ++k) {
      const tinyxml2::XMLElement* p = placemarks[k];
      EXPECT_EQ(childNumber(p, "wpml:index"), static_cast<double>(k));
      double lon = 0, lat = 0;
      ASSERT_EQ(std::sscanf(childText(p->FirstChildElement("Point"), "coordinates").c_str(), "%lf,%lf", &lon, &lat), 2);
      const double height = childNumber(p, is_template ? "wpml:height" : "wpml:executeHeight");
      // Heights above the take-off point: back to the map frame within 1 cm; the route ends at
      // home, so its last waypoint is above home at the landing height (the last but one's, 4.7 m).
      const Eigen::Vector3d flown = k + 1 < placemarks.size()
                                        ? route.waypoints[k].position_m
                                        : Eigen::Vector3d(route.home_m + Eigen::Vector3d(0, 0, 4.7));
      const Eigen::Vector3d back = toLocal(kOrigin, {lat, lon, home.z() + height});
      EXPECT_LT((back - flown).norm(), 0.01) << "waypoint " << k;
      if (is_template) {
        EXPECT_NEAR(childNumber(p, "wpml:ellipsoidHeight"), toGeodetic(kOrigin, flown).z(), 1e-3);
        EXPECT_EQ(childNumber(p, "wpml:useGlobalHeight"), 0);
        EXPECT_EQ(childNumber(p, "wpml:useGlobalSpeed"), 0);
        EXPECT_EQ(childNumber(p, "wpml:useGlobalHeadingParam"), 0);
        EXPECT_EQ(childNumber(p, "wpml:useGlobalTurnParam"), 0);
      }
      EXPECT_DOUBLE_EQ(childNumber(p, "wpml:waypointSpeed"), route.speedInto_m_s(k + 1));
      const tinyxml2::XMLElement* heading = p->FirstChildElement("wpml:waypointHeadingParam");
      EXPECT_EQ(childText(heading, "wpml:waypointHeadingMode"), "smoothTransition");
      const double angle = childNumber(heading, "wpml:waypointHeadingAngle");
      EXPECT_GT(angle, -180.0);
      EXPECT_LE(angle, 180.0);
      EXPECT_NEAR(std::remainder(angle - headings[k], 360.0), 0.0, 1e-3);
      EXPECT_EQ(heading->FirstChildElement("wpml:waypointHeadingAngleEnable"), nullptr);  // not DJI's
      EXPECT_EQ(childText(p->FirstChildElement("wpml:waypointTurnParam"), "wpml:waypointTurnMode"),
                "toPointAndStopWithDiscontinuityCurvature");
      EXPECT_EQ(p->FirstChildElement("wpml:waypointTurnParam")->FirstChildElement("wpml:waypointTurnDampingDist"),
                nullptr);
      EXPECT_EQ(p->FirstChildElement("wpml:useStraightLine"), nullptr);
    }
    // Actions on arrival, in order, and the distance trigger as its own group.
    const auto groups1 = children(placemarks[1], "wpml:actionGroup");
    ASSERT_EQ(groups1.size(), 2u);
    EXPECT_EQ(childText(groups1[0]->FirstChildElement("wpml:actionTrigger"), "wpml:actionTriggerType"), "reachPoint");
    EXPECT_EQ(childNumber(groups1[0], "wpml:actionGroupStartIndex"), 1);
    EXPECT_EQ(childNumber(groups1[0], "wpml:actionGroupEndIndex"), 1);
    EXPECT_EQ(childText(groups1[0], "wpml:actionGroupMode"), "sequence");
    const std::vector<std::string> arrival{"rotateYaw", "gimbalRotate", "hover", "takePhoto"};
    EXPECT_EQ(actionFunctions(groups1[0]), arrival);
    const auto actions = children(groups1[0], "wpml:action");
    const tinyxml2::XMLElement* yaw = actions[0]->FirstChildElement("wpml:actionActuatorFuncParam");
    EXPECT_EQ(childNumber(yaw, "wpml:aircraftHeading"), 90.0);
    EXPECT_EQ(childText(yaw, "wpml:aircraftPathMode"), "clockwise");  // already east: no turn either way
    const tinyxml2::XMLElement* gimbal = actions[1]->FirstChildElement("wpml:actionActuatorFuncParam");
    EXPECT_EQ(childText(gimbal, "wpml:gimbalRotateMode"), "absoluteAngle");
    EXPECT_EQ(childNumber(gimbal, "wpml:gimbalPitchRotateEnable"), 1);
    EXPECT_EQ(childNumber(gimbal, "wpml:gimbalPitchRotateAngle"), 30.0);
    EXPECT_EQ(childNumber(gimbal, "wpml:gimbalYawRotateEnable"), 0);
    EXPECT_EQ(childNumber(gimbal, "wpml:payloadPositionIndex"), 0);
    EXPECT_EQ(childNumber(actions[2]->FirstChildElement("wpml:actionActuatorFuncParam"), "wpml:hoverTime"), 12.0);
    const tinyxml2::XMLElement* photo = actions[3]->FirstChildElement("wpml:actionActuatorFuncParam");
    EXPECT_EQ(childNumber(photo, "wpml:payloadPositionIndex"), 0);
    EXPECT_EQ(childText(photo, "wpml:fileSuffix"), "deck_bay_06");
    const tinyxml2::XMLElement* trigger = groups1[1]->FirstChildElement("wpml:actionTrigger");
    EXPECT_EQ(childText(trigger, "wpml:actionTriggerType"), "multipleDistance");
    EXPECT_EQ(childNumber(trigger, "wpml:actionTriggerParam"), 2.0);
    EXPECT_EQ(childNumber(groups1[1], "wpml:actionGroupStartIndex"), 1);
    EXPECT_EQ(childNumber(groups1[1], "wpml:actionGroupEndIndex"), 2);
    EXPECT_EQ(actionFunctions(groups1[1]), std::vector<std::string>{"takePhoto"});
    // Waypoint 3 turns to 200 degrees (-160 in WPML's range) the short way round: clockwise.
    const auto groups3 = children(placemarks[3], "wpml:actionGroup");
    ASSERT_EQ(groups3.size(), 1u);
    EXPECT_EQ(actionFunctions(groups3[0]), std::vector<std::string>{"rotateYaw"});
    const tinyxml2::XMLElement* turn =
        children(groups3[0], "wpml:action")[0]->FirstChildElement("wpml:actionActuatorFuncParam");
    EXPECT_EQ(childNumber(turn, "wpml:aircraftHeading"), -160.0);
    EXPECT_EQ(childText(turn, "wpml:aircraftPathMode"), "clockwise");
    EXPECT_TRUE(children(placemarks[0], "wpml:actionGroup").empty());
    // Action group ids are unique in each file.
    std::set<int> ids;
    for (const auto* p : placemarks)
      for (const auto* g : children(p, "wpml:actionGroup"))
        EXPECT_TRUE(ids.insert(static_cast<int>(childNumber(g, "wpml:actionGroupId"))).second);
  }
}

TEST(DjiWpml, HeightsAboveSeaLevelNeedTheGeoidSeparation) {
  const mission::SortieRoute route = soffitSortie();
  DjiWpmlOptions options;
  options.height_mode = DjiHeightMode::SeaLevel;
  EXPECT_THROW(djiWpml(route, kOrigin, options), InputError);
  options.geoid_separation_m = 47.0;
  Files files;
  const DjiWpml wpml = djiWpml(route, kOrigin, options);
  ASSERT_EQ(files.template_kml.Parse(wpml.template_kml.c_str()), tinyxml2::XML_SUCCESS);
  ASSERT_EQ(files.waylines.Parse(wpml.waylines_wpml.c_str()), tinyxml2::XML_SUCCESS);
  const auto* template_folder =
      files.template_kml.RootElement()->FirstChildElement("Document")->FirstChildElement("Folder");
  const auto* waylines_folder =
      files.waylines.RootElement()->FirstChildElement("Document")->FirstChildElement("Folder");
  EXPECT_EQ(childText(template_folder->FirstChildElement("wpml:waylineCoordinateSysParam"), "wpml:heightMode"),
            "EGM96");
  EXPECT_EQ(childText(waylines_folder, "wpml:executeHeightMode"), "WGS84");
  const auto template_marks = children(template_folder, "Placemark");
  const auto waylines_marks = children(waylines_folder, "Placemark");
  for (std::size_t k = 0; k < route.waypoints.size(); ++k) {
    // The last waypoint, home, is flown at the landing height (the last but one's, 4.7 m up).
    const double z_m = k + 1 < route.waypoints.size() ? route.waypoints[k].position_m.z() : route.home_m.z() + 4.7;
    const double sea_level = kOrigin.altitude_m + z_m;  // within mm over 50 m
    EXPECT_NEAR(childNumber(template_marks[k], "wpml:height"), sea_level, 0.01);
    EXPECT_NEAR(childNumber(waylines_marks[k], "wpml:executeHeight"), sea_level + 47.0, 0.01);
    EXPECT_NEAR(childNumber(template_marks[k], "wpml:ellipsoidHeight"), sea_level + 47.0, 0.01);
  }
}

TEST(DjiWpml, ChoosesTheDroneAndRefusesAPitchThePayloadCannotReach) {
  mission::SortieRoute route = soffitSortie();
  DjiWpmlOptions options;
  options.drone_enum = 67;  // Matrice 30
  options.drone_sub_enum = 1;
  options.payload_enum = 53;
  options.gimbal_pitch_range_deg = {-120.0, 45.0};
  const std::filesystem::path dir = testing::scratchDirectory("dji_m30");
  writeDjiKmz(dir / "m30.kmz", route, kOrigin, options);
  Files files;
  parseKmz(dir / "m30.kmz", files);
  checkMissionConfig(files.waylines.RootElement()->FirstChildElement("Document"), options);
  route.waypoints[1].gimbal_pitch_deg = 90.0;
  try {
    writeDjiKmz(dir / "up.kmz", route, kOrigin, options);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("waypoint 2: gimbal pitch 90 deg is outside the payload's range [-120, 45]"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "up.kmz"));
  options = {};
  options.finish_action = "fly away";
  EXPECT_THROW(djiWpml(soffitSortie(), kOrigin, options), InputError);
  options = {};
  options.rth_height_m = 1.0;  // below DJI's 2 m
  EXPECT_THROW(djiWpml(soffitSortie(), kOrigin, options), InputError);
}

// Speeds below DJI's 1 m/s (the plan's 0.5 m/s inspection legs) and a take-off climb below its
// 1.2 m are written as the nearest allowed value, and each is recorded.
TEST(DjiWpml, ClampsToDjisRangesAndSaysWhere) {
  mission::SortieRoute route = soffitSortie();
  route.waypoints[2].speed_m_s = 0.5;
  route.cruise_speed_m_s = 20.0;
  route.takeoff_height_m = 0.6;
  const DjiWpml wpml = djiWpml(route, kOrigin);
  std::vector<std::tuple<std::size_t, std::string, double, double>> clamps;
  for (const DjiClamp& c : wpml.clamps) clamps.emplace_back(c.waypoint, c.element, c.planned, c.written);
  const std::vector<std::tuple<std::size_t, std::string, double, double>> expected{
      {0, "wpml:autoFlightSpeed", 20.0, 15.0}, {1, "wpml:waypointSpeed", 20.0, 15.0},
      {3, "wpml:waypointSpeed", 0.5, 1.0},     {4, "wpml:waypointSpeed", 20.0, 15.0},
      {5, "wpml:waypointSpeed", 20.0, 15.0},   {0, "wpml:takeOffSecurityHeight", 0.6, 1.2}};
  EXPECT_EQ(clamps, expected);
  tinyxml2::XMLDocument waylines;
  ASSERT_EQ(waylines.Parse(wpml.waylines_wpml.c_str()), tinyxml2::XML_SUCCESS);
  const auto* document = waylines.RootElement()->FirstChildElement("Document");
  const auto placemarks = children(document->FirstChildElement("Folder"), "Placemark");
  EXPECT_EQ(childNumber(placemarks[2], "wpml:waypointSpeed"), 1.0);
  EXPECT_EQ(childNumber(document->FirstChildElement("wpml:missionConfig"), "wpml:globalTransitionalSpeed"), 15.0);
  EXPECT_EQ(childNumber(document->FirstChildElement("wpml:missionConfig"), "wpml:takeOffSecurityHeight"), 1.2);
  EXPECT_TRUE(djiWpml(soffitSortie(), kOrigin).clamps.empty());
}

// A contact reading is a hover for the reading's time, never a photo.
TEST(DjiWpml, AContactReadingHoversWithoutAPhoto) {
  mission::SortieRoute route = soffitSortie();
  route.waypoints[1].take_photo = false;
  route.waypoints[1].contact_reading = true;
  route.waypoints[1].trigger_distance_m.reset();
  route.waypoints[2].trigger_distance_m.reset();
  tinyxml2::XMLDocument waylines;
  ASSERT_EQ(waylines.Parse(djiWpml(route, kOrigin).waylines_wpml.c_str()), tinyxml2::XML_SUCCESS);
  const auto placemarks =
      children(waylines.RootElement()->FirstChildElement("Document")->FirstChildElement("Folder"), "Placemark");
  const auto groups = children(placemarks[1], "wpml:actionGroup");
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_EQ(actionFunctions(groups[0]), (std::vector<std::string>{"rotateYaw", "gimbalRotate", "hover"}));
  EXPECT_EQ(childNumber(children(groups[0], "wpml:action")[2]->FirstChildElement("wpml:actionActuatorFuncParam"),
                        "wpml:hoverTime"),
            12.0);
}

// The mission file's names become DJI's enumeration values; the upper mount looks up.
TEST(DjiWpml, AircraftPayloadAndMountFromTheirNames) {
  mission::DjiAircraft aircraft;
  DjiWpmlOptions options = djiWpmlOptions(aircraft);
  EXPECT_EQ(std::make_tuple(options.drone_enum, options.drone_sub_enum, options.payload_enum, options.payload_position),
            std::make_tuple(89, 0, 42, 0));
  EXPECT_EQ(options.gimbal_pitch_range_deg, (std::array<double, 2>{-120.0, 30.0}));
  aircraft.payload_position = "upper";
  options = djiWpmlOptions(aircraft);
  EXPECT_EQ(options.payload_position, 2);
  EXPECT_EQ(options.gimbal_pitch_range_deg, (std::array<double, 2>{-30.0, 120.0}));
  mission::SortieRoute up = soffitSortie();
  up.waypoints[1].gimbal_pitch_deg = 90.0;
  EXPECT_NO_THROW(djiWpml(up, kOrigin, options));
  EXPECT_THROW(djiWpml(up, kOrigin, djiWpmlOptions(mission::DjiAircraft{})), InputError);
  aircraft = {};
  aircraft.drone = "m30t";
  EXPECT_THROW(djiWpmlOptions(aircraft), InputError);  // the M30T flies its own camera
  aircraft.payload = "builtin";
  aircraft.gimbal_pitch_range_deg = std::array<double, 2>{-90.0, 45.0};
  options = djiWpmlOptions(aircraft);
  EXPECT_EQ(std::make_tuple(options.drone_enum, options.drone_sub_enum, options.payload_enum),
            std::make_tuple(67, 1, 53));
  aircraft.payload_position = "upper";
  EXPECT_THROW(djiWpmlOptions(aircraft), InputError);  // one gimbal
  aircraft = {};
  aircraft.payload = "h30";  // range not built in, not given
  try {
    djiWpmlOptions(aircraft);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("give gimbal_pitch_range_deg"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ceilplan::io
