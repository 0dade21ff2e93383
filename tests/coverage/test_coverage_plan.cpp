// Coverage planning on a small room: a ceiling crossed by a beam, with a closet the vehicle
// cannot enter. The chosen views cover the reachable ceiling by the independent re-check, the
// closet's ceiling is reported unreachable where it is, every pose is valid, passes hold every
// photo once, and ceiling mode hugs the ceiling to photograph the beam's web for less current.

#include "coverage_fixtures.hpp"

#include "ceilplan/core/format.hpp"
#include "ceilplan/mission/coverage_check.hpp"
#include "ceilplan/mission/coverage_plan.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <set>

namespace ceilplan::mission {
namespace {

const testing::CoverageScene& room() { return testing::roomScene(); }

CoverageRegion ceiling() {
  CoverageRegion region;
  region.name = "ceiling";
  region.shape = RegionShape::makeBox({-2, -2, 2.95}, {2, 2, 3.05});
  region.faces.down = true;
  region.gsd_mm_px = 1.0;
  return region;
}

// The beam's two webs, at 0.5 mm/px (0.5 to 1.48 m away with the upward H20 wide camera).
CoverageRegion beamWebs() {
  CoverageRegion region;
  region.name = "beam_webs";
  region.shape = RegionShape::makeBox({-0.05, -1.5, 2.4}, {0.35, 1.5, 3.0});
  region.faces.side = true;
  region.gsd_mm_px = 0.5;
  region.max_incidence_deg = 50.0;
  return region;
}

CoveragePlan plan(const std::vector<CoverageRegion>& regions, FlightMode mode) {
  CoveragePlanOptions options;
  options.views.mode = mode;
  return planCoverage(room().environment, mode == FlightMode::Ceiling ? room().ceiling_model : room().free_model,
                      testing::upwardCamera(), regions, options);
}

CoverageCheck recheck(const CoveragePlan& planned) {
  std::vector<CoverageRegion> regions;
  std::vector<RegionSurface> surfaces;
  std::vector<std::vector<std::uint8_t>> reachable;
  for (const RegionPlan& region : planned.regions) {
    regions.push_back(region.region);
    surfaces.push_back(region.surface);
    reachable.push_back(region.reachable);
  }
  std::vector<CameraPose> poses;
  for (const PlannedPhoto& photo : planned.photos) poses.push_back(photo.pose);
  return checkCoverage(room().map.tree(), testing::upwardCamera(), regions, surfaces, reachable, poses);
}

TEST(CoveragePlan, CoversTheReachableCeilingAndReportsTheCloset) {
  for (const FlightMode mode : {FlightMode::Ceiling, FlightMode::Free}) {
    const CoveragePlan planned = plan({ceiling()}, mode);
    const RegionPlan& region = planned.regions.at(0);
    // 40 x 40 faces, less 3 x 40 above the beam and the closet's 19 wall tops.
    EXPECT_EQ(region.surface.elements.size(), 1600u - 120u - 19u);
    // The closet's 9 x 9 faces, and nothing else, are unreachable.
    const std::vector<Eigen::Vector3d> unreachable = region.unreachableCentres();
    EXPECT_EQ(unreachable.size(), 81u);
    for (const Eigen::Vector3d& centre : unreachable) {
      EXPECT_GT(centre.x(), 1.1);
      EXPECT_GT(centre.y(), 1.1);
    }
    EXPECT_NEAR(region.unreachable_area_m2, 0.81, 1e-9);

    const CoverageCheck check = recheck(planned);
    const RegionCoverageCheck& checked = check.regions.at(0);
    EXPECT_GE(checked.coveredReachableShare(), 0.99)
        << checked.covered_reachable_area_m2 << " of " << checked.reachable_area_m2;
    EXPECT_NEAR(checked.reachable_area_m2, region.reachable_area_m2, 1e-9);
    EXPECT_EQ(checked.covered_area_m2, checked.covered_reachable_area_m2);  // nothing in the closet
    EXPECT_LE(checked.mean_gsd_mm_px, 1.0);
    double histogram = checked.unseen_area_m2;
    for (const double area : checked.gsd_bin_area_m2) histogram += area;
    EXPECT_NEAR(histogram, checked.area_m2, 1e-9);

    std::multiset<std::uint32_t> in_passes;
    for (const ViewPass& pass : region.passes.passes) in_passes.insert(pass.views.begin(), pass.views.end());
    EXPECT_EQ(in_passes.size(), planned.photos.size());
    EXPECT_EQ(std::set<std::uint32_t>(in_passes.begin(), in_passes.end()).size(), planned.photos.size());
    for (const PlannedPhoto& photo : planned.photos) {
      EXPECT_TRUE(room().environment.isStateValid(photo.pose.body_m)) << formatPoint(photo.pose.body_m);
      EXPECT_FALSE(room().environment.checkPathDensely({photo.pose.body_m, photo.pose.body_m}).has_value());
      EXPECT_LE(photo.gsd_mm_px, 1.0);
      EXPECT_GE(photo.distance_m, testing::upwardCamera().min_focus_m);
      EXPECT_GT(photo.hover_current_a, 0.0);
      EXPECT_DOUBLE_EQ(photo.stop_s, 2.0);
    }
  }
}

// A coarse GSD reaches farther than the room below the ceiling (8 m at 3 mm/px, 2.8 m from
// ceiling to floor): the levels within the room come in too, so the photos stand as far off as
// the room lets them, and a coarser GSD takes hardly more photos than a finer one (the greedy
// cover is not monotone; with the GSD's levels alone, the bridge's first span took three times
// as many at 3 mm/px as at 2).
TEST(CoveragePlan, ACoarseGsdUnderALowCeilingKeepsLevelsWithinTheRoom) {
  const Camera camera = testing::upwardCamera();
  CoverageRegion coarse = ceiling();
  coarse.gsd_mm_px = 3.0;
  const RegionSurface surface =
      extractRegionSurface(room().environment.grid(), coarse.shape, coarse.faces, "surface region 'ceiling'");
  const double reach_m = distanceLevels(camera, coarse, 1).front();
  EXPECT_GT(reach_m, 7.0);
  const double room_m = roomInFront_m(room().environment, camera, surface, reach_m);
  // The floor's top is 2.8 m below the ceiling; the airframe below the body and the mount take
  // the rest (the beam and the closet are too few elements to move the median).
  const environment::VehicleGeometry& vehicle = room().environment.vehicle();
  EXPECT_NEAR(room_m, 2.8 + vehicle.inflatedBottom_m() - camera.mount_offset_m.z(), 0.05 + 1e-9);
  EXPECT_DOUBLE_EQ(distanceLevels(camera, coarse, 4, room_m).front(), room_m);
  EXPECT_EQ(distanceLevels(camera, coarse, 4, room_m).size(), 4u);
  EXPECT_DOUBLE_EQ(distanceLevels(camera, coarse, 4, 0.1).front(), distanceLevels(camera, coarse, 4).back());
  // Room enough: the GSD's reach stands.
  EXPECT_GE(roomInFront_m(room().environment, camera, surface, 1.0), 1.0);

  CoverageRegion fine = ceiling();
  fine.gsd_mm_px = 2.0;
  const CoveragePlan coarse_plan = plan({coarse}, FlightMode::Ceiling);
  const CoveragePlan fine_plan = plan({fine}, FlightMode::Ceiling);
  EXPECT_LE(coarse_plan.photos.size(), 1.25 * fine_plan.photos.size());
  double farthest_m = 0.0;
  for (const PlannedPhoto& photo : coarse_plan.photos) {
    farthest_m = std::max(farthest_m, photo.distance_m);
    EXPECT_TRUE(room().environment.isStateValid(photo.pose.body_m)) << formatPoint(photo.pose.body_m);
  }
  EXPECT_GT(farthest_m, 0.9 * room_m);
  EXPECT_GE(recheck(coarse_plan).regions.at(0).coveredReachableShare(), 0.99);
  std::cout << "3 mm/px: " << coarse_plan.photos.size() << " photos (2 mm/px: " << fine_plan.photos.size() << "), room "
            << formatNumber(room_m, 3) << " m, farthest " << formatNumber(farthest_m, 3) << " m\n";
}

TEST(CoveragePlan, CeilingModeHugsTheCeilingToPhotographTheBeam) {
  const CoveragePlan ceiling_mode = plan({beamWebs()}, FlightMode::Ceiling);
  const CoveragePlan free_mode = plan({beamWebs()}, FlightMode::Free);
  for (const CoveragePlan* planned : {&ceiling_mode, &free_mode})
    EXPECT_GE(recheck(*planned).regions.at(0).coveredReachableShare(), 0.99);
  const auto mean_current = [](const CoveragePlan& planned) {
    double sum = 0.0;
    for (const PlannedPhoto& photo : planned.photos) sum += photo.hover_current_a;
    return sum / planned.photos.size();
  };
  int hugging = 0;
  for (const PlannedPhoto& photo : ceiling_mode.photos)
    if (room().environment.ceiling(photo.pose.body_m).nearest_gap_m < 0.1) ++hugging;
  EXPECT_GT(hugging, 0);
  // Free mode prices every hover as free air (a conventional planner); ceiling mode finds less.
  EXPECT_LT(mean_current(ceiling_mode), 0.95 * mean_current(free_mode));
  EXPECT_LT(ceiling_mode.charge_estimate_ah, free_mode.charge_estimate_ah);
}

TEST(CoveragePlan, OnTheMoveNeitherStopsNorBlurs) {
  Camera camera = testing::upwardCamera();
  camera.capture = CaptureStyle::OnTheMove;
  camera.exposure_s = 0.002;
  camera.blur_limit_px = 0.1;  // at 1 mm/px at most 0.05 m/s; finer GSD is slower still
  const CoveragePlan planned = planCoverage(room().environment, room().ceiling_model, camera, {ceiling()});
  ASSERT_FALSE(planned.photos.empty());
  for (const PlannedPhoto& photo : planned.photos) {
    EXPECT_DOUBLE_EQ(photo.stop_s, 0.0);
    EXPECT_GT(photo.max_speed_m_s, 0.0);
    EXPECT_LE(photo.max_speed_m_s, 0.05 + 1e-12);
  }
}

// Every flat patch of the ceiling is tiled as a survey would fly it, with straight-up views in two
// image orientations a quarter turn apart; the second orientation's views are kept for the cover
// that starts from the tilings (docs/coverage.md, "Seeds" and "Set cover").
TEST(CoveragePlan, FlatPatchesAreTiledInBothImageOrientations) {
  const CoverageRegion region = ceiling();
  const RegionSurface surface = extractRegionSurface(room().environment.grid(), region.shape, region.faces, "ceiling");
  const CandidateViews views =
      generateCandidateViews(room().environment, testing::upwardCamera(), region, surface, ViewGenerationOptions{});
  ASSERT_EQ(views.tiling_only.size(), views.size());
  const double heading_deg = regionHeading(surface);
  int along = 0, across = 0;
  for (const Tiling& tiling : views.tilings) {
    ASSERT_FALSE(tiling.views.empty());
    const bool turned = views.tilingOnly(tiling.views.front());
    for (const std::uint32_t v : tiling.views) {
      EXPECT_EQ(views.tilingOnly(v), turned) << "view " << v;
      EXPECT_NEAR(views.poses[v].gimbal_pitch_deg, 90.0, 1e-9) << "view " << v;
      const double turn_deg = std::fmod(std::abs(views.poses[v].yaw_deg - heading_deg), 180.0);
      EXPECT_NEAR(std::min(turn_deg, 180.0 - turn_deg), turned ? 90.0 : 0.0, 1e-6) << "view " << v;
    }
    ++(turned ? across : along);
  }
  EXPECT_GT(along, 0);
  EXPECT_GT(across, 0);
}

TEST(CoveragePlan, RefusesBadInputBeforeTheMapWork) {
  CoverageRegion sharp = ceiling();
  sharp.gsd_mm_px = 0.1;  // 0.3 m: inside the 0.5 m focus
  try {
    plan({sharp}, FlightMode::Ceiling);
    FAIL();
  } catch (const ceilplan::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("camera.min_focus_m"), std::string::npos) << e.what();
  }
  CoverageRegion nothing = ceiling();
  nothing.shape = RegionShape::makeBox({-1, -1, 1}, {1, 1, 2});
  EXPECT_THROW(plan({nothing}, FlightMode::Free), ceilplan::InputError);
  EXPECT_THROW(plan({}, FlightMode::Free), ceilplan::InputError);
}

}  // namespace
}  // namespace ceilplan::mission
