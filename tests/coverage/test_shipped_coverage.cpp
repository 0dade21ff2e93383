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

#include <gtest/gtest.h>

#include <iostream>

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

// Plans `mission` in `mode`, re-checks it, and checks docs/coverage.md's coverage and safety claims.
void expectCovered(const ShippedMission& mission, FlightMode mode, double max_unreachable_share) {
  const testing::CoverageScene& scene = mission.scene;
  CoveragePlanOptions options;
  options.views.mode = mode;
  const CoveragePlan plan =
      planCoverage(scene.environment, mode == FlightMode::Ceiling ? scene.ceiling_model : scene.free_model,
                   *mission.keys.camera, mission.keys.surfaces, options);
  std::vector<RegionSurface> surfaces;
  std::vector<std::vector<std::uint8_t>> reachable;
  for (const RegionPlan& region : plan.regions) {
    surfaces.push_back(region.surface);
    reachable.push_back(region.reachable);
  }
  std::vector<CameraPose> poses;
  for (const PlannedPhoto& photo : plan.photos) poses.push_back(photo.pose);
  const CoverageCheck check =
      checkCoverage(scene.map.tree(), *mission.keys.camera, mission.keys.surfaces, surfaces, reachable, poses);

  const char* mode_name = mode == FlightMode::Ceiling ? "ceiling" : "free";
  for (std::size_t r = 0; r < plan.regions.size(); ++r) {
    const RegionCoverageCheck& checked = check.regions[r];
    std::cout << mission.file.filename().string() << " " << mode_name << " '" << checked.name
              << "': " << formatNumber(checked.area_m2, 4) << " m2, reachable "
              << formatNumber(checked.reachable_area_m2, 4) << ", covered "
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
    EXPECT_LE(photo.gsd_mm_px, mission.keys.surfaces[static_cast<std::size_t>(photo.region)].gsd_mm_px);
    EXPECT_TRUE(mission.keys.camera->pitchReachable(photo.pose.gimbal_pitch_deg));
  }
}

TEST(ShippedCoverage, BridgeSoffitInBothModes) {
  const ShippedMission mission("bridge_soffit");
  expectCovered(mission, FlightMode::Ceiling, 0.005);
  expectCovered(mission, FlightMode::Free, 0.005);
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
