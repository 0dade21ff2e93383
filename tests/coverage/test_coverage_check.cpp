// The independent re-check's lines of sight (mission::checkCoverage, docs/coverage.md "Re-check")
// on trees built here node by node: they pass known free space whatever the size of the leaf
// that holds it (a pruned tree keeps large free nodes), and stop at an unknown or occupied voxel.

#include "coverage_fixtures.hpp"

#include "ceilplan/mission/coverage_check.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ceilplan::mission {
namespace {

constexpr double kResolution_m = 0.1;

// Free air in x, y, z in [-1.6, 1.6) x [-1.6, 1.6) x [0, 3.2), pruned into large leaves, and an
// occupied ceiling layer on top, its underside at z = 3.2.
octomap::OcTree room() {
  octomap::OcTree tree(kResolution_m);
  for (double x = -1.55; x < 1.6; x += kResolution_m)
    for (double y = -1.55; y < 1.6; y += kResolution_m) {
      for (double z = 0.05; z < 3.2; z += kResolution_m) tree.updateNode(x, y, z, false);
      tree.updateNode(x, y, 3.25, true);
    }
  tree.updateInnerOccupancy();
  tree.prune();
  return tree;
}

// The underside of the ceiling voxel above the middle, photographed straight up from 1.5 m below.
CoverageCheck photographTheMiddle(const octomap::OcTree& tree, const Eigen::Vector3d& body_m) {
  RegionSurface surface;
  environment::SurfaceElement element;
  element.centre_m = Eigen::Vector3d(0.05, 0.05, 3.2);
  element.normal = -Eigen::Vector3d::UnitZ();
  element.area_m2 = kResolution_m * kResolution_m;
  element.face = 5;
  surface.elements = {element};
  surface.area_m2 = element.area_m2;
  CoverageRegion region;
  region.name = "middle";
  region.faces.down = true;
  region.gsd_mm_px = 2.0;
  return checkCoverage(tree, testing::upwardCamera(), {region}, {surface}, {{1}}, {{body_m, 0.0, 90.0}});
}

TEST(CoverageCheck, LinesOfSightPassLargeFreeLeavesAndStopAtUnknownOrOccupiedVoxels) {
  octomap::OcTree tree = room();
  std::size_t large_leaves = 0;
  for (auto leaf = tree.begin_leafs(), end = tree.end_leafs(); leaf != end; ++leaf)
    large_leaves += leaf.getDepth() < tree.getTreeDepth() ? 1 : 0;
  ASSERT_GT(large_leaves, 0u) << "the test needs a pruned tree";

  const Eigen::Vector3d below(0.05, 0.05, 1.65);  // the camera 5 cm above: 1.5 m from the surface
  const CoverageCheck clear = photographTheMiddle(tree, below);
  EXPECT_EQ(clear.rays, 1u);
  EXPECT_EQ(clear.regions.at(0).covered.at(0), 1);
  EXPECT_NEAR(clear.regions.at(0).best_gsd_mm_px.at(0), 0.338 * 1.5, 0.01);

  // A photo from beside the room, looking up, has the element outside its frame: no ray.
  EXPECT_EQ(photographTheMiddle(tree, Eigen::Vector3d(1.5, 1.5, 0.5)).rays, 0u);

  octomap::OcTree unknown = room();
  unknown.deleteNode(0.05, 0.05, 2.45);  // in a pruned leaf: its other voxels stay free
  const CoverageCheck through_unknown = photographTheMiddle(unknown, below);
  EXPECT_EQ(through_unknown.rays, 1u);
  EXPECT_EQ(through_unknown.regions.at(0).covered.at(0), 0);
  EXPECT_EQ(photographTheMiddle(unknown, Eigen::Vector3d(0.25, 0.05, 1.65)).regions.at(0).covered.at(0), 1)
      << "a line of sight beside the unknown voxel";

  octomap::OcTree occupied = room();
  occupied.updateNode(0.05, 0.05, 2.45, true);
  occupied.updateNode(0.05, 0.05, 2.45, true);
  ASSERT_TRUE(occupied.isNodeOccupied(occupied.search(0.05, 0.05, 2.45)));
  EXPECT_EQ(photographTheMiddle(occupied, below).regions.at(0).covered.at(0), 0);
}

// Photos beyond the required GSD or incidence can only lower an element's best GSD, so the check
// casts them finest first and stops at the first clear one: the figures are what checking each
// photo alone gives (covered by any, best GSD the least, photos within the limits summed), with
// fewer rays. Ceiling elements over a patch, photos below at three heights, some behind posts.
TEST(CoverageCheck, PhotosBeyondTheLimitsAreCastOnlyUntilTheBestGsdIsFound) {
  octomap::OcTree tree = room();
  for (const double x : {-0.35, 0.25})
    for (double z = 2.05; z < 2.9; z += kResolution_m) tree.updateNode(x, 0.05, z, true);
  RegionSurface surface;
  for (double x = -0.45; x < 0.5; x += kResolution_m) {
    environment::SurfaceElement element;
    element.centre_m = Eigen::Vector3d(x, 0.05, 3.2);
    element.normal = -Eigen::Vector3d::UnitZ();
    element.area_m2 = kResolution_m * kResolution_m;
    element.face = 5;
    surface.elements.push_back(element);
  }
  CoverageRegion region;
  region.name = "patch";
  region.faces.down = true;
  region.gsd_mm_px = 0.45;  // about 1.3 m straight on: the lower photos are beyond it
  std::vector<CameraPose> photos;
  for (const double z : {0.4, 1.2, 1.9})
    for (const double x : {-0.8, -0.3, 0.0, 0.45}) photos.push_back({Eigen::Vector3d(x, 0.05, z), 0.0, 90.0});
  const Camera camera = testing::upwardCamera();
  const std::vector<std::uint8_t> reachable(surface.elements.size(), 1);
  const CoverageCheck all = checkCoverage(tree, camera, {region}, {surface}, {reachable}, photos);
  const RegionCoverageCheck& checked = all.regions.at(0);

  std::size_t alone_rays = 0;
  std::vector<std::uint8_t> covered(surface.elements.size(), 0);
  std::vector<float> best(surface.elements.size(), std::numeric_limits<float>::infinity());
  std::vector<int> views(surface.elements.size(), 0);
  for (const CameraPose& photo : photos) {
    const CoverageCheck alone = checkCoverage(tree, camera, {region}, {surface}, {reachable}, {photo});
    alone_rays += alone.rays;
    for (std::size_t e = 0; e < surface.elements.size(); ++e) {
      covered[e] |= alone.regions.at(0).covered[e];
      best[e] = std::min(best[e], alone.regions.at(0).best_gsd_mm_px[e]);
      views[e] += alone.regions.at(0).view_count[e];
    }
  }
  int beyond = 0, blocked = 0;
  for (std::size_t e = 0; e < surface.elements.size(); ++e) {
    EXPECT_EQ(checked.covered[e], covered[e]) << e;
    EXPECT_EQ(checked.best_gsd_mm_px[e], best[e]) << e;
    EXPECT_EQ(checked.view_count[e], views[e]) << e;
    beyond += std::isfinite(best[e]) && best[e] > region.gsd_mm_px ? 1 : 0;
    blocked += std::isfinite(best[e]) ? 0 : 1;
  }
  EXPECT_LT(all.rays, alone_rays);
  EXPECT_GT(beyond, 0) << "some elements are seen only beyond the required GSD";
  EXPECT_GT(std::count(covered.begin(), covered.end(), 1), 0);
  EXPECT_EQ(blocked, 0);
}

}  // namespace
}  // namespace ceilplan::mission
