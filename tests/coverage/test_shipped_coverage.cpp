// The shipped coverage missions (maps/coverage/), planned with the library and checked by the
// independent re-check: each covers at least 99 % of each region's reachable area at or below
// the required GSD and incidence, with the overlap; no photo pose is inside the clearance; the
// contact grid's points all get a hugging viewpoint. The same on a scan nobody here made.

#include "coverage_fixtures.hpp"

#include "ceilplan/core/format.hpp"
#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/mission/contact_points.hpp"
#include "ceilplan/mission/coverage_check.hpp"
#include "ceilplan/mission/coverage_plan.hpp"
#include "ceilplan/mission/coverage_views.hpp"
#include "ceilplan/mission/region_surface.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <thread>
#include <vector>

namespace ceilplan::mission {
namespace {

struct ShippedMission {
  explicit ShippedMission(const std::string& name)
      : file(testing::shippedFile("coverage/" + name + ".yaml")),
        keys(io::readMission(file)),
        scene(environment::OccupancyMap::load(keys.map_file)) {}

  std::filesystem::path file;
  Mission keys;  // its coverage keys: camera, surfaces, contact_grids
  testing::CoverageScene scene;
};

// A plan and its independent re-check.
struct CheckedPlan {
  CoveragePlan plan;
  CoverageCheck check;
};

// Plans `regions` in `mode`, re-checks them, and checks docs/coverage.md's coverage and safety claims.
CheckedPlan expectCovered(const testing::CoverageScene& scene, const Camera& camera,
                          const std::vector<CoverageRegion>& regions, FlightMode mode, double max_unreachable_share,
                          const std::string& label) {
  CoveragePlanOptions options;
  options.views.mode = mode;
  CheckedPlan checked_plan;
  const CoveragePlan& plan = checked_plan.plan =
      planCoverage(scene.environment, mode == FlightMode::Ceiling ? scene.ceiling_model : scene.free_model, camera,
                   regions, options);
  std::vector<RegionSurface> surfaces;
  std::vector<std::vector<std::uint8_t>> reachable;
  for (const RegionPlan& region : plan.regions) {
    surfaces.push_back(region.surface);
    reachable.push_back(region.reachable);
  }
  std::vector<CameraPose> poses;
  for (const PlannedPhoto& photo : plan.photos) poses.push_back(photo.pose);
  const CoverageCheck& check = checked_plan.check =
      checkCoverage(scene.map.tree(), camera, regions, surfaces, reachable, poses);

  const char* mode_name = mode == FlightMode::Ceiling ? "ceiling" : "free";
  for (std::size_t r = 0; r < plan.regions.size(); ++r) {
    const RegionCoverageCheck& checked = check.regions[r];
    std::cout << label << " " << mode_name << " '" << checked.name << "': " << formatNumber(checked.area_m2, 4)
              << " m2, reachable " << formatNumber(checked.reachable_area_m2, 4) << ", covered "
              << formatNumber(100.0 * checked.coveredReachableShare(), 4) << " % of reachable, "
              << plan.regions[r].photos.size() << " photos, mean GSD " << formatNumber(checked.mean_gsd_mm_px, 3)
              << " mm/px\n";
    EXPECT_GE(checked.coveredReachableShare(), 0.99) << checked.name << " " << mode_name;
    EXPECT_LE(checked.unreachable_area_m2, max_unreachable_share * checked.area_m2) << checked.name << " " << mode_name;
    EXPECT_NEAR(checked.reachable_area_m2, plan.regions[r].reachable_area_m2, 1e-6);
  }
  for (const PlannedPhoto& photo : plan.photos) {
    EXPECT_TRUE(scene.environment.isStateValid(photo.pose.body_m)) << formatPoint(photo.pose.body_m);
    EXPECT_FALSE(scene.environment.checkPathDensely({photo.pose.body_m, photo.pose.body_m}).has_value())
        << formatPoint(photo.pose.body_m);
    EXPECT_LE(photo.gsd_mm_px, regions[static_cast<std::size_t>(photo.region)].gsd_mm_px);
    EXPECT_TRUE(camera.pitchReachable(photo.pose.gimbal_pitch_deg));
  }
  return checked_plan;
}

void expectCovered(const ShippedMission& mission, FlightMode mode, double max_unreachable_share) {
  expectCovered(mission.scene, *mission.keys.camera, mission.keys.surfaces, mode, max_unreachable_share,
                mission.file.filename().string());
}

TEST(ShippedCoverage, BridgeSoffitInBothModes) {
  const ShippedMission mission("bridge_soffit");
  expectCovered(mission, FlightMode::Ceiling, 0.005);
  expectCovered(mission, FlightMode::Free, 0.005);
}

// The deck bay over the first pier cap (x 12.1 to 19.9 m between two cross-frames, the cap 1 m
// under the deck from x 15.4 to 16.6 m): 56.2 m^2 across the three bays, at least 47 photos at
// 1 mm/px (docs/coverage.md, "Against the lower bound"). The parts of each bay beside the cap are
// tiled on their own, anchored to its edges, and oblique rows from beside it cover the strip
// above it: 66 photos in ceiling mode and 74 in free mode, where a tiling of the whole bay and the
// greedy's near and oblique photos over the cap took 105 and 157.
TEST(ShippedCoverage, ABayOverAPierCapIsTiledBesideTheCapAndSeenObliquelyAboveIt) {
  CoverageRegion region = testing::bridgeSoffit();
  region.shape = RegionShape::makeBox({12.0, -4.0, 5.95}, {20.0, 4.0, 6.05});
  for (const FlightMode mode : {FlightMode::Ceiling, FlightMode::Free}) {
    const CheckedPlan checked =
        expectCovered(testing::bridgeScene(), testing::upwardCamera(), {region}, mode, 0.0, "bay over the pier cap");
    const char* mode_name = mode == FlightMode::Ceiling ? "ceiling" : "free";
    EXPECT_GE(checked.check.regions.at(0).coveredReachableShare(), 1.0 - 1e-9) << mode_name;
    EXPECT_LE(checked.plan.photos.size(), 80u) << mode_name;
    int oblique_beside_cap = 0;  // tilted, within 2 m beside the cap
    for (const PlannedPhoto& photo : checked.plan.photos) {
      const double from_cap_m = std::abs(photo.pose.body_m.x() - 16.0) - 0.6;
      if (from_cap_m > 0.0 && from_cap_m < 2.0 && photo.pose.gimbal_pitch_deg < 80.0) ++oblique_beside_cap;
    }
    EXPECT_GT(oblique_beside_cap, 0) << mode_name;
  }
}

// planTours plans its modes at once, and they share what their candidate poses cover: each mode's
// candidates are exactly those it generates alone, and most of free mode's covers come from
// ceiling mode's generation or go to it (free mode's poses are ceiling mode's unraised ones).
TEST(ShippedCoverage, ModesPlannedAtOnceShareCoversAndGenerateWhatEachGeneratesAlone) {
  CoverageRegion region = testing::bridgeSoffit();
  region.shape = RegionShape::makeBox({12.0, -4.0, 5.95}, {20.0, 4.0, 6.05});
  const testing::CoverageScene& scene = testing::bridgeScene();
  const RegionSurface surface = extractRegionSurface(scene.environment.grid(), region.shape, region.faces, region.name);
  const std::vector<FlightMode> modes{FlightMode::Ceiling, FlightMode::Free};
  const auto generate = [&](FlightMode mode, const std::shared_ptr<SharedCovers>& shared) {
    ViewGenerationOptions options;
    options.mode = mode;
    options.shared_covers = shared;
    return generateCandidateViews(scene.environment, testing::upwardCamera(), region, surface, options);
  };
  const auto shared = std::make_shared<SharedCovers>(modes);
  std::vector<CandidateViews> together(2);
  std::vector<std::thread> threads;
  for (std::size_t m = 0; m < 2; ++m) threads.emplace_back([&, m] { together[m] = generate(modes[m], shared); });
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(shared->size(), 0u);  // every region finished: nothing is held
  for (std::size_t m = 0; m < 2; ++m) {
    const CandidateViews alone = generate(modes[m], nullptr);
    const CandidateViews& shared_views = together[m];
    ASSERT_EQ(shared_views.size(), alone.size()) << flightModeName(modes[m]);
    ASSERT_EQ(shared_views.offsets, alone.offsets);
    for (std::size_t v = 0; v < alone.size(); ++v) {
      ASSERT_EQ(shared_views.poses[v].body_m, alone.poses[v].body_m);
      ASSERT_EQ(shared_views.summaries[v].area_m2, alone.summaries[v].area_m2);
      ASSERT_EQ(shared_views.summaries[v].gsd_mm_px, alone.summaries[v].gsd_mm_px);
    }
    ASSERT_EQ(shared_views.runs.size(), alone.runs.size());
    for (std::size_t k = 0; k < alone.runs.size(); ++k) {
      ASSERT_EQ(shared_views.runs[k].first, alone.runs[k].first);
      ASSERT_EQ(shared_views.runs[k].count, alone.runs[k].count);
    }
  }
  // Found once for both modes: at least half as many covers as ceiling mode has candidates (8679
  // for 11,174 when written).
  EXPECT_GT(2 * shared->handed(), together[0].size());
}

TEST(ShippedCoverage, TunnelCrown) { expectCovered(ShippedMission("tunnel_crown"), FlightMode::Ceiling, 0.01); }

TEST(ShippedCoverage, WarehouseCeiling) {
  expectCovered(ShippedMission("warehouse_ceiling"), FlightMode::Ceiling, 0.01);
}

TEST(ShippedCoverage, ContactGridPointsAreHuggedUnderTheDeck) {
  const ShippedMission mission("bridge_contact_grid");
  ASSERT_EQ(mission.keys.contact_grids.size(), 1u);
  const std::vector<InspectionTarget> targets =
      contactTargets(mission.scene.environment.grid(), mission.keys.contact_grids[0]);
  // Faces from x = 2 to 14 m (11.9 m: 12 points) and y = -1.2 to 1.2 m (2.3 m: 3 points).
  ASSERT_EQ(targets.size(), 36u);
  for (const InspectionTarget& target : targets) {
    EXPECT_DOUBLE_EQ(target.point_m.z(), 6.0) << target.name;
    const Viewpoint viewpoint = chooseViewpoint(target, mission.scene.environment, mission.scene.energy);
    EXPECT_LE(viewpoint.distance_m, 0.5) << target.name;
    EXPECT_LE(viewpoint.ceiling_gap_m, 0.1) << target.name;  // hugging the deck or a girder
    EXPECT_LT(viewpoint.dwell_current_a, 9.0) << target.name;
  }
}

TEST(ShippedCoverage, ARealScanNobodyHereMade) {
  // geb079.bt (liboctomap-dev): an office corridor, 0.08 m voxels, its ceiling about 2.64 m up.
  const testing::CoverageScene scene(
      environment::OccupancyMap::load("/usr/share/doc/liboctomap-dev/examples/data/geb079.bt"));
  CoverageRegion region = testing::bridgeSoffit();
  region.name = "corridor_ceiling";
  region.shape = RegionShape::makeBox({0.0, -1.5, 2.3}, {8.0, 1.5, 2.9});
  const Camera camera = testing::upwardCamera();
  const CoveragePlan plan = planCoverage(scene.environment, scene.ceiling_model, camera, {region});
  const RegionPlan& planned = plan.regions.at(0);
  std::vector<CameraPose> poses;
  for (const PlannedPhoto& photo : plan.photos) poses.push_back(photo.pose);
  const CoverageCheck check =
      checkCoverage(scene.map.tree(), camera, {region}, {planned.surface}, {planned.reachable}, poses);
  const RegionCoverageCheck& checked = check.regions.at(0);
  std::cout << "geb079 ceiling: " << planned.surface.elements.size() << " elements, "
            << formatNumber(checked.area_m2, 4) << " m2, reachable " << formatNumber(checked.reachable_area_m2, 4)
            << " m2, covered " << formatNumber(100.0 * checked.coveredReachableShare(), 4) << " % of reachable with "
            << plan.photos.size() << " photos\n";
  EXPECT_GT(checked.reachable_area_m2, 0.5 * checked.area_m2);
  EXPECT_GE(checked.coveredReachableShare(), 0.99);
  for (const PlannedPhoto& photo : plan.photos) EXPECT_TRUE(scene.environment.isStateValid(photo.pose.body_m));
}

}  // namespace
}  // namespace ceilplan::mission
