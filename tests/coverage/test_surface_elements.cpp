// Surface elements and lines of sight on small analytic maps: faces onto known free space only,
// exact normals and areas on flat surfaces and box edges, the inclined surface's normal on a
// staircase, and sight blocked by occupied and unknown voxels alike.

#include "analytic_maps.hpp"

#include "ceilplan/environment/surface_elements.hpp"
#include "ceilplan/environment/visibility.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <utility>
#include <vector>

namespace ceilplan::environment {
namespace {

using testing::analyticMap;

VoxelGrid gridOf(const OccupancyMap& map) { return VoxelGrid::fromTree(map.tree()); }

TEST(SurfaceElements, FacesOntoKnownFreeSpaceOnly) {
  // A slab at z in [2, 2.4): free below, unknown above; x < 0 of the free space unknown too.
  const OccupancyMap map = analyticMap({-1, -1, 0}, {1, 1, 3}, 0.1, [](const Eigen::Vector3d& c) {
    if (c.z() >= 2.0 && c.z() < 2.4) return CellState::Occupied;
    if (c.z() < 2.0 && c.x() > 0.0) return CellState::Free;
    return CellState::Unknown;
  });
  const std::vector<SurfaceElement> elements =
      exposedSurface(gridOf(map), Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(1, 1, 3)));
  ASSERT_EQ(elements.size(), 10u * 20u);  // the underside over the known half only
  for (const SurfaceElement& element : elements) {
    EXPECT_EQ(element.face, 5);
    EXPECT_TRUE(element.normal.isApprox(-Eigen::Vector3d::UnitZ()));
    EXPECT_NEAR(element.area_m2, 0.01, 1e-12);
    EXPECT_NEAR(element.centre_m.z(), 2.0, 1e-12);
    EXPECT_GT(element.centre_m.x(), 0.0);
  }
}

TEST(SurfaceElements, BoxEdgesKeepTheirAxisNormals) {
  // A 0.4 m square beam under a ceiling: its bottom and sides stay exactly axis-aligned up to
  // the edges, so a box's area is exact.
  const OccupancyMap map = analyticMap({-1, -1, 0}, {1, 1, 3}, 0.1, [](const Eigen::Vector3d& c) {
    if (c.z() >= 2.5) return CellState::Occupied;
    if (std::abs(c.x()) < 0.2 && c.z() >= 2.1) return CellState::Occupied;
    return CellState::Free;
  });
  const std::vector<SurfaceElement> elements = exposedSurface(
      gridOf(map), Eigen::AlignedBox3d(Eigen::Vector3d(-0.3, -0.5, 2.05), Eigen::Vector3d(0.3, 0.5, 2.45)));
  double bottom = 0.0, sides = 0.0;
  for (const SurfaceElement& element : elements) {
    EXPECT_TRUE(element.normal.isApprox(element.faceNormal())) << element.centre_m.transpose();
    (element.face == 5 ? bottom : sides) += element.area_m2;
  }
  EXPECT_NEAR(bottom, 0.4 * 1.0, 1e-9);
  EXPECT_NEAR(sides, 2 * 0.4 * 1.0, 1e-9);
}

TEST(SurfaceElements, AStaircaseTakesTheInclinedSurfacesNormal) {
  // A ceiling rising at 45 degrees along y: z = 2 + y, stepped in 0.1 m voxels.
  const OccupancyMap map = analyticMap({-1, -1, 0}, {1, 1, 4}, 0.1, [](const Eigen::Vector3d& c) {
    return c.z() < 2.0 + c.y() ? CellState::Free : CellState::Occupied;
  });
  const Eigen::Vector3d expected = Eigen::Vector3d(0, 1, -1).normalized();
  const std::vector<SurfaceElement> elements = exposedSurface(
      gridOf(map), Eigen::AlignedBox3d(Eigen::Vector3d(-0.5, -0.5, 1.3), Eigen::Vector3d(0.5, 0.49, 2.7)));
  ASSERT_FALSE(elements.empty());
  double area = 0.0;
  for (const SurfaceElement& element : elements) {
    EXPECT_GT(element.normal.dot(expected), 1.0 - 1e-12) << element.centre_m.transpose();
    area += element.area_m2;
  }
  // Ten steps of 0.1 m along y over 1 m in x (each a tread and a riser: 2 m^2 of voxel faces)
  // stand for 1 m x sqrt(2) m of inclined surface.
  EXPECT_EQ(elements.size(), 10u * 20u);
  EXPECT_NEAR(area, std::sqrt(2.0), 1e-9);
}

TEST(Visibility, BlockedByOccupiedAndUnknownVoxels) {
  // Free everywhere but a wall at x in [0.5, 0.6) for y < 0, and unknown space for y > 0.5.
  const OccupancyMap map = analyticMap({-1, -1, 0}, {1, 1, 1}, 0.1, [](const Eigen::Vector3d& c) {
    if (c.y() > 0.5) return CellState::Unknown;
    if (c.x() >= 0.5 && c.x() < 0.6 && c.y() < 0.0) return CellState::Occupied;
    return CellState::Free;
  });
  const VoxelGrid grid = gridOf(map);
  EXPECT_TRUE(lineOfSight(grid, {-0.95, 0.25, 0.5}, {0.95, 0.25, 0.55}));
  EXPECT_FALSE(lineOfSight(grid, {-0.95, -0.25, 0.5}, {0.95, -0.25, 0.55}));  // through the wall
  EXPECT_FALSE(lineOfSight(grid, {-0.95, 0.25, 0.5}, {0.95, 0.75, 0.5}));     // into unknown space
  EXPECT_FALSE(lineOfSight(grid, {0.0, 0.0, 0.5}, {0.0, 0.0, 1.5}));          // out of the map
  EXPECT_TRUE(lineOfSight(grid, {0.3, 0.3, 0.3}, {0.3, 0.3, 0.3}));           // a point in a free voxel
  // Grazing the wall's end: the walk visits exactly the voxels the segment crosses.
  EXPECT_TRUE(lineOfSight(grid, {0.55, 0.05, 0.5}, {0.55, 0.45, 0.5}));
  EXPECT_FALSE(lineOfSight(grid, {0.55, 0.05, 0.5}, {0.55, -0.05, 0.5}));
  // A diagonal through a corner between two blocked voxels' neighbours stays exact both ways.
  EXPECT_EQ(lineOfSight(grid, {0.2, -0.35, 0.5}, {0.9, 0.35, 0.5}),
            lineOfSight(grid, {0.9, 0.35, 0.5}, {0.2, -0.35, 0.5}));
}

// Whether the closed segment a-b meets the box [lo, hi] (the slab test).
bool segmentMeetsBox(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& lo,
                     const Eigen::Vector3d& hi) {
  double t0 = 0.0, t1 = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double d = b[axis] - a[axis];
    if (d == 0.0) {
      if (a[axis] < lo[axis] || a[axis] > hi[axis]) return false;
      continue;
    }
    double ta = (lo[axis] - a[axis]) / d, tb = (hi[axis] - a[axis]) / d;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

TEST(Visibility, ASightIsClearExactlyWhenEveryVoxelTheSegmentMeetsIsFree) {
  // A 12-voxel cube of scattered occupied and unknown voxels; segments with both ends inside (the
  // walk without bounds checks) and with one end outside, where every voxel counts as unknown.
  const GridFrame frame(0.1, {0, 0, 0}, {12, 12, 12});
  VoxelGrid grid(frame);
  std::mt19937 random(11);
  for (int k = 0; k < 12; ++k)
    for (int j = 0; j < 12; ++j)
      for (int i = 0; i < 12; ++i) {
        const unsigned draw = random() % 100;
        grid.set(i, j, k, draw < 3 ? CellState::Occupied : (draw < 4 ? CellState::Unknown : CellState::Free));
      }
  std::uniform_real_distribution<double> inside(0.0, 1.2), beyond(-0.3, 1.5);
  int clear = 0, blocked = 0;
  for (int trial = 0; trial < 6000; ++trial) {
    const Eigen::Vector3d a(inside(random), inside(random), inside(random));
    const Eigen::Vector3d b = trial % 3 == 0 ? Eigen::Vector3d(beyond(random), beyond(random), beyond(random))
                                             : Eigen::Vector3d(inside(random), inside(random), inside(random));
    bool expected = true;
    for (int k = -3; k < 15 && expected; ++k)
      for (int j = -3; j < 15 && expected; ++j)
        for (int i = -3; i < 15 && expected; ++i)
          if (grid.at(i, j, k) != CellState::Free &&
              segmentMeetsBox(a, b, Eigen::Vector3d(i, j, k) * 0.1, Eigen::Vector3d(i + 1, j + 1, k + 1) * 0.1))
            expected = false;
    ASSERT_EQ(lineOfSight(grid, a, b), expected) << a.transpose() << " -> " << b.transpose();
    ++(expected ? clear : blocked);
  }
  EXPECT_GT(clear, 1000);  // both answers are exercised
  EXPECT_GT(blocked, 1000);
}

// Segments that meet voxel edges and corners exactly (ends at voxel centres and corners, whole
// voxel steps apart, straight and diagonal), where the walk breaks ties between axes, and general
// ones; both ends inside the grid and one end outside.
std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> testSegments(const GridFrame& frame, std::mt19937& random,
                                                                      int count) {
  const Eigen::Vector3d lo = frame.bounds().min(), hi = frame.bounds().max();
  const double r = frame.resolution_m();
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto anywhere = [&](double margin) {
    return Eigen::Vector3d(lo.x() - margin + unit(random) * (hi.x() - lo.x() + 2 * margin),
                           lo.y() - margin + unit(random) * (hi.y() - lo.y() + 2 * margin),
                           lo.z() - margin + unit(random) * (hi.z() - lo.z() + 2 * margin));
  };
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> segments;
  for (int n = 0; n < count; ++n) {
    Eigen::Vector3d a = anywhere(0.0), b;
    switch (n % 4) {
      case 0:  // general
        b = anywhere(0.0);
        break;
      case 1:  // one end outside
        b = anywhere(5 * r);
        break;
      default: {  // on the lattice: centres (case 2) or corners (case 3), whole steps apart
        const double shift = n % 4 == 2 ? 0.5 : 0.0;
        for (int axis = 0; axis < 3; ++axis) a[axis] = (std::floor(a[axis] / r) + shift) * r;
        const int length = 1 + static_cast<int>(random() % 40);
        Eigen::Vector3d direction;
        for (int axis = 0; axis < 3; ++axis) direction[axis] = static_cast<int>(random() % 3) - 1;
        if (direction.isZero()) direction.x() = 1;
        b = a + direction * (length * r);
      }
    }
    segments.emplace_back(a, b);
  }
  return segments;
}

TEST(Visibility, FreeBlocksGiveTheVoxelWalksAnswerOnEverySegment) {
  // A grid whose sides are not whole blocks, free but for a slab, a column, a wall and scattered
  // voxels above the slab: the walk crosses all-free blocks of both sizes, stops in mixed ones
  // and at the grid's far faces.
  const GridFrame frame(0.1, {-4, 2, 0}, {37, 42, 29});
  VoxelGrid grid(frame);
  std::mt19937 random(23);
  for (int k = 0; k < 29; ++k)
    for (int j = 0; j < 42; ++j)
      for (int i = 0; i < 37; ++i) {
        const bool slab = k == 20 && i < 30, column = i >= 17 && i < 20 && j >= 10 && j < 14, wall = j == 33 && k < 12;
        const unsigned draw = k > 20 ? random() % 1000 : 1000;
        grid.set(i, j, k,
                 slab || column || wall || draw < 2 ? CellState::Occupied
                                                    : (draw < 3 ? CellState::Unknown : CellState::Free));
      }
  const FreeBlocks blocks(grid, 2);
  std::map<int, int> voxels_by_shift;
  for (int k = 0; k < 29; ++k)
    for (int j = 0; j < 42; ++j)
      for (int i = 0; i < 37; ++i) ++voxels_by_shift[blocks.freeShift(i, j, k)];
  ASSERT_GT(voxels_by_shift[FreeBlocks::kCoarseShift], 4096);  // the walks have blocks of both sizes to cross
  ASSERT_GT(voxels_by_shift[FreeBlocks::kFineShift], 4096);
  int clear = 0, blocked = 0;
  for (const auto& [a, b] : testSegments(frame, random, 40000)) {
    const bool expected = lineOfSight(grid, a, b);
    ASSERT_EQ(lineOfSight(grid, blocks, a, b), expected) << a.transpose() << " -> " << b.transpose();
    ++(expected ? clear : blocked);
  }
  EXPECT_GT(clear, 5000);  // both answers are exercised
  EXPECT_GT(blocked, 5000);
}

TEST(Visibility, AVoxelsFreeBlockIsTheLargestWhoseVoxelsAreAllFree) {
  const Index3 size{40, 20, 36};  // partial blocks at the far faces
  const GridFrame frame(0.05, {0, 0, 0}, size);
  VoxelGrid grid(frame);
  for (int k = 0; k < size[2]; ++k)
    for (int j = 0; j < size[1]; ++j)
      for (int i = 0; i < size[0]; ++i) grid.set(i, j, k, CellState::Free);
  grid.set(39, 19, 35, CellState::Unknown);  // in the far corner's partial blocks
  grid.set(8, 0, 7, CellState::Occupied);
  grid.set(30, 5, 20, CellState::Occupied);
  const FreeBlocks blocks(grid);
  // Whether the block of side 2^shift holding (i, j, k) holds free voxels only.
  const auto allFree = [&](int shift, int i, int j, int k) {
    for (int z = (k >> shift) << shift; z < std::min(((k >> shift) + 1) << shift, size[2]); ++z)
      for (int y = (j >> shift) << shift; y < std::min(((j >> shift) + 1) << shift, size[1]); ++y)
        for (int x = (i >> shift) << shift; x < std::min(((i >> shift) + 1) << shift, size[0]); ++x)
          if (grid.at(x, y, z) != CellState::Free) return false;
    return true;
  };
  std::map<int, int> voxels_by_shift;
  for (int k = 0; k < size[2]; ++k)
    for (int j = 0; j < size[1]; ++j)
      for (int i = 0; i < size[0]; ++i) {
        const int expected = allFree(FreeBlocks::kCoarseShift, i, j, k)
                                 ? FreeBlocks::kCoarseShift
                                 : (allFree(FreeBlocks::kFineShift, i, j, k) ? FreeBlocks::kFineShift : 0);
        ASSERT_EQ(blocks.freeShift(i, j, k), expected) << i << " " << j << " " << k;
        ++voxels_by_shift[expected];
      }
  EXPECT_EQ(voxels_by_shift.size(), 3u);  // every answer occurs
}

}  // namespace
}  // namespace ceilplan::environment
