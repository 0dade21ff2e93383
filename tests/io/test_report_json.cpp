// The JSON reports of probe, mapinfo and current (io/report_json.hpp).

#include "analytic_maps.hpp"

#include "ceilplan/environment/position_probe.hpp"
#include "ceilplan/io/report_json.hpp"
#include "ceilplan/mission/vehicle.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace ceilplan::io {
namespace {

constexpr double kNone = std::numeric_limits<double>::infinity();

TEST(ReportJson, AProbeWritesNoSurfaceAsNullAndEachRotorWithItsOffset) {
  environment::VehicleGeometry vehicle;
  vehicle.rotor_positions_m = {{0.2, 0.1}, {-0.2, -0.1}};
  environment::PositionProbe probe;
  probe.body_m = {1.0, 2.0, 3.0};
  probe.ceiling = {{{0.25, 1.0, 0.3}, {kNone, 0.0, kNone}}, 0.25, 0.5, 0.3};
  probe.ground = {{{2.0, 1.0, 2.0}, {2.0, 1.0, 2.0}}, 2.0, 1.0, 2.0};
  probe.clearance_m = kNone;
  probe.assumes_free = probe.point_assumed_free = false;
  const nlohmann::json json = positionProbeJson(probe, vehicle);
  EXPECT_EQ(json["at"], nlohmann::json({1.0, 2.0, 3.0}));
  EXPECT_EQ(json["ceiling_gap_m"].get<double>(), 0.25);
  EXPECT_EQ(json["ceiling_coverage"].get<double>(), 0.5);
  EXPECT_TRUE(json["clearance_m"].is_null());
  EXPECT_TRUE(json["valid"].get<bool>());
  EXPECT_TRUE(json["violation"].is_null());
  EXPECT_FALSE(json["assumed_free"].get<bool>());
  EXPECT_FALSE(json["point_assumed_free"].get<bool>());
  ASSERT_EQ(json["rotors"].size(), 2u);
  EXPECT_EQ(json["rotors"][0]["offset_m"], nlohmann::json({0.2, 0.1}));
  EXPECT_TRUE(json["rotors"][1]["ceiling"]["nearest_gap_m"].is_null());
  EXPECT_EQ(json["rotors"][1]["ground"]["mean_gap_m"].get<double>(), 2.0);

  probe.violation = environment::Violation{0, {1.0, 2.0, 3.0}, environment::ViolationKind::Occupied};
  probe.assumes_free = true;
  const nlohmann::json invalid = positionProbeJson(probe, vehicle);
  EXPECT_TRUE(invalid["assumed_free"].get<bool>());
  EXPECT_FALSE(invalid["valid"].get<bool>());
  EXPECT_EQ(invalid["violation"], probe.violation->describe());
}

TEST(ReportJson, AProbeReportNamesTheMapTheVehicleFileOrBuiltInAndTheUnknownSpace) {
  const environment::OccupancyMap map = testing::room([](double, double) { return 2.4; });
  const environment::Environment environment(map, mission::Vehicle::defaultQuad().geometry);
  const environment::PositionProbe probe = environment::probePosition(environment, {0.0, 0.0, 1.0});
  const nlohmann::json built_in = probeReportJson(probe, environment, "room.bt", "");
  EXPECT_EQ(built_in["map"], "room.bt");
  EXPECT_EQ(built_in["vehicle"], "built-in: " + environment.vehicle().name);
  EXPECT_EQ(built_in["unknown"]["policy"], "occupied");
  EXPECT_EQ(built_in["at"], nlohmann::json({0.0, 0.0, 1.0}));
  EXPECT_EQ(built_in["rotors"].size(), environment.vehicle().rotor_positions_m.size());
  EXPECT_EQ(probeReportJson(probe, environment, "room.bt", "maps/vehicles/quad.yaml")["vehicle"],
            "maps/vehicles/quad.yaml");
}

TEST(ReportJson, MapStatisticsGroupExtentLeavesAndVolumes) {
  environment::MapStatistics stats;
  stats.resolution_m = 0.1;
  stats.extent_m = Eigen::AlignedBox3d(Eigen::Vector3d(-1, -2, 0), Eigen::Vector3d(1, 2, 3));
  stats.occupied_leaves = 10;
  stats.free_leaves = 20;
  stats.occupied_volume_m3 = 1.5;
  stats.free_volume_m3 = 2.5;
  stats.unknown_volume_m3 = 0.5;
  stats.unknown.policy = environment::UnknownPolicy::Free;
  stats.ceiling.min_headroom_m = 1.5;
  stats.ceiling_area_share = 0.25;
  const nlohmann::json json = mapStatisticsJson("maps/room.bt", stats);
  EXPECT_EQ(json["map"], "maps/room.bt");
  EXPECT_EQ(json["resolution_m"].get<double>(), 0.1);
  EXPECT_EQ(json["extent_m"]["min"], nlohmann::json({-1.0, -2.0, 0.0}));
  EXPECT_EQ(json["extent_m"]["max"], nlohmann::json({1.0, 2.0, 3.0}));
  EXPECT_EQ(json["leaves"]["free"].get<int>(), 20);
  EXPECT_EQ(json["volume_m3"]["unknown"].get<double>(), 0.5);
  EXPECT_EQ(json["ceiling_area_share"].get<double>(), 0.25);
  EXPECT_EQ(json["ceiling"]["min_headroom_m"].get<double>(), 1.5);
  EXPECT_EQ(json["ceiling"]["min_area_m2"].get<double>(), environment::CeilingCriteria{}.min_area_m2);
  EXPECT_EQ(json["unknown"]["policy"], "free");
}

TEST(ReportJson, ACurrentReportKeepsTheConditionAndEveryTermOfTheBreakdown) {
  energy::CurrentBreakdown b;
  b.current_a = 8.0;
  b.power_w = 120.0;
  b.climb_w = -3.0;
  b.ceiling_factor = 1.2;
  energy::FlightCondition flight;
  flight.soc = 0.7;
  flight.speed_m_s = 2.0;
  const nlohmann::json json = currentReportJson("quad", 0.05, 0.8, flight, b);
  EXPECT_EQ(json.size(), 8u + 1u + 11u);  // the condition with its wind, gap_m and the breakdown
  EXPECT_EQ(json["vehicle"], "quad");
  EXPECT_EQ(json["headwind_m_s"].get<double>(), 0.0);
  EXPECT_EQ(json["airspeed_m_s"].get<double>(), 2.0);  // still air: the ground speed
  EXPECT_EQ(json["soc"].get<double>(), 0.7);
  EXPECT_EQ(json["coverage"].get<double>(), 0.8);
  EXPECT_TRUE(json["ground_gap_m"].is_null());  // no ground
  EXPECT_EQ(json["gap_m"].get<double>(), 0.05);
  EXPECT_EQ(json["current_a"].get<double>(), 8.0);
  EXPECT_EQ(json["climb_w"].get<double>(), -3.0);
  EXPECT_EQ(json["ceiling_factor"].get<double>(), 1.2);
  EXPECT_TRUE(currentReportJson("quad", kNone, 1.0, flight, b)["gap_m"].is_null());

  flight.ground_gap_m = 1.5;
  const nlohmann::json sweep = currentSweepReportJson("quad", 1.0, flight, 0.127, 9.5, {{0.0, b}, {0.05, b}});
  EXPECT_EQ(sweep["ground_gap_m"].get<double>(), 1.5);
  EXPECT_EQ(sweep["rotor_radius_m"].get<double>(), 0.127);
  EXPECT_EQ(sweep["free_air_current_a"].get<double>(), 9.5);
  EXPECT_FALSE(sweep.contains("gap_m"));
  ASSERT_EQ(sweep["sweep"].size(), 2u);
  EXPECT_EQ(sweep["sweep"][1]["gap_m"].get<double>(), 0.05);
  EXPECT_EQ(sweep["sweep"][1]["power_w"].get<double>(), 120.0);
}

TEST(ReportJson, APlannerBenchmarkKeepsTheReferenceAndWritesNoSolutionAsNull) {
  planner::PlanResult reference;
  reference.planner = "lattice";
  reference.cost = 0.02;
  reference.search_cost = 0.021;
  reference.total_time_s = 3.0;
  planner::PlannerBenchmarkRow solved{"PRMstar", 10, 9, 0.05, 1.07, 1.02, 1.01, 0.1};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  planner::PlannerBenchmarkRow never{"RRTstar", 10, 0, nan, nan, nan, nan, nan};
  const nlohmann::json json = plannerBenchmarkJson(reference, 0.2, {solved, never});
  EXPECT_EQ(json["reference"]["planner"], "lattice");
  EXPECT_EQ(json["reference"]["spacing_m"].get<double>(), 0.2);
  EXPECT_EQ(json["reference"]["raw_cost"].get<double>(), 0.021);
  ASSERT_EQ(json["planners"].size(), 2u);
  EXPECT_EQ(json["planners"][0]["solved"].get<int>(), 9);
  EXPECT_EQ(json["planners"][0]["median_cost_ratio"].get<double>(), 1.02);
  EXPECT_EQ(nlohmann::json::parse(json.dump())["planners"][1]["median_cost_ratio"], nullptr);
}

}  // namespace
}  // namespace ceilplan::io
