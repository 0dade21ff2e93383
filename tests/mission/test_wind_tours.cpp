// Tours in wind, on the shipped bridge (its deck runs along x): a calm `wind:` key changes nothing,
// a leg costs differently flown upwind and downwind, and the tour's charge moves with the wind's
// direction (docs/tours.md, "Wind").

#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/io/provenance.hpp"
#include "ceilplan/io/tour_files.hpp"
#include "ceilplan/mission/planning_context.hpp"
#include "ceilplan/mission/tour_planner.hpp"
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <string>

namespace ceilplan::mission {
namespace {

const std::filesystem::path kMaps = std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps";

using testing::readWholeFile;

// A directory of this suite's own: ctest runs its tests in parallel processes.
std::filesystem::path scratch(const std::string& name) { return testing::scratchDirectory("wind_tours_" + name); }

// The bridge mission, as maps/bridge.yaml, in `dir` with its map and vehicle by absolute path (so
// tour.json names the same files) and `extra` appended.
Mission bridgeMission(const std::filesystem::path& dir, const std::string& extra) {
  std::string text = readWholeFile(kMaps / "bridge.yaml");
  text = std::regex_replace(text, std::regex("\nmap: bridge.bt"), "\nmap: " + (kMaps / "bridge.bt").string());
  text = std::regex_replace(text, std::regex("\nvehicle: vehicles/quad.yaml"),
                            "\nvehicle: " + (kMaps / "vehicles/quad.yaml").string());
  std::ofstream(dir / "bridge.yaml") << text << extra;
  return io::readMission(dir / "bridge.yaml");
}

// tour.json and path.csv of the mission's tour in `mode`, written as `ceilplan tour` writes them.
std::map<std::string, std::string> tourFiles(const Mission& mission, FlightMode mode, const std::string& name) {
  const PlanningContext context(mission);
  const TourResult tour = planTour(mission, context, mode, TourOptions{});
  const std::filesystem::path dir = scratch(name) / "out";
  io::Provenance provenance = io::Provenance::of("test_wind_tours");
  provenance.seed = context.options().seed;
  io::writeTourDirectory(dir, tour, mission, context.environment(), std::nullopt, provenance);
  return {{"tour.json", readWholeFile(dir / "tour.json")}, {"path.csv", readWholeFile(dir / "path.csv")}};
}

double tourChargeAh(const Mission& mission, FlightMode mode) {
  const PlanningContext context(mission);
  return planTour(mission, context, mode, TourOptions{}).plan.charge_ah;
}

energy::Wind windFrom(double from_deg, double speed_m_s = 8.0) {
  energy::Wind wind;
  wind.speed_m_s = speed_m_s;
  wind.from_deg = from_deg;
  return wind;
}

}  // namespace

TEST(WindTours, ACalmWindKeyWritesTheSameTourJsonAndPathCsvAsNoKey) {
  // One file, read twice: tour.json names it.
  const std::filesystem::path dir = scratch("missions");
  const Mission still = bridgeMission(dir, "");
  const Mission calm = bridgeMission(dir, "wind: {speed_m_s: 0, from_deg: 90, gust_m_s: 2}\n");
  ASSERT_TRUE(calm.planning.wind.calm());
  const auto expected = tourFiles(still, FlightMode::Ceiling, "still");
  const auto actual = tourFiles(calm, FlightMode::Ceiling, "calm");
  for (const auto& [file, text] : expected) EXPECT_TRUE(actual.at(file) == text) << file << " differs in a calm wind";
}

// The default quad's power is least near 8-9 m/s of airspeed (docs/models.md, "Wind"): in an
// 8 m/s wind the leg flown into it (airspeed 9.8 m/s) draws less than the leg flown with it
// (6.2 m/s); in a 12 m/s wind both sides are past the minimum and upwind costs more.
TEST(WindTours, ReversingALegAlongTheDeckChangesItsCostInWindAndNotInStillAir) {
  const Mission mission = io::readMission(kMaps / "bridge.yaml");
  const PlanningContext context(mission);
  // Under the deck, along it (x): 6 m at the ceiling mode's working height.
  const Eigen::Vector3d west(4.0, 0.0, 5.2), east(10.0, 0.0, 5.2);
  planner::CostModelOptions options = context.fullModel().options();
  const planner::FlightCostModel still(context.environment(), context.energy(), options);
  const planner::MotionTotals still_out = still.integrate(west, east), still_back = still.integrate(east, west);
  EXPECT_NEAR(still_out.charge_ah, still_back.charge_ah, 1e-12 * still_out.charge_ah);
  options.wind = windFrom(90.0);  // from the east: flying east is into it
  const planner::FlightCostModel windy(context.environment(), context.energy(), options);
  const planner::MotionTotals upwind = windy.integrate(west, east), downwind = windy.integrate(east, west);
  EXPECT_LT(upwind.charge_ah, downwind.charge_ah * 0.98) << "reversing the leg should change its cost";
  EXPECT_LT(upwind.charge_ah, still_out.charge_ah);
  // The ground speeds are the planned ones: the wind changes the charge, not the time.
  EXPECT_DOUBLE_EQ(upwind.duration_s, still_out.duration_s);
  options.wind = windFrom(90.0, 12.0);
  const planner::FlightCostModel gale(context.environment(), context.energy(), options);
  EXPECT_GT(gale.integrate(west, east).charge_ah, gale.integrate(east, west).charge_ah * 1.05);
}

TEST(WindTours, AFullyShelteredHoverCloseUnderTheDeckMeetsNoWindAndOneInTheOpenMeetsItAll) {
  const Mission mission = io::readMission(kMaps / "bridge.yaml");
  const PlanningContext context(mission);
  planner::CostModelOptions options = context.fullModel().options();
  const planner::FlightCostModel still(context.environment(), context.energy(), options);
  options.wind = windFrom(90.0);
  options.wind.sheltered_fraction = 1.0;
  const planner::FlightCostModel sheltered(context.environment(), context.energy(), options);
  const double soc = options.planning_soc;
  const planner::PointConditions under = sheltered.conditionsAt(Eigen::Vector3d(7.0, 0.0, 5.85));
  ASSERT_TRUE(sheltered.nearCeiling(under));
  EXPECT_EQ(sheltered.currentA(under, sheltered.hoverAt(under), soc), still.currentA(under, still.hoverAt(under), soc));
  const planner::PointConditions open = sheltered.conditionsAt(Eigen::Vector3d(-4.0, 0.0, 2.0));
  ASSERT_FALSE(sheltered.nearCeiling(open));
  EXPECT_NEAR(sheltered.hoverAt(open).wind.headwind_m_s, 8.0, 1e-12);
  EXPECT_NE(sheltered.currentA(open, sheltered.hoverAt(open), soc), still.currentA(open, still.hoverAt(open), soc));
}

TEST(WindTours, TheBridgeTourChargeChangesWithTheWindsDirection) {
  const Mission still = io::readMission(kMaps / "bridge.yaml");
  const double still_ah = tourChargeAh(still, FlightMode::Ceiling);
  std::map<double, double> charge_ah;
  for (const double from_deg : {0.0, 90.0, 180.0, 270.0}) {
    Mission windy = still;
    windy.planning.wind = windFrom(from_deg);
    charge_ah[from_deg] = tourChargeAh(windy, FlightMode::Ceiling);
    EXPECT_NE(charge_ah[from_deg], still_ah) << "from " << from_deg;
  }
  std::set<double> distinct;
  for (const auto& [from_deg, ah] : charge_ah) distinct.insert(ah);
  EXPECT_GT(distinct.size(), 1u) << "the wind's direction changed nothing";
}

}  // namespace ceilplan::mission
