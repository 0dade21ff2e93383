// The independent re-check's lines of sight (mission::checkCoverage, docs/coverage.md "Re-check")
// on trees built here node by node: they pass known free space whatever the size of the leaf
// that holds it (a pruned tree keeps large free nodes), and stop at an unknown or occupied voxel.

#include "coverage_fixtures.hpp"

#include "ceilplan/mission/coverage_check.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace ceilplan::mission
