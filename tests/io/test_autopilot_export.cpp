// Autopilot export: the QGroundControl plan has every required field with the right type, its
// waypoints convert back to the local route within 1 cm, the WPL file has 12 tab-separated
// fields per row with home first, the mission takes off first, commands its speed before the
// first waypoint and lands last at home, camera, speed and yaw commands sit where the route asks
// for them with every parameter checked, a contact reading hovers without a photo, and a
// missing origin is a clear error.

#include "ceilplan/core/error.hpp"

#include "ceilplan/io/autopilot_export.hpp"
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace ceilplan::io {
namespace {

// The NAV_WAYPOINT items of a plan, in order.
std::vector<nlohmann::json> waypointItems(const nlohmann::json& plan) {
  std::vector<nlohmann::json> waypoints;
  for (const nlohmann::json& item : plan.at("mission").at("items"))
    if (item.at("command") == mav::kNavWaypoint) waypoints.push_back(item);
  return waypoints;
}

const mission::GeodeticOrigin kCambridge{52.218, 0.0923, 12.0};

AutopilotMission bridgeSortie() {
  AutopilotMission mission;
  mission.origin = kCambridge;
  mission.home_m = {-4.0, 0.0, 0.5};
  mission.waypoints = {{{-4.0, 0.0, 3.0}, 0.0, std::nullopt},
                       {{5.7, 0.2, 5.85}, 20.0, 90.0},
                       {{30.4, -1.1, 5.85}, 20.0, std::nullopt},
                       {{46.0, -2.8, 5.2}, 15.0, std::nullopt},
                       {{-4.0, 0.0, 3.0}, 0.0, std::nullopt}};
  mission.cruise_speed_m_s = 2.0;
  mission.hover_speed_m_s = 0.5;
  return mission;
}

TEST(AutopilotExport, PlanHasEveryRequiredFieldWithTheRightType) {
  const AutopilotMission mission = bridgeSortie();
  // Through text, as a ground station reads it.
  const nlohmann::json plan = nlohmann::json::parse(qgcPlan(mission).dump(2));
  EXPECT_EQ(plan.at("fileType"), "Plan");
  EXPECT_EQ(plan.at("version"), 1);
  EXPECT_EQ(plan.at("groundStation"), "ceilplan");
  const nlohmann::json& m = plan.at("mission");
  EXPECT_EQ(m.at("version"), 2);
  EXPECT_EQ(m.at("firmwareType"), 12);
  EXPECT_EQ(m.at("vehicleType"), 2);
  EXPECT_TRUE(m.at("cruiseSpeed").is_number());
  EXPECT_TRUE(m.at("hoverSpeed").is_number());
  ASSERT_TRUE(m.at("plannedHomePosition").is_array());
  ASSERT_EQ(m.at("plannedHomePosition").size(), 3u);
  for (const auto& v : m.at("plannedHomePosition")) EXPECT_TRUE(v.is_number());
  for (std::size_t k = 0; k < m.at("items").size(); ++k) {
    const nlohmann::json& item = m.at("items")[k];
    EXPECT_EQ(item.at("type"), "SimpleItem");
    EXPECT_EQ(item.at("autoContinue"), true);
    EXPECT_EQ(item.at("doJumpId"), static_cast<int>(k + 1));
    ASSERT_EQ(item.at("params").size(), 7u);
  }
  const std::vector<nlohmann::json> items = waypointItems(plan);
  ASSERT_EQ(items.size(), mission.waypoints.size());
  for (std::size_t k = 0; k < items.size(); ++k) {
    const nlohmann::json& item = items[k];
    EXPECT_EQ(item.at("frame"), 3);
    const nlohmann::json& params = item.at("params");
    ASSERT_EQ(params.size(), 7u);
    for (int p : {0, 1, 2, 4, 5, 6}) EXPECT_TRUE(params[p].is_number()) << "item " << k << " param " << p;
    EXPECT_TRUE(params[3].is_number()) << "yaw at every waypoint";
    EXPECT_DOUBLE_EQ(params[0].get<double>(), mission.waypoints[k].hold_s);
  }
  // Yaw: the heading in effect, the route's own at waypoint 2 and kept after it; before it the
  // bearing of the first horizontal motion (east, a little north).
  EXPECT_NEAR(items[0].at("params")[3].get<double>(), 88.8, 0.1);
  EXPECT_EQ(items[1].at("params")[3], 90.0);
  EXPECT_EQ(items[4].at("params")[3], 90.0);
  EXPECT_EQ(plan.at("ceilplan").at("ekf_origin").at("lat_deg"), kCambridge.latitude_deg);
  EXPECT_EQ(plan.at("ceilplan").at("ekf_origin").at("lon_deg"), kCambridge.longitude_deg);
  EXPECT_EQ(plan.at("ceilplan").at("ekf_origin").at("alt_m"), kCambridge.altitude_m);
  for (const char* section : {"geoFence", "rallyPoints"}) EXPECT_EQ(plan.at(section).at("version"), 2);
  EXPECT_TRUE(plan.at("geoFence").at("circles").is_array());
  EXPECT_TRUE(plan.at("geoFence").at("polygons").is_array());
  EXPECT_TRUE(plan.at("rallyPoints").at("points").is_array());

  AutopilotMission ardupilot = mission;
  ardupilot.autopilot = Autopilot::ArduPilot;
  EXPECT_EQ(qgcPlan(ardupilot)["mission"]["firmwareType"], 3);
}

TEST(AutopilotExport, PlanWaypointsConvertBackToTheLocalRouteWithinOneCentimetre) {
  const AutopilotMission mission = bridgeSortie();
  const nlohmann::json plan = nlohmann::json::parse(qgcPlan(mission).dump());
  const auto home = plan["mission"]["plannedHomePosition"].get<std::vector<double>>();
  EXPECT_LT((toLocal(kCambridge, {home[0], home[1], home[2]}) - mission.home_m).norm(), 0.01);
  const std::vector<nlohmann::json> items = waypointItems(plan);
  for (std::size_t k = 0; k < mission.waypoints.size(); ++k) {
    const auto params = items[k]["params"];
    const Eigen::Vector3d geodetic(params[4].get<double>(), params[5].get<double>(), home[2] + params[6].get<double>());
    EXPECT_LT((toLocal(kCambridge, geodetic) - mission.waypoints[k].position_m).norm(), 0.01) << "waypoint " << k;
  }
  // East is east and up is up: a waypoint 46 m east of the origin has a larger longitude.
  EXPECT_GT(items[3]["params"][5].get<double>(), kCambridge.longitude_deg);
  EXPECT_NEAR(items[1]["params"][6].get<double>(), 5.85 - 0.5, 0.01);
}

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  for (std::string field; std::getline(in, field, separator);) fields.push_back(field);
  return fields;
}

TEST(AutopilotExport, WplHasTwelveTabSeparatedFieldsAndHomeFirst) {
  const AutopilotMission mission = bridgeSortie();
  std::stringstream text(qgcWpl(mission));
  std::string line;
  std::getline(text, line);
  EXPECT_EQ(line, "QGC WPL 110");
  std::vector<std::vector<std::string>> rows;
  while (std::getline(text, line)) rows.push_back(split(line, '\t'));
  ASSERT_EQ(rows.size(), qgcPlan(mission)["mission"]["items"].size() + 1);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    ASSERT_EQ(rows[k].size(), 12u) << "row " << k;
    EXPECT_EQ(std::stoi(rows[k][0]), static_cast<int>(k));
    EXPECT_EQ(rows[k][11], "1");
  }
  EXPECT_EQ(rows[0][3], "16");
  EXPECT_EQ(rows[0][1], "1");   // home is the current item
  EXPECT_EQ(rows[1][3], "22");  // then the take-off ArduCopter needs to start AUTO from the ground
  const Eigen::Vector3d home(std::stod(rows[0][8]), std::stod(rows[0][9]), std::stod(rows[0][10]));
  EXPECT_LT((toLocal(kCambridge, home) - mission.home_m).norm(), 0.01);
  std::size_t waypoint = 0;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    if (rows[k][3] != "16") continue;
    EXPECT_EQ(rows[k][2], "3");
    const Eigen::Vector3d geodetic(std::stod(rows[k][8]), std::stod(rows[k][9]), home.z() + std::stod(rows[k][10]));
    EXPECT_LT((toLocal(kCambridge, geodetic) - mission.waypoints[waypoint].position_m).norm(), 0.01) << "row " << k;
    EXPECT_DOUBLE_EQ(std::stod(rows[k][4]), mission.waypoints[waypoint].hold_s);
    ++waypoint;
  }
  EXPECT_EQ(waypoint, mission.waypoints.size());
}

