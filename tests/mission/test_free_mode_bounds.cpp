// Free mode keeps each target's standoff range from the mission file (issue: viewpoints 2.2 m
// from a target whose range ends at 1.5 m). On the shipped bridge (ceilplan mapgen's scene) four
// deck bays between girders cannot be seen from within 1.5 m while keeping the conventional 1 m
// from every structure: they are seen from within their range all the same and reported, in the
// summary and in tour.json, with the reason; only TourOptions::free_standoff_max_m lets a
// viewpoint leave the range, and each one that does is reported as beyond it.

#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/io/plan_files.hpp"
#include "ceilplan/io/provenance.hpp"
#include "ceilplan/io/tour_files.hpp"
#include "ceilplan/mission/planning_context.hpp"
#include "ceilplan/mission/tour_planner.hpp"
#include "ceilplan/planner/standoff.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <set>
#include <string>

namespace ceilplan::mission {
namespace {

const std::set<std::string> kLimitedDeckBays = {"deck_bay_14_north", "deck_bay_22_south", "deck_bay_38_north",
                                                "deck_bay_46_south"};

TourResult bridgeFreeTour(const TourOptions& options, const Mission& mission) {
  const PlanningContext context(mission);
  return planTour(mission, context, FlightMode::Free, options);
}

TEST(FreeModeBounds, EveryViewpointLiesInItsTargetsStandoffRangeAndTargetsItCannotServeAreReported) {
  const Mission mission = io::readMission(std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/bridge.yaml");
  const TourResult tour = bridgeFreeTour(TourOptions{}, mission);
  ASSERT_TRUE(tour.standoff);
  const double standoff_m = tour.standoff->standoff_m;
  std::set<std::string> limited;
  int point_targets = 0;
  for (const TourStop& stop : tour.stops) {
    if (stop.photo || stop.contact) continue;
    ++point_targets;
    const InspectionTarget& given = mission.targets.at(static_cast<std::size_t>(point_targets - 1));
    ASSERT_EQ(stop.target.name, given.name);
    // The mission's own range, not a wider one, and the viewpoint within it.
    EXPECT_EQ(stop.target.standoff_max_m, given.standoff_max_m) << given.name;
    EXPECT_GE(stop.viewpoint.distance_m, given.standoff_min_m) << given.name;
    EXPECT_LE(stop.viewpoint.distance_m, given.standoff_max_m + 1e-9) << given.name;
    EXPECT_FALSE(stop.beyond_standoff_range) << given.name;
    if (stop.standoff_limited) {
      limited.insert(given.name);
      EXPECT_LT(stop.viewpoint.standoff_m, standoff_m - planner::kStandoffTolerance_m) << given.name;
    } else {
      EXPECT_GE(stop.viewpoint.standoff_m, standoff_m - planner::kStandoffTolerance_m) << given.name;
    }
  }
  EXPECT_EQ(point_targets, 13);
  EXPECT_EQ(limited, kLimitedDeckBays);

  // Reported with the reason: one summary line naming each, and tour.json.
  const std::string summary = io::tourSummary(tour);
  const std::string line = *io::standoffLimitedLine(tour);
  EXPECT_NE(summary.find("  " + line + "\n"), std::string::npos) << summary;
  EXPECT_EQ(
      line.rfind("4 target(s) keep less than the 1 m standoff, as no viewpoint in their standoff range keeps it: ", 0),
      0u)
      << line;
  for (const std::string& name : kLimitedDeckBays)
    EXPECT_NE(line.find("'" + name +
                        "' seen from 1.50 m, within its range 0.3-1.5 m, with the airframe's bounding "
                        "sphere 0.97 m from the nearest structure"),
              std::string::npos)
        << line;
  const nlohmann::json json = io::tourJson(tour, mission, io::Provenance::of("test"));
  const nlohmann::json& reported = json["standoff"]["limited_targets"];
  ASSERT_EQ(reported.size(), kLimitedDeckBays.size());
  for (const nlohmann::json& target : reported) {
    EXPECT_EQ(kLimitedDeckBays.count(target["target"].get<std::string>()), 1u) << target;
    EXPECT_EQ(target["standoff_range_m"], nlohmann::json::array({0.3, 1.5}));
    EXPECT_LE(target["distance_m"].get<double>(), 1.5 + 1e-9);
    EXPECT_FALSE(target["beyond_standoff_range"].get<bool>());
    EXPECT_EQ(target["reason"].get<std::string>().rfind(
                  "no viewpoint within its standoff range keeps 1 m from every structure; seen from 1.50 m, within "
                  "its range 0.3-1.5 m",
                  0),
              0u)
        << target;
  }
  // What the figures measure, beside them.
  EXPECT_EQ(json["standoff"]["standoff_measures"], io::kStandoffMeasures);
  EXPECT_EQ(json["target_figures"]["viewpoint_standoff_m"], io::kStandoffMeasures);
  EXPECT_EQ(json["target_figures"]["distance_m"], "from the viewpoint (the body centre) to the target point");
  for (const nlohmann::json& target : json["targets"])
    EXPECT_LE(target["distance_m"].get<double>(), target["standoff_m"][1].get<double>() + 1e-9) << target["name"];
}

TEST(FreeModeBounds, OnlyAFreeStandoffMaximumLetsAViewpointLeaveItsRangeAndEachThatDoesIsReported) {
  const Mission mission = io::readMission(std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/bridge.yaml");
  TourOptions options;
  options.free_standoff_max_m = 3.0;
  const TourResult tour = bridgeFreeTour(options, mission);
  std::set<std::string> beyond;
  for (const TourStop& stop : tour.stops) {
    if (stop.viewpoint.distance_m > stop.target.standoff_max_m + 1e-9) {
      EXPECT_TRUE(stop.beyond_standoff_range) << stop.target.name;
      EXPECT_LE(stop.viewpoint.distance_m, 3.0 + 1e-9) << stop.target.name;
    }
    if (stop.beyond_standoff_range) beyond.insert(stop.target.name);
    EXPECT_TRUE(!stop.beyond_standoff_range || stop.standoff_limited) << stop.target.name;
  }
  EXPECT_FALSE(beyond.empty());
  for (const std::string& name : beyond) {
    EXPECT_EQ(kLimitedDeckBays.count(name), 1u) << name;
    EXPECT_NE(io::tourSummary(tour).find("'" + name + "' seen from "), std::string::npos);
  }
  EXPECT_NE(io::standoffLimitedLine(tour)->find("beyond its range 0.3-1.5 m (--free-standoff-max-m)"),
            std::string::npos)
      << *io::standoffLimitedLine(tour);
  TourOptions bad;
  bad.free_standoff_max_m = 0.0;
  EXPECT_THROW(bad.validate(), InputError);
}

}  // namespace
}  // namespace ceilplan::mission
