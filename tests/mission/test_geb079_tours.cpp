// A real scan nobody here made, end to end: geb079.bt (liboctomap-dev's office corridor) with
// the shipped mission maps/real/geb079_corridor.yaml. Probe, plan, compare and a corridor tour
// in both modes succeed under the fill policy (the mission's) and under the occupied policy
// (home is valid under both); free mode keeps the largest standoff that fits and says where it
// had to narrow. In-process through the library, and once through the command line.

#include "analytic_maps.hpp"
#include "run_command.hpp"

#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/mission/route_planning.hpp"
#include "ceilplan/mission/tour_planner.hpp"
#include "ceilplan/planner/planner_factory.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace ceilplan::mission {
namespace {

const std::filesystem::path kMission = std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/real/geb079_corridor.yaml";

const Mission& corridorMission() {
  static const Mission mission = io::readMission(kMission);
  return mission;
}

// The mission's planning context under `policy` (the mission says fill).
std::unique_ptr<PlanningContext> contextUnder(environment::UnknownPolicy policy) {
  const Mission& mission = corridorMission();
  PlanningOptions options = mission.planning;
  options.unknown.policy = policy;
  return std::make_unique<PlanningContext>(environment::OccupancyMap::load(mission.map_file), mission.vehicle,
                                           mission.battery, options);
}

double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// The standoff kept along a path, sampled every 5 cm.
std::vector<double> standoffsAlong(const environment::Environment& environment,
                                   const std::vector<Eigen::Vector3d>& path) {
  std::vector<double> standoffs;
  for (std::size_t k = 1; k < path.size(); ++k) {
    const int steps = std::max(1, static_cast<int>((path[k] - path[k - 1]).norm() / 0.05));
    for (int s = 0; s < steps; ++s)
      standoffs.push_back(
          planner::standoffAt(environment, path[k - 1] + (path[k] - path[k - 1]) * (double(s) / steps)));
  }
  return standoffs;
}

TEST(Geb079Mission, TargetsLieOnScannedSurfacesAndHomeIsValidUnderEveryPolicy) {
  const Mission& mission = corridorMission();
  EXPECT_TRUE(mission.map_file.is_absolute()) << mission.map_file;  // the system's copy, from liboctomap-dev
  EXPECT_EQ(mission.planning.unknown.policy, environment::UnknownPolicy::Fill);
  EXPECT_EQ(mission.mode, "both");
  EXPECT_GE(mission.targets.size(), 8u);
  for (const environment::UnknownPolicy policy :
       {environment::UnknownPolicy::Occupied, environment::UnknownPolicy::Fill, environment::UnknownPolicy::Free}) {
    const auto context = contextUnder(policy);
    EXPECT_TRUE(context->baseRules().isStateValid(mission.home_m)) << environment::unknownPolicyName(policy);
    for (const InspectionTarget& target : mission.targets)
      EXPECT_TRUE(testing::onOccupiedSurface(context->environment().grid(), target.point_m)) << target.name;
  }
}

// From home, low at the corridor's west end, to the ceiling 8 m east (ceiling_x7.4's
// viewpoint in ceiling mode), and both modes compared there.
void probePlanAndCompare(environment::UnknownPolicy policy) {
  const auto context = contextUnder(policy);
  const environment::Environment& environment = context->environment();
  const Eigen::Vector3d home = corridorMission().home_m, under_the_ceiling(7.48, 0.52, 2.55);
  // Probe: both ends are valid, a ceiling panel 6 cm above a rotor at the far end.
  EXPECT_TRUE(environment.isStateValid(home));
  EXPECT_TRUE(environment.isStateValid(under_the_ceiling));
  EXPECT_NEAR(environment.ceiling(under_the_ceiling).nearest_gap_m, 2.64 - 2.58, 1e-9);
  EXPECT_NEAR(environment.ground(home).nearest_gap_m, 0.63, 1e-9);

  planner::PlanRequest request;
  request.start_m = home;
  request.goal_m = under_the_ceiling;
  request.planner = planner::defaultTourPlannerName();  // deterministic
  for (const FlightMode mode : {FlightMode::Ceiling, FlightMode::Free}) {
    const RoutePlan route = planRoute(*context, mode, request);
    const RouteCheck check = checkRoute(*context, route.plan.waypoints);  // the independent dense re-check
    EXPECT_FALSE(check.violation) << flightModeName(mode) << ": " << check.violation.value_or("");
    EXPECT_GT(route.evaluation.length_m, (under_the_ceiling - home).norm());
    EXPECT_EQ(route.standoff.has_value(), mode == FlightMode::Free);
    if (policy == environment::UnknownPolicy::Occupied) {
      EXPECT_EQ(route.evaluation.assumed_free_m, 0.0);
    }
  }
  const RouteComparison comparison = compareRoutes(*context, request, DutyOptions{});
  EXPECT_LE(comparison.ceiling.plan.cost, comparison.free.plan.cost * (1.0 + 1e-9));  // shown the free route
  EXPECT_GT(comparison.ceiling_duty.fecTotal(), 0.0);
  EXPECT_GT(comparison.free_duty.fecTotal(), 0.0);
  // Free mode says where it narrowed: the corridor (2.6 m by 2.6 m) is too tight for 1 m
  // anywhere, so the whole way, and it ends 14 cm under the ceiling.
  ASSERT_TRUE(comparison.free.standoff);
  const planner::StandoffReport& standoff = *comparison.free.standoff;
  EXPECT_EQ(standoff.standoff_m, 1.0);
  EXPECT_NEAR(standoff.narrowed_m, standoff.length_m, 1e-9);
  ASSERT_FALSE(standoff.spans.empty());
  EXPECT_LT(standoff.min_standoff_m, 0.1);
  // Under fill it keeps more of it than ceiling mode (median 0.42 against 0.37 m: the corridor
  // leaves little room either way, 0.9 m at most in its middle). (Under
  // the occupied policy the only way there runs along the floor and up a shaft a voxel wide
  // beside a lamp: neither mode has a choice.)
  const double free_median_m = median(standoffsAlong(environment, comparison.free.plan.waypoints));
  const double ceiling_median_m = median(standoffsAlong(environment, comparison.ceiling.plan.waypoints));
  if (policy == environment::UnknownPolicy::Fill) {
    EXPECT_GT(free_median_m, ceiling_median_m);
  }
}

TEST(Geb079Fill, ProbePlanAndCompareSucceedInTheCorridor) { probePlanAndCompare(environment::UnknownPolicy::Fill); }

TEST(Geb079Occupied, ProbePlanAndCompareSucceedInTheCorridor) {
  probePlanAndCompare(environment::UnknownPolicy::Occupied);
}

// The corridor tour in both modes: every target visited, in ceiling mode from close under the
// surface, in free mode from the largest standoff that fits, every narrowed viewpoint and leg
// reported.
void corridorTourInBothModes(environment::UnknownPolicy policy) {
  const Mission& mission = corridorMission();
  const auto context = contextUnder(policy);
  const TourResult ceiling = planTour(mission, *context, FlightMode::Ceiling);
  const TourResult free = planTour(mission, *context, FlightMode::Free);
  for (const TourResult* tour : {&ceiling, &free}) {
    const std::string mode = flightModeName(tour->mode);
    int visited = 0;
    for (const Sortie& sortie : tour->plan.sorties) visited += static_cast<int>(sortie.targets.size());
    EXPECT_EQ(visited, static_cast<int>(mission.targets.size())) << mode;
    EXPECT_EQ(tour->unknown_space.policy, policy) << mode;
    if (policy == environment::UnknownPolicy::Occupied) {
      EXPECT_EQ(tour->assumed_free_m, 0.0) << mode;
    }
    EXPECT_GT(tour->plan.charge_ah, 0.0) << mode;
  }
  EXPECT_FALSE(ceiling.standoff);
  ASSERT_TRUE(free.standoff);
  const TourStandoff& standoff = *free.standoff;
  EXPECT_EQ(standoff.standoff_m, 1.0);
  EXPECT_GT(standoff.narrowed_m, 0.0);
  EXPECT_LE(standoff.narrowed_m, standoff.length_m + 1e-9);
  EXPECT_FALSE(standoff.legs.empty());
  std::set<int> narrowed(standoff.narrowed_stops.begin(), standoff.narrowed_stops.end());
  for (std::size_t k = 0; k < free.stops.size(); ++k) {
    const TourStop &hug = ceiling.stops[k], &keep = free.stops[k];
    const std::string& name = keep.target.name;
    // The viewpoint's standoff, as reported, is what the map says there.
    EXPECT_NEAR(keep.viewpoint.standoff_m, planner::standoffAt(context->environment(), keep.viewpoint.position_m),
                1e-9);
    // Free mode keeps what fits within the target's own 0.3-1.5 m range (at least 0.1 m, most of
    // the corridor's ~0.9 m under fill; farther than 1.5 m, which free mode no longer goes, it
    // kept 0.6 and 0.15 m), ceiling mode comes close to a surface; no viewpoint in the corridor
    // keeps 1 m: all reported, as narrowed and as kept short by their range.
    EXPECT_GT(keep.viewpoint.standoff_m, hug.viewpoint.standoff_m) << name;
    EXPECT_GT(keep.viewpoint.standoff_m, policy == environment::UnknownPolicy::Fill ? 0.5 : 0.1) << name;
    EXPECT_LE(keep.viewpoint.distance_m, keep.target.standoff_max_m + 1e-9) << name;
    EXPECT_TRUE(keep.standoff_limited) << name;
    EXPECT_LT(hug.viewpoint.standoff_m, 0.0) << name;
    EXPECT_TRUE(narrowed.count(static_cast<int>(k))) << name;
    EXPECT_LE(standoff.min_standoff_m, keep.viewpoint.standoff_m) << name;
  }
}

TEST(Geb079Fill, TheCorridorTourSucceedsInBothModes) { corridorTourInBothModes(environment::UnknownPolicy::Fill); }

TEST(Geb079Occupied, TheCorridorTourSucceedsInBothModes) {
  corridorTourInBothModes(environment::UnknownPolicy::Occupied);
}

TEST(Geb079Cli, TourTakesTheUnknownFlagsAndSaysWhereFreeModeNarrowed) {
  const auto dir = testing::scratchDirectory("geb079_tour");
  const auto run = testing::runCeilplan("tour --mission " + kMission.string() +
                                        " --mode free --no-export --unknown occupied --out " + (dir / "out").string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("unknown space: occupied"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("  standoff 1 m: kept over "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("9 of 9 viewpoints keep less"), std::string::npos) << run.out;
  const nlohmann::json tour = nlohmann::json::parse(testing::readWholeFile(dir / "out/tour.json"));
  EXPECT_EQ(tour["unknown_space"]["policy"], "occupied");
  EXPECT_EQ(tour["assumed_free_m"], 0.0);
  const nlohmann::json& standoff = tour["standoff"];
  EXPECT_EQ(standoff["standoff_m"], 1.0);
  EXPECT_EQ(standoff["narrowed_viewpoints"].size(), 9u);
  ASSERT_FALSE(standoff["narrowed"].empty());
  for (const nlohmann::json& span : standoff["narrowed"]) {
    EXPECT_NE(span["leg"].get<std::string>().find(" -> "), std::string::npos);
    EXPECT_LE(span["from_m"].get<double>(), span["to_m"].get<double>());
    EXPECT_LT(span["min_standoff_m"].get<double>(), 1.0);
    EXPECT_EQ(span["at"].size(), 3u);
  }
  for (const nlohmann::json& target : tour["targets"]) EXPECT_LT(target["viewpoint_standoff_m"].get<double>(), 1.0);

  // And a compare under the fill flags, with the free plan's narrowing in its outputs.
  const auto compare = testing::runCeilplan("compare --map " + corridorMission().map_file.string() +
                                            " --unknown fill --unknown-fill-max-m 1.5 --start -4.5,0,0.6 " +
                                            "--goal 7.5,0,2.3 --planner roadmap --out " + (dir / "compare").string());
  ASSERT_EQ(compare.exit_code, 0) << compare.err;
  EXPECT_NE(compare.out.find("unknown space: fill (pockets up to 1.5 m)"), std::string::npos) << compare.out;
  EXPECT_NE(compare.out.find("free mode's standoff 1 m: kept over "), std::string::npos) << compare.out;
  const nlohmann::json plan = nlohmann::json::parse(testing::readWholeFile(dir / "compare/free/plan.json"));
  EXPECT_GT(plan["assumed_free_m"].get<double>(), 0.0);
  EXPECT_FALSE(plan["standoff"]["narrowed"].empty());
  EXPECT_FALSE(nlohmann::json::parse(testing::readWholeFile(dir / "compare/ceiling/plan.json")).contains("standoff"));
}

// A coverage tour of the corridor's ceiling through the command line, from a mission written
// outside the checkout: ceiling mode covers the reachable ceiling (re-check). Free mode under the
// occupied policy, which cuts the corridor into pieces, first chooses photo poses no route from
// home reaches (it once crashed there, then stopped with "no path"), chooses them again among
// the reachable ones, and reports the rest of the ceiling unreachable.
TEST(Geb079Cli, ACeilingCoverageTourCoversTheCorridorAndNeverCrashes) {
  const auto dir = testing::scratchDirectory("geb079_coverage");
  const std::filesystem::path mission = dir / "geb079_ceiling.yaml";
  std::ofstream(mission)
      << "map: " << corridorMission().map_file.string() << "\n"
      << "vehicle: " << CEILPLAN_SOURCE_DIR << "/maps/vehicles/quad.yaml\n"
      << "battery: {capacity_ah: 5.2, start_soc: 0.95, reserve_soc: 0.25, charge_current_a: 10.4}\n"
      << "home: [-4.5, 0.0, 0.6]\nseed: 1\nunknown: {policy: fill, fill_max_m: 2.0}\n"
      << "speeds: {cruise_m_s: 1.0, inspection_m_s: 0.5, climb_m_s: 0.8, descent_m_s: 0.6}\n"
      << "camera: {preset: zenmuse_h20_wide, gimbal_pitch_deg: [-30, 90], mount_offset_m: [0, 0, 0.05]}\n"
      << "surfaces:\n  - {name: corridor_ceiling, box: {min: [0.0, -1.5, 2.3], max: [8.0, 1.5, 2.9]}, "
         "faces: [down], gsd_mm_px: 1.0, overlap: {front: 70, side: 60}, max_incidence_deg: 45}\n";
  const auto ceiling = testing::runCeilplan("tour --mission " + mission.string() +
                                            " --mode ceiling --no-export --out " + (dir / "ceiling").string());
  ASSERT_EQ(ceiling.exit_code, 0) << ceiling.err;
  const nlohmann::json coverage = nlohmann::json::parse(testing::readWholeFile(dir / "ceiling/coverage.json"));
  const nlohmann::json& region = coverage["regions"].at(0);
  EXPECT_GT(region["reachable_area_m2"].get<double>(), 0.5 * region["area_m2"].get<double>());
  EXPECT_GE(region["covered_reachable_pct"].get<double>(), 99.0);

  const auto free =
      testing::runCeilplan("tour --mission " + mission.string() + " --mode free --unknown occupied --no-export --out " +
                           (dir / "free").string());
  ASSERT_EQ(free.exit_code, 0) << free.err;
  EXPECT_NE(free.out.find("stops chosen again among the places a route from home reaches"), std::string::npos)
      << free.out;
  EXPECT_TRUE(nlohmann::json::parse(testing::readWholeFile(dir / "free/tour.json"))["stops_rechosen"].get<bool>());
  EXPECT_FALSE(nlohmann::json::parse(testing::readWholeFile(dir / "ceiling/tour.json"))["stops_rechosen"].get<bool>());
  const nlohmann::json free_coverage = nlohmann::json::parse(testing::readWholeFile(dir / "free/coverage.json"));
  const nlohmann::json& cut = free_coverage["regions"].at(0);
  EXPECT_LT(cut["reachable_area_m2"].get<double>(), region["reachable_area_m2"].get<double>());
  EXPECT_GT(cut["reachable_area_m2"].get<double>(), 0.0);
  EXPECT_GE(cut["covered_reachable_pct"].get<double>(), 99.0);
}

// Every file under `dir` (relative path -> bytes).
std::map<std::string, std::string> filesUnder(const std::filesystem::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir))
    if (entry.is_regular_file())
      files[std::filesystem::relative(entry.path(), dir).string()] = testing::readWholeFile(entry.path());
  return files;
}

// The shipped coverage mission on the corridor's ceiling (maps/real/geb079_ceiling.yaml), as a
// user runs it from a directory of their own: both modes cover all the ceiling a photo can
// reach (re-check), every photo is taken from under that ceiling at or below the GSD, and a
// second run into the same --out writes the same files, byte for byte, and nothing else.
TEST(Geb079Cli, TheShippedCeilingCoverageMissionToursInBothModesTwiceIntoOneOut) {
  const auto dir = testing::scratchDirectory("geb079_ceiling_mission");
  const std::string mission = std::string(CEILPLAN_SOURCE_DIR) + "/maps/real/geb079_ceiling.yaml";
  const std::string in_dir = "cd " + dir.string() + " &&";
  const auto first = testing::runCeilplan("tour --mission " + mission + " --no-export --out out", in_dir);
  ASSERT_EQ(first.exit_code, 0) << first.err << first.out;
  EXPECT_NE(first.out.find("mode both"), std::string::npos) << first.out;  // the mission's mode
  for (const char* mode : {"ceiling", "free"}) {
    const nlohmann::json coverage = nlohmann::json::parse(testing::readWholeFile(dir / "out" / mode / "coverage.json"));
    ASSERT_EQ(coverage["regions"].size(), 1u) << mode;
    const nlohmann::json& region = coverage["regions"][0];
    EXPECT_EQ(region["name"], "corridor_ceiling");
    // Beams and ducts hide a little of the ceiling from every pose; the rest is covered.
    EXPECT_GT(region["reachable_area_m2"].get<double>(), 0.95 * region["area_m2"].get<double>()) << mode;
    EXPECT_EQ(region["covered_reachable_pct"].get<double>(), 100.0) << mode;
    const int photos = region["photos"].get<int>();
    EXPECT_GT(photos, 50) << mode;
    int rows = 0;
    std::istringstream csv(testing::readWholeFile(dir / "out" / mode / "photos.csv"));
    for (std::string line; std::getline(csv, line);) {
      if (line.empty() || line[0] == '#' || line.rfind("index,", 0) == 0) continue;
      ++rows;
      std::vector<double> field;
      std::istringstream cells(line);
      for (std::string cell; std::getline(cells, cell, ',');)
        field.push_back(field.size() < 10 && !cell.empty() ? std::stod(cell) : 0.0);
      ASSERT_GE(field.size(), 10u) << line;
      // x, y, z (3-5) in the corridor under the region's box, below its highest ceiling (2.76 m)
      // and above the floor; gimbal pitch (7) up; GSD (9).
      EXPECT_GE(field[3], -1.0) << line;
      EXPECT_LE(field[3], 9.0) << line;
      EXPECT_LE(std::abs(field[4]), 1.5) << line;
      EXPECT_LT(field[5], 2.76) << line;
      EXPECT_GT(field[5], 0.1) << line;
      EXPECT_GT(field[7], 0.0) << line;
      EXPECT_LE(field[9], 1.0) << line;
    }
    EXPECT_EQ(rows, photos) << mode;
  }
  const auto written = filesUnder(dir / "out");
  const auto second = testing::runCeilplan("tour --mission " + mission + " --no-export --out out", in_dir);
  ASSERT_EQ(second.exit_code, 0) << second.err << second.out;
  const auto rewritten = filesUnder(dir / "out");
  ASSERT_EQ(rewritten.size(), written.size());
  for (const auto& [path, bytes] : written) {
    ASSERT_EQ(rewritten.count(path), 1u) << path;
    EXPECT_TRUE(rewritten.at(path) == bytes) << path << " differs on the second run";
  }
}

}  // namespace
}  // namespace ceilplan::mission