TEST(AutopilotExport, MissingOriginIsAClearError) {
  AutopilotMission mission = bridgeSortie();
  mission.origin.reset();
  for (auto write : {+[](const AutopilotMission& m) { qgcPlan(m); }, +[](const AutopilotMission& m) { qgcWpl(m); }}) {
    try {
      write(mission);
      FAIL() << "expected an error";
    } catch (const ceilplan::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("without the map's geodetic origin"), std::string::npos) << e.what();
    }
  }
}

TEST(AutopilotExport, RefusesBadNumbersAndWritesNothing) {
  const std::filesystem::path dir = testing::scratchDirectory("export_bad");
  AutopilotMission mission = bridgeSortie();
  mission.waypoints[2].position_m.y() = std::nan("");
  EXPECT_THROW(writeQgcPlan(dir / "mission.plan", mission), ceilplan::InputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "mission.plan"));
  mission = bridgeSortie();
  mission.waypoints[1].hold_s = -1;
  EXPECT_THROW(writeQgcWpl(dir / "mission.waypoints", mission), ceilplan::InputError);
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  mission = bridgeSortie();
  mission.origin->latitude_deg = 95;
  EXPECT_THROW(qgcPlan(mission), ceilplan::InputError);
  mission = bridgeSortie();
  mission.waypoints.clear();
  EXPECT_THROW(qgcPlan(mission), ceilplan::InputError);
}

