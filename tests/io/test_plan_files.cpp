// What plan, evaluate and compare write and print about a route (io/plan_files.hpp), and a
// tour's provenance (io/tour_files.hpp), in a small room.

#include "analytic_maps.hpp"

#include "ceilplan/io/plan_files.hpp"
#include "ceilplan/io/tour_files.hpp"

#include "run_command.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace ceilplan::io {
namespace {

// A 4 x 4 m room with its ceiling at 2.4 m, planned under the charge objective.
const mission::PlanningContext& roomContext() {
  static const mission::PlanningContext context(testing::room([](double, double) { return 2.4; }),
                                                mission::Vehicle::defaultQuad(), mission::BatterySpec{},
                                                mission::PlanningOptions{});
  return context;
}

const std::vector<Eigen::Vector3d> kAcrossTheRoom{{-1.0, 0.0, 1.0}, {1.0, 0.0, 1.0}};

// A free-mode route across the room, as if planned under the ageing objective.
mission::RoutePlan ageingRoute() {
  mission::RoutePlan route;
  route.mode = mission::FlightMode::Free;
  route.plan.waypoints = {kAcrossTheRoom[0], {0.0, 0.0, 1.0}, kAcrossTheRoom[1]};
  route.plan.planner = "lattice";
  route.plan.cost = 0.5;
  route.plan.search_cost = 0.6;
  route.plan.total_time_s = 1.25;
  route.evaluation = mission::checkRoute(roomContext(), kAcrossTheRoom).evaluation;
  route.objective.name = "ageing";
  route.objective.ageing = {"xu", 0.25, 1e-4, 2e-9};
  route.cost_unit = "capacity fraction";
  planner::StandoffReport standoff;
  standoff.standoff_m = 1.0;
  standoff.length_m = 2.0;
  route.standoff = standoff;
  return route;
}

nlohmann::json readJson(const std::filesystem::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

TEST(PlanFiles, APlannedRouteNamesItsQueryMapVehicleBatteryAndAgeingRates) {
  const mission::RoutePlan route = ageingRoute();
  const nlohmann::json json = routePlanJson(route, roomContext(), "maps/room.bt", 7);
  EXPECT_EQ(json["seed"].get<int>(), 7);
  EXPECT_EQ(json["objective"], "ageing");
  EXPECT_EQ(json["cost_unit"], "capacity fraction");
  EXPECT_EQ(json["mode"], "free");
  EXPECT_EQ(json["map"], "maps/room.bt");
  EXPECT_EQ(json["vehicle"], mission::Vehicle::defaultQuad().name);
  EXPECT_EQ(json["battery"], mission::BatterySpec{}.description);
  EXPECT_EQ(json["start_soc"].get<double>(), 0.95);
  EXPECT_EQ(json["unknown_space"]["policy"], "occupied");
  EXPECT_EQ(json["standoff"]["standoff_m"].get<double>(), 1.0);
  EXPECT_EQ(json["ageing"]["model"], "xu");
  EXPECT_EQ(json["ageing"]["depth_of_discharge"].get<double>(), 0.25);
  EXPECT_EQ(json["ageing"]["loss_per_s"].get<double>(), 2e-9);

  mission::RoutePlan charge = route;
  charge.objective = planner::ObjectiveChoice{};
  charge.mode = mission::FlightMode::Ceiling;
  charge.standoff.reset();
  const nlohmann::json plain = routePlanJson(charge, roomContext(), "maps/room.bt", 7);
  EXPECT_EQ(plain["objective"], "charge");
  EXPECT_EQ(plain["mode"], "ceiling");
  EXPECT_FALSE(plain.contains("ageing"));
  EXPECT_FALSE(plain.contains("standoff"));

  const std::filesystem::path dir = testing::scratchDirectory("plan_files_route");
  writeRoutePlan(dir, route, roomContext(), "maps/room.bt", 7, Provenance::of("ceilplan plan"));
  const nlohmann::json written = readJson(dir / "plan.json");
  EXPECT_EQ(written["planner"], "lattice");
  EXPECT_EQ(written["waypoints"].size(), 3u);
  EXPECT_EQ(written["ageing"], json["ageing"]);
  EXPECT_EQ(written["provenance"]["command"], "ceilplan plan");
  EXPECT_TRUE(std::filesystem::exists(dir / "path.csv"));
}

TEST(PlanFiles, APlannedRoutePrintsItsCostFiguresStandoffAndAgeingRates) {
  const mission::RoutePlan route = ageingRoute();
  const std::string text = routePlanText(route);
  EXPECT_EQ(text.rfind("3 waypoints; cost 0.5 capacity fraction (search 0.6) after 1.25 s\n", 0), 0u) << text;
  EXPECT_NE(text.find("\n" + figuresLine(route.evaluation) + "\n"), std::string::npos) << text;
  EXPECT_NE(text.find(standoffLine(*route.standoff) + "\n"), std::string::npos) << text;
  mission::RoutePlan ceiling = route;
  ceiling.standoff.reset();
  EXPECT_EQ(routePlanText(ceiling).find("standoff"), std::string::npos);
  EXPECT_EQ(ageingObjectiveLine(route.objective.ageing),
            "ageing objective: xu model at 25.0 % depth of discharge: 0.0001 per Ah, 2e-09 per s of capacity");
}

TEST(PlanFiles, ACheckedPathSaysWhetherItIsValidAndWhy) {
  const mission::RouteCheck check = mission::checkRoute(roomContext(), kAcrossTheRoom);
  ASSERT_FALSE(check.violation);
  Provenance provenance = Provenance::of("ceilplan evaluate");
  const nlohmann::json json = routeCheckJson(check, kAcrossTheRoom, roomContext(), provenance);
  EXPECT_TRUE(json["valid"].get<bool>());
  EXPECT_TRUE(json["violation"].is_null());
  EXPECT_EQ(json["objective"], "charge");
  EXPECT_EQ(json["cost"].get<double>(), check.cost);
  EXPECT_EQ(json["cost_unit"], check.cost_unit);
  EXPECT_EQ(json["waypoints"], nlohmann::json({{-1.0, 0.0, 1.0}, {1.0, 0.0, 1.0}}));
  EXPECT_EQ(json["length_m"].get<double>(), check.evaluation.length_m);
  EXPECT_EQ(json["unknown_space"]["policy"], "occupied");
  EXPECT_EQ(json["provenance"]["command"], "ceilplan evaluate");
  const std::string text = routeCheckText(check, 2, roomContext());
  EXPECT_EQ(text.rfind("2 points: " + figuresLine(check.evaluation) + "\ncharge cost ", 0), 0u) << text;
  EXPECT_NE(text.find("\nvalid: true\nunknown space: "), std::string::npos) << text;

  mission::RouteCheck invalid = check;
  invalid.violation = "the airframe hits the wall at (2.00, 0.00, 1.00)";
  const nlohmann::json refused = routeCheckJson(invalid, kAcrossTheRoom, roomContext(), provenance);
  EXPECT_FALSE(refused["valid"].get<bool>());
  EXPECT_EQ(refused["violation"], *invalid.violation);
  EXPECT_NE(routeCheckText(invalid, 2, roomContext()).find("valid: false\nviolation: the airframe hits the wall"),
            std::string::npos);
}

TEST(PlanFiles, AComparisonNamesTheObjectivePlannerSeedAndUnknownSpaceInEveryFile) {
  mission::RouteComparison comparison;
  comparison.free = ageingRoute();
  comparison.ceiling = ageingRoute();
  comparison.ceiling.mode = mission::FlightMode::Ceiling;
  comparison.ceiling.standoff.reset();
  const std::filesystem::path dir = testing::scratchDirectory("plan_files_comparison");
  writeRouteComparison(dir, comparison, mission::DutyOptions{}, roomContext(), "BITstar", 3,
                       Provenance::of("ceilplan compare"));
  const nlohmann::json compare = readJson(dir / "compare.json");
  EXPECT_EQ(compare["objective"], "charge");  // the context's
  EXPECT_EQ(compare["planner"], "BITstar");
  EXPECT_EQ(compare["seed"].get<int>(), 3);
  EXPECT_EQ(compare["unknown_space"]["policy"], "occupied");
  EXPECT_EQ(compare["duty"]["days"].get<int>(), 30);
  for (const std::string mode : {"ceiling", "free"}) {
    const nlohmann::json plan = readJson(dir / mode / "plan.json");
    EXPECT_EQ(plan["mode"], mode);
    EXPECT_EQ(plan["planner"], "BITstar");  // the one asked for, as compare.json
    EXPECT_EQ(plan["seed"].get<int>(), 3);
    EXPECT_EQ(plan.contains("standoff"), mode == "free");
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "map_top.csv"));
}

TEST(TourFiles, ATourRecordsTheMissionMapAndVehicleFilesAndTheSeed) {
  mission::Mission mission;
  mission.file = std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/bridge.yaml";
  mission.map_file = std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/bridge.bt";
  const Provenance provenance = tourProvenance(Provenance::of("ceilplan tour"), mission, 5);
  EXPECT_EQ(provenance.command_line, "ceilplan tour");
  EXPECT_EQ(provenance.seed, std::optional<std::uint64_t>(5));
  const nlohmann::json json = provenance.json();
  ASSERT_EQ(json["inputs"].size(), 2u);  // no vehicle file: the built-in vehicle
  EXPECT_EQ(json["inputs"][0]["role"], "mission");
  EXPECT_EQ(json["inputs"][1]["role"], "map");
  EXPECT_EQ(json["inputs"][1]["sha256"].get<std::string>().size(), 64u);
}

// Every standoff figure a summary prints says what it measures: the gap between the airframe's
// bounding sphere and the nearest structure, and a negative one is said as the overlap it is,
// never as a bare negative number.
TEST(StandoffWords, EveryStandoffFigureSaysWhatItMeasuresAndANegativeOneIsAnOverlap) {
  EXPECT_EQ(standoffText(0.42), "the airframe's bounding sphere 0.42 m from the nearest structure");
  EXPECT_EQ(standoffText(-0.07),
            "the airframe's bounding sphere 0.07 m into the nearest structure (the sphere overlaps it; the airframe "
            "itself keeps its clearance)");

  planner::StandoffReport plan;
  plan.standoff_m = 1.0;
  plan.length_m = 12.52;
  plan.narrowed_m = 3.22;
  plan.min_standoff_m = -0.19;
  plan.spans = {{2.0, 4.0, 0.3, {0.0, 0.0, 1.0}}, {6.0, 7.22, -0.19, {1.0, 0.7, 5.2}}};
  EXPECT_EQ(standoffLine(plan),
            "standoff 1 m: kept over 9.30 of 12.52 m, narrowed over 3.22 m in 2 places; closest: the airframe's "
            "bounding sphere 0.19 m into the nearest structure (the sphere overlaps it; the airframe itself keeps its "
            "clearance) at (1.00, 0.70, 5.20)");
  EXPECT_EQ(standoffJson(plan)["standoff_measures"], kStandoffMeasures);

  mission::TourResult tour;
  tour.mode = mission::FlightMode::Free;
  tour.standoff = mission::TourStandoff{1.0, 55.1, 0.0, -0.07, {8.5, 0.24, 1.52}, {}, {}};
  const std::string line = standoffLine(tour);
  EXPECT_EQ(line,
            "standoff 1 m: kept over the whole 55.1 m flown; 0 of 0 viewpoints keep less; closest: the airframe's "
            "bounding sphere 0.07 m into the nearest structure (the sphere overlaps it; the airframe itself keeps its "
            "clearance) at (8.50, 0.24, 1.52) (tour.json: standoff)");
  EXPECT_EQ(line.find("-0."), std::string::npos) << line;
  EXPECT_FALSE(standoffLimitedLine(tour));  // no target kept less for want of range
}

}  // namespace
}  // namespace ceilplan::io
