// Autopilot export: the QGroundControl plan has every required field with the right type, its
// waypoints convert back to the local route within 1 cm, the WPL file has 12 tab-separated
// fields per row with home first, camera, speed and yaw commands sit where the route asks for
// them with every parameter checked, and a missing origin is a clear error.

#include "ceilplan/core/error.hpp"

#include "ceilplan/io/autopilot_export.hpp"
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace ceilplan::io {
namespace {

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
  const nlohmann::json& items = m.at("items");
  ASSERT_EQ(items.size(), mission.waypoints.size());
  for (std::size_t k = 0; k < items.size(); ++k) {
    const nlohmann::json& item = items[k];
    EXPECT_EQ(item.at("type"), "SimpleItem");
    EXPECT_EQ(item.at("command"), 16);
    EXPECT_EQ(item.at("frame"), 3);
    EXPECT_EQ(item.at("autoContinue"), true);
    EXPECT_EQ(item.at("doJumpId"), static_cast<int>(k + 1));
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
  for (std::size_t k = 0; k < mission.waypoints.size(); ++k) {
    const auto params = plan["mission"]["items"][k]["params"];
    const Eigen::Vector3d geodetic(params[4].get<double>(), params[5].get<double>(), home[2] + params[6].get<double>());
    EXPECT_LT((toLocal(kCambridge, geodetic) - mission.waypoints[k].position_m).norm(), 0.01) << "waypoint " << k;
  }
  // East is east and up is up: a waypoint 46 m east of the origin has a larger longitude.
  EXPECT_GT(plan["mission"]["items"][3]["params"][5].get<double>(), kCambridge.longitude_deg);
  EXPECT_NEAR(plan["mission"]["items"][1]["params"][6].get<double>(), 5.85 - 0.5, 0.01);
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
  ASSERT_EQ(rows.size(), mission.waypoints.size() + 1);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    ASSERT_EQ(rows[k].size(), 12u) << "row " << k;
    EXPECT_EQ(std::stoi(rows[k][0]), static_cast<int>(k));
    EXPECT_EQ(rows[k][3], "16");
    EXPECT_EQ(rows[k][11], "1");
  }
  EXPECT_EQ(rows[0][1], "1");  // home is the current item
  const Eigen::Vector3d home(std::stod(rows[0][8]), std::stod(rows[0][9]), std::stod(rows[0][10]));
  EXPECT_LT((toLocal(kCambridge, home) - mission.home_m).norm(), 0.01);
  for (std::size_t k = 1; k < rows.size(); ++k) {
    EXPECT_EQ(rows[k][2], "3");
    const Eigen::Vector3d geodetic(std::stod(rows[k][8]), std::stod(rows[k][9]), home.z() + std::stod(rows[k][10]));
    EXPECT_LT((toLocal(kCambridge, geodetic) - mission.waypoints[k - 1].position_m).norm(), 0.01) << "row " << k;
    EXPECT_DOUBLE_EQ(std::stod(rows[k][4]), mission.waypoints[k - 1].hold_s);
  }
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
  mission.waypoints[1].speed_m_s = 0.5;  // slow from waypoint 2 to 3
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
  // wp1; gimbal, wp2, photo; slow, wp3, photo, trigger on; cruise again, gimbal, wp4, trigger off; wp5
  const std::vector<int> expected{16, 1000, 16, 2000, 178, 16, 2000, 206, 178, 1000, 16, 206, 16};
  EXPECT_EQ(commands, expected);
  for (std::size_t k = 0; k < items.size(); ++k) {
    const auto& item = items[k];
    EXPECT_EQ(item["type"], "SimpleItem");
    EXPECT_EQ(item["autoContinue"], true);
    EXPECT_EQ(item["doJumpId"], static_cast<int>(k + 1));
    ASSERT_EQ(item["params"].size(), 7u);
    EXPECT_EQ(item["frame"], item["command"] == 16 ? 3 : 2) << k;
  }
  const auto params = [&](std::size_t k) { return items[k]["params"]; };
  // MAV_CMD_DO_GIMBAL_MANAGER_PITCHYAW: pitch, yaw (follow the vehicle), rates NaN (null), flags, 0, all gimbals.
  EXPECT_EQ(params(1), nlohmann::json::parse("[90.0, 0.0, null, null, 12, 0, 0]"));
  EXPECT_EQ(params(9), nlohmann::json::parse("[-30.0, 0.0, null, null, 12, 0, 0]"));
  // MAV_CMD_IMAGE_START_CAPTURE: all cameras, no interval, one image, sequence numbers 1 and 2.
  EXPECT_EQ(params(3), nlohmann::json::parse("[0, 0, 1, 1, 0, 0, 0]"));
  EXPECT_EQ(params(6), nlohmann::json::parse("[0, 0, 1, 2, 0, 0, 0]"));
  // MAV_CMD_DO_CHANGE_SPEED: ground speed, m/s, throttle unchanged.
  EXPECT_EQ(params(4), nlohmann::json::parse("[1, 0.5, -1, 0, 0, 0, 0]"));
  EXPECT_EQ(params(8), nlohmann::json::parse("[1, 2.0, -1, 0, 0, 0, 0]"));
  // MAV_CMD_DO_SET_CAM_TRIGG_DIST: distance, shutter default, trigger once now; 0 stops.
  EXPECT_EQ(params(7), nlohmann::json::parse("[1.5, 0, 1, 0, 0, 0, 0]"));
  EXPECT_EQ(params(11), nlohmann::json::parse("[0.0, 0, 0, 0, 0, 0, 0]"));
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
    if (items[k]["command"] != 16) {
      for (int p = 4; p < 7; ++p) EXPECT_EQ(std::stod(fields[4 + p]), items[k]["params"][p].get<double>()) << line;
    }
    ++k;
  }
  EXPECT_EQ(k, items.size());
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