TEST(AutopilotExport, WritesBothFilesWhole) {
  const std::filesystem::path dir = testing::scratchDirectory("export_files");
  writeQgcPlan(dir / "mission.plan", bridgeSortie());
  writeQgcWpl(dir / "mission.waypoints", bridgeSortie());
  EXPECT_EQ(nlohmann::json::parse(testing::readWholeFile(dir / "mission.plan")), qgcPlan(bridgeSortie()));
  EXPECT_EQ(testing::readWholeFile(dir / "mission.waypoints"), qgcWpl(bridgeSortie()));
}

// A photo route: a speed change, the gimbal pitched up for two photos, a distance trigger.
AutopilotMission cameraSortie() {
  AutopilotMission mission = bridgeSortie();
  mission.waypoints[1].gimbal_pitch_deg = 90.0;
  mission.waypoints[1].take_photo = true;
  mission.waypoints[1].speed_m_s = 0.5;          // slow from waypoint 2 to 3
  mission.waypoints[2].gimbal_pitch_deg = 90.0;  // unchanged: no second gimbal command
  mission.waypoints[2].take_photo = true;
  mission.waypoints[2].trigger_distance_m = 1.5;
  mission.waypoints[3].trigger_distance_m = 0.0;
  mission.waypoints[3].gimbal_pitch_deg = -30.0;
  return mission;
}

