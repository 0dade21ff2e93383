// Coverage tours of the shipped coverage missions (maps/coverage/), planned end to end with
// mission::planTour, as `ceilplan tour` plans them. What docs/coverage.md claims of them:
// - every stop is flown once, photo poses as planned and none inside the clearance;
// - every leg flown passes the dense re-check, run here again;
// - the photos flown cover at least 99 % of each region's reachable area at or below the
//   required GSD and incidence, by the independent re-check (mission::checkCoverage: rays from
//   every photo pose through the OctoMap tree), re-run here on the poses the sorties fly;
// - each photo's row says when and in which sortie it is taken, as the flight record shows it.

#include "ceilplan/core/format.hpp"
#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/mission/tour_planner.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <set>

namespace ceilplan::mission {
namespace {

std::filesystem::path shipped(const std::string& name) {
  return std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps" / "coverage" / (name + ".yaml");
}

struct PlannedTour {
  Mission mission;
  std::unique_ptr<PlanningContext> context;
  TourResult tour;
};

PlannedTour planShipped(const std::string& name, FlightMode mode) {
  PlannedTour planned{io::readMission(shipped(name)), nullptr, {}};
  planned.context = std::make_unique<PlanningContext>(planned.mission);
  planned.tour = planTour(planned.mission, *planned.context, mode);
  return planned;
}

// Every stop flown once, every leg through the dense re-check, photo poses valid.
void expectSafeAndComplete(const PlannedTour& planned) {
  const TourResult& tour = planned.tour;
  std::multiset<int> visited;
  for (const Sortie& sortie : tour.plan.sorties) {
    visited.insert(sortie.targets.begin(), sortie.targets.end());
    for (const SortieLeg& leg : sortie.legs) {
      const auto violation = planned.context->baseRules().checkPathDensely(tour.legs[leg.from][leg.to].waypoints);
      EXPECT_FALSE(violation.has_value()) << tour.names[leg.from] << " -> " << tour.names[leg.to] << ": " << *violation;
    }
  }
  ASSERT_EQ(visited.size(), tour.stops.size());
  for (int k = 1; k <= static_cast<int>(tour.stops.size()); ++k) EXPECT_EQ(visited.count(k), 1u) << tour.names[k];
  const environment::Environment& environment = planned.context->environment();
  for (const TourStop& stop : tour.stops) {
    const Eigen::Vector3d& body = stop.viewpoint.position_m;
    EXPECT_TRUE(environment.isStateValid(body)) << stop.target.name;
    EXPECT_FALSE(planned.context->baseRules().checkPathDensely({body, body}).has_value()) << stop.target.name;
    if (!stop.photo) continue;
    const PlannedPhoto& photo = tour.coverage->photos.at(*stop.photo);
    EXPECT_EQ(body, photo.pose.body_m);
    EXPECT_EQ(stop.yaw_deg, photo.pose.yaw_deg);
    EXPECT_EQ(stop.gimbal_pitch_deg, photo.pose.gimbal_pitch_deg);
    EXPECT_EQ(stop.target.dwell_s, photo.stop_s);
  }
}

// The re-check of the poses the sorties fly, run here from the plan, and the photo rows.
void expectCovered(const PlannedTour& planned) {
  const TourResult& tour = planned.tour;
  ASSERT_TRUE(tour.coverage && tour.coverage_check);
  std::vector<CameraPose> flown;
  std::vector<const PlannedPhoto*> photos;
  for (std::size_t s = 0; s < tour.plan.sorties.size(); ++s)
    for (int place : tour.plan.sorties[s].targets)
      if (const auto& k = tour.stops[place - 1].photo) {
        photos.push_back(&tour.coverage->photos.at(*k));
        flown.push_back(photos.back()->pose);
      }
  ASSERT_EQ(flown.size(), tour.coverage->photos.size());
  std::vector<RegionSurface> surfaces;
  std::vector<std::vector<std::uint8_t>> reachable;
  for (const RegionPlan& region : tour.coverage->regions) {
    surfaces.push_back(region.surface);
    reachable.push_back(region.reachable);
  }
  const CoverageCheck check = checkCoverage(planned.context->map().tree(), *planned.mission.camera,
                                            planned.mission.surfaces, surfaces, reachable, flown, 2);
  for (std::size_t r = 0; r < check.regions.size(); ++r) {
    const RegionCoverageCheck& region = check.regions[r];
    std::cout << planned.mission.file.filename().string() << " " << flightModeName(tour.mode) << " '" << region.name
              << "': " << flown.size() << " photos in " << tour.plan.sorties.size() << " sortie(s), "
              << formatNumber(100.0 * region.coveredReachableShare(), 5) << " % of "
              << formatNumber(region.reachable_area_m2, 5) << " m2 reachable covered, mean GSD "
              << formatNumber(region.mean_gsd_mm_px, 3) << " mm/px, " << formatNumber(tour.plan.charge_ah, 4)
              << " Ah\n";
    EXPECT_GE(region.coveredReachableShare(), 0.99) << region.name;
    EXPECT_DOUBLE_EQ(region.covered_area_m2, tour.coverage_check->regions[r].covered_area_m2);
    EXPECT_LE(region.unreachable_area_m2, 0.01 * region.area_m2);
  }
  // Rows in flying order: sortie and time from the flight record, where the vehicle holds the pose.
  ASSERT_EQ(tour.photos.size(), photos.size());
  double last_t = -1.0;
  for (std::size_t k = 0; k < tour.photos.size(); ++k) {
    const PhotoRow& row = tour.photos[k];
    EXPECT_EQ(row.index, static_cast<int>(k + 1));
    ASSERT_TRUE(row.sortie && row.t_s);
    EXPECT_GT(*row.t_s, last_t);
    last_t = *row.t_s;
    EXPECT_TRUE(row.camera_m.isApprox(photos[k]->camera_m, 1e-12));
    EXPECT_EQ(row.gimbal_pitch_deg, photos[k]->pose.gimbal_pitch_deg);
    const SortieRecord& record = tour.record.sorties.at(*row.sortie - 1);
    bool held = false;
    for (const planner::PathSample& sample : record.samples)
      held = held || (std::abs(record.takeoff_s + sample.t_s - *row.t_s) < 1e-9 &&
                      (sample.position_m - photos[k]->pose.body_m).norm() < 1e-9 && sample.speed_m_s == 0.0);
    EXPECT_TRUE(held) << "photo " << row.index << " at " << *row.t_s << " s";
  }
}

// A shipped mission's tour, checked for safety, completeness and coverage.
PlannedTour planAndCheckShipped(const std::string& name, FlightMode mode) {
  PlannedTour planned = planShipped(name, mode);
  expectSafeAndComplete(planned);
  expectCovered(planned);
  return planned;
}

// The soffit's 332.6 m^2 need at least 276 photos (its area over one photo's covered part at
// the 2.69 m where 1 mm/px holds at the part's corners). Started from the deck bays' lawnmower
// tilings, anchored to the pier caps' edges, with oblique rows from beside the caps over them, the
// cover takes 352 photos (1.28 times that: issue 26's target is 1.3) where it took 418 with
// tilings of whole bays and 471 before the tilings, and 2.330 Ah where it took 2.728 and 3.130
// (docs/coverage.md, "The lawnmower baseline").
TEST(CoverageTours, BridgeSoffitCeilingMode) {
  const PlannedTour planned = planAndCheckShipped("bridge_soffit", FlightMode::Ceiling);
  EXPECT_EQ(planned.tour.order.method, "neighbour-list 2-opt+or-opt");
  EXPECT_LE(planned.tour.photos.size(), 359u);
  EXPECT_LT(planned.tour.plan.charge_ah, 2.331);
}

// Free mode's soffit. The split that adapts its split points to the sorties a tour needs chose
// the sorties the 60 fixed split points did, to the last photo and microampere-hour (270 and 254
// photos, 3.410819812168305 Ah, before views had to meet their aim along the optical axis; 207
// and 317 photos, 3.393100501879697 Ah, before the cover started from the lawnmower tilings; 494
// photos, 3.2345939287337329 Ah, in one pack, before the tilings were anchored to the pier caps'
// edges; 380 photos, 2.5646204540869637 Ah, before free mode kept the survey stations at the
// abutments and moved those beside the pier caps back to its standoff). Now the soffit takes 359
// photos, at most 1.3 times its lower bound of 276 as in ceiling mode (issue 26's target), and one
// pack, as with `ceilplan tour --split-points 600`.
TEST(CoverageTours, BridgeSoffitFreeMode) {
  const PlannedTour planned = planAndCheckShipped("bridge_soffit", FlightMode::Free);
  const SortiePlan& plan = planned.tour.plan;
  ASSERT_EQ(plan.sorties.size(), 1u);
  EXPECT_EQ(plan.sorties[0].targets.size(), 359u);
  EXPECT_LE(planned.tour.photos.size(), 359u);
  EXPECT_NEAR(plan.charge_ah, 2.3715322826544716, 1e-9);
}

TEST(CoverageTours, TunnelCrown) { planAndCheckShipped("tunnel_crown", FlightMode::Ceiling); }

TEST(CoverageTours, WarehouseCeiling) { planAndCheckShipped("warehouse_ceiling", FlightMode::Ceiling); }

TEST(CoverageTours, ContactGridUnderTheDeckIsHugged) {
  const PlannedTour planned = planShipped("bridge_contact_grid", FlightMode::Ceiling);
  expectSafeAndComplete(planned);
  const TourResult& tour = planned.tour;
  EXPECT_FALSE(tour.coverage.has_value());
  EXPECT_TRUE(tour.photos.empty());
  ASSERT_EQ(tour.stops.size(), 36u);
  for (const TourStop& stop : tour.stops) {
    EXPECT_EQ(stop.target.name.rfind("deck_thickness_", 0), 0u) << stop.target.name;
    EXPECT_LE(stop.viewpoint.distance_m, 0.5) << stop.target.name;     // the probe's reach
    EXPECT_LE(stop.viewpoint.ceiling_gap_m, 0.1) << stop.target.name;  // hugging the deck or a girder
    EXPECT_DOUBLE_EQ(stop.target.dwell_s, 10.0);
  }
  std::cout << "bridge_contact_grid ceiling: " << tour.stops.size() << " points, " << tour.plan.sorties.size()
            << " sortie(s), " << formatNumber(tour.plan.charge_ah, 4) << " Ah\n";
}

}  // namespace
}  // namespace ceilplan::mission