TEST(AutopilotExport, CameraSpeedAndYawCommandsWithEveryParameter) {
  const AutopilotMission mission = cameraSortie();
  const nlohmann::json plan = nlohmann::json::parse(qgcPlan(mission).dump(2));
  const nlohmann::json& items = plan["mission"]["items"];
  std::vector<int> commands;
  for (const auto& item : items) commands.push_back(item["command"]);
  // take-off, cruise, wp1; gimbal, wp2, photo; slow, wp3, photo, trigger on; cruise again, gimbal, wp4, trigger off;
  // wp5
  const std::vector<int> expected{22, 178, 16, 1000, 16, 2000, 178, 16, 2000, 206, 178, 1000, 16, 206, 16};
  EXPECT_EQ(commands, expected);
  for (std::size_t k = 0; k < items.size(); ++k) {
    const auto& item = items[k];
    EXPECT_EQ(item["type"], "SimpleItem");
    EXPECT_EQ(item["autoContinue"], true);
    EXPECT_EQ(item["doJumpId"], static_cast<int>(k + 1));
    ASSERT_EQ(item["params"].size(), 7u);
    const int command = item["command"];
    EXPECT_EQ(item["frame"], command == 16 || command == 22 ? 3 : 2) << k;
  }
  const auto params = [&](std::size_t k) { return items[k]["params"]; };
  // MAV_CMD_DO_GIMBAL_MANAGER_PITCHYAW: pitch, yaw (follow the vehicle), rates NaN (null), flags, 0, all gimbals.
  EXPECT_EQ(params(3), nlohmann::json::parse("[90.0, 0.0, null, null, 12, 0, 0]"));
  EXPECT_EQ(params(11), nlohmann::json::parse("[-30.0, 0.0, null, null, 12, 0, 0]"));
  // MAV_CMD_IMAGE_START_CAPTURE: all cameras, no interval, one image, sequence numbers 1 and 2,
  // param 7 reserved (NaN, common.xml).
  EXPECT_EQ(params(5), nlohmann::json::parse("[0, 0, 1, 1, 0, 0, null]"));
  EXPECT_EQ(params(8), nlohmann::json::parse("[0, 0, 1, 2, 0, 0, null]"));
  // MAV_CMD_DO_CHANGE_SPEED: ground speed, m/s, throttle unchanged; the cruise from the first leg.
  EXPECT_EQ(params(1), nlohmann::json::parse("[1, 2.0, -1, 0, 0, 0, 0]"));
  EXPECT_EQ(params(6), nlohmann::json::parse("[1, 0.5, -1, 0, 0, 0, 0]"));
  EXPECT_EQ(params(10), nlohmann::json::parse("[1, 2.0, -1, 0, 0, 0, 0]"));
  // MAV_CMD_DO_SET_CAM_TRIGG_DIST: distance, shutter default, trigger once now; 0 stops.
  EXPECT_EQ(params(9), nlohmann::json::parse("[1.5, 0, 1, 0, 0, 0, 0]"));
  EXPECT_EQ(params(13), nlohmann::json::parse("[0.0, 0, 0, 0, 0, 0, 0]"));
  // Waypoints keep their positions, holds and headings.
  std::size_t waypoint = 0;
  const auto home = plan["mission"]["plannedHomePosition"].get<std::vector<double>>();
  for (const auto& item : items) {
    if (item["command"] != 16) continue;
    const auto& p = item["params"];
    const Eigen::Vector3d geodetic(p[4].get<double>(), p[5].get<double>(), home[2] + p[6].get<double>());
    EXPECT_LT((toLocal(kCambridge, geodetic) - mission.waypoints[waypoint].position_m).norm(), 0.01);
    EXPECT_DOUBLE_EQ(p[0].get<double>(), mission.waypoints[waypoint].hold_s);
    EXPECT_DOUBLE_EQ(p[1].get<double>(), mission.acceptance_radius_m);
    EXPECT_DOUBLE_EQ(p[2].get<double>(), mission.pass_radius_m);
    ++waypoint;
  }
  EXPECT_EQ(waypoint, mission.waypoints.size());

  // The same sequence in WPL, NaN written as nan.
  std::stringstream text(qgcWpl(mission));
  std::string line;
  std::getline(text, line);
  std::getline(text, line);  // home
  std::size_t k = 0;
  while (std::getline(text, line)) {
    const std::vector<std::string> fields = split(line, '\t');
    ASSERT_EQ(fields.size(), 12u);
    ASSERT_LT(k, items.size());
    EXPECT_EQ(std::stoi(fields[3]), items[k]["command"].get<int>()) << line;
    EXPECT_EQ(std::stoi(fields[2]), items[k]["frame"].get<int>()) << line;
    for (int p = 0; p < 4; ++p) {
      const nlohmann::json& expected_param = items[k]["params"][p];
      if (expected_param.is_null()) {
        EXPECT_EQ(fields[4 + p], "nan") << line;
      } else {
        EXPECT_NEAR(std::stod(fields[4 + p]), expected_param.get<double>(), 1e-3) << line;
      }
    }
    if (items[k]["command"] != 16 && items[k]["command"] != 22) {
      for (int p = 4; p < 7; ++p) {
        const nlohmann::json& expected_param = items[k]["params"][p];
        if (expected_param.is_null()) {
          EXPECT_EQ(fields[4 + p], "nan") << line;
        } else {
          EXPECT_EQ(std::stod(fields[4 + p]), expected_param.get<double>()) << line;
        }
      }
    }
    ++k;
  }
  EXPECT_EQ(k, items.size());
}

// Speeds from a flight record differ by rounding where nothing changes: a command only where the
// speed moves 1 cm/s or more from the one last commanded, so slow drift still gets one.
TEST(AutopilotExport, ChangesSpeedOnlyWhereItChangesByACentimetrePerSecond) {
  AutopilotMission mission = bridgeSortie();
  mission.waypoints[0].speed_m_s = 2.0 + 1e-12;  // cruise, by rounding
  mission.waypoints[1].speed_m_s = 2.006;        // under 1 cm/s from the cruise commanded
  mission.waypoints[2].speed_m_s = 2.012;        // 1.2 cm/s from it: commanded
  mission.waypoints[3].speed_m_s = 0.5;
  const nlohmann::json plan = qgcPlan(mission);
  std::vector<double> commanded;
  for (const auto& item : plan["mission"]["items"])
    if (item["command"] == mav::kDoChangeSpeed) commanded.push_back(item["params"][1].get<double>());
  EXPECT_EQ(commanded, (std::vector<double>{2.0, 2.012, 0.5}));
}

// From the ground and back onto it: a vertical take-off to the route's height before anything
// else, the speed before the first waypoint (the .plan's cruiseSpeed never reaches the vehicle),
// and a route that ends at home flies its last waypoint above home, then lands there.
TEST(AutopilotExport, TakesOffFirstCommandsItsSpeedAndLandsAtHome) {
  AutopilotMission mission = bridgeSortie();
  mission.waypoints.back().position_m = mission.home_m;  // back home
  mission.takeoff_height_m = 2.5;
  mission.landing_height_m = 1.25;
  const nlohmann::json plan = nlohmann::json::parse(qgcPlan(mission).dump());
  const nlohmann::json& items = plan["mission"]["items"];
  const auto home = plan["mission"]["plannedHomePosition"].get<std::vector<double>>();
  ASSERT_GE(items.size(), 4u);
  EXPECT_EQ(items[0]["command"], mav::kNavTakeoff);
  EXPECT_EQ(items[0]["frame"], mav::kFrameGlobalRelativeAlt);
  EXPECT_EQ(items[0]["params"], nlohmann::json::parse("[0, 0, 0, null, " + nlohmann::json(home[0]).dump() + ", " +
                                                      nlohmann::json(home[1]).dump() + ", 2.5]"));
  EXPECT_EQ(items[1]["command"], mav::kDoChangeSpeed);
  EXPECT_EQ(items[1]["params"][1], mission.cruise_speed_m_s);
  EXPECT_EQ(items[2]["command"], mav::kNavWaypoint);
  const nlohmann::json& land = items.back();
  EXPECT_EQ(land["command"], mav::kNavLand);
  EXPECT_EQ(land["params"], nlohmann::json::parse("[0, 0, 0, null, " + nlohmann::json(home[0]).dump() + ", " +
                                                  nlohmann::json(home[1]).dump() + ", 0.0]"));
  const nlohmann::json& above_home = items[items.size() - 2];
  EXPECT_EQ(above_home["command"], mav::kNavWaypoint);
  const Eigen::Vector3d geodetic(above_home["params"][4].get<double>(), above_home["params"][5].get<double>(),
                                 home[2] + above_home["params"][6].get<double>());
  EXPECT_LT((toLocal(kCambridge, geodetic) - (mission.home_m + Eigen::Vector3d(0, 0, 1.25))).norm(), 0.01);
  // Without a height given: the first waypoint's height above home (2.5 m here), at least 1 m.
  mission.takeoff_height_m.reset();
  EXPECT_DOUBLE_EQ(qgcPlan(mission)["mission"]["items"][0]["params"][6].get<double>(), 2.5);
  mission.waypoints.front().position_m.z() = 0.8;
  EXPECT_DOUBLE_EQ(qgcPlan(mission)["mission"]["items"][0]["params"][6].get<double>(), mission::kMinTakeoffHeight_m);
  // A route that does not end at home does not land.
  EXPECT_NE(qgcPlan(bridgeSortie())["mission"]["items"].back()["command"], mav::kNavLand);
}

// A contact reading is a hover for the reading's time: no photo command.
TEST(AutopilotExport, AContactReadingHoversWithoutAPhoto) {
  AutopilotMission mission = bridgeSortie();
  mission.waypoints[1].contact_reading = true;
  mission.waypoints[1].hold_s = 12.0;
  mission.waypoints[2].take_photo = true;
  const nlohmann::json plan = qgcPlan(mission);
  std::vector<int> commands;
  for (const auto& item : plan["mission"]["items"]) commands.push_back(item["command"]);
  EXPECT_EQ(commands, (std::vector<int>{22, 178, 16, 16, 16, 2000, 16, 16}));
  EXPECT_EQ(waypointItems(plan)[1]["params"][0], 12.0);
  mission.waypoints[1].take_photo = true;
  EXPECT_THROW(qgcPlan(mission), ceilplan::InputError);  // a reading is not a photo
}

TEST(AutopilotExport, FromARouteAndOrigin) {
  mission::SortieRoute route = bridgeSortie();
  route.sortie = 2;
  const AutopilotMission m = autopilotMission(route, kCambridge, Autopilot::ArduPilot);
  EXPECT_EQ(m.sortie, 2);
  EXPECT_EQ(m.waypoints.size(), route.waypoints.size());
  EXPECT_EQ(qgcPlan(m)["mission"]["firmwareType"], 3);
  EXPECT_EQ(qgcPlan(m)["ceilplan"]["sortie"], 2);
}

TEST(AutopilotExport, OneFilePerSortie) {
  EXPECT_EQ(sortieFileName("out/mission.plan", 1, 1), std::filesystem::path("out/mission.plan"));
  EXPECT_EQ(sortieFileName("out/mission.plan", 1, 3), std::filesystem::path("out/mission_sortie1.plan"));
  EXPECT_EQ(sortieFileName("out/mission.waypoints", 3, 3), std::filesystem::path("out/mission_sortie3.waypoints"));
  EXPECT_THROW(sortieFileName("mission.plan", 0, 2), ceilplan::InputError);
  EXPECT_THROW(sortieFileName("mission.plan", 3, 2), ceilplan::InputError);
}

}  // namespace
}  // namespace ceilplan::io
