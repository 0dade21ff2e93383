// The map builders as a library: scans and origins bookkeeping, mesh topology, refusals.

#include "scan_files.hpp"

#include "ceilplan/environment/map_builder.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <limits>

namespace ceilplan {
namespace {

using environment::SensorOrigins;

TEST(SensorOrigins, ExpandsScansToPoints) {
  const SensorOrigins origins{{0, 2}, {{1, 0, 0}, {2, 0, 0}}};
  EXPECT_NO_THROW(origins.validate(5));
  const auto per_point = origins.perPoint(5);
  ASSERT_EQ(per_point.size(), 5u);
  EXPECT_EQ(per_point[1].x(), 1.0);
  EXPECT_EQ(per_point[2].x(), 2.0);
  EXPECT_EQ(per_point[4].x(), 2.0);
}

TEST(SensorOrigins, RefusesScansThatDoNotFitTheCloud) {
  EXPECT_THROW((SensorOrigins{{1}, {{0, 0, 0}}}.validate(5)), InputError);                // not from point 0
  EXPECT_THROW((SensorOrigins{{0, 7}, {{0, 0, 0}, {1, 1, 1}}}.validate(5)), InputError);  // beyond the cloud
  EXPECT_THROW((SensorOrigins{{0, 3, 3}, {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}}.validate(5)),
               InputError);  // not increasing
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((SensorOrigins{{0}, {{nan, 0, 0}}}.validate(5)), InputError);
}

TEST(SensorOrigins, DroppingNonFinitePointsRenumbersTheScans) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Eigen::Vector3d> points = {{0, 0, 0}, {nan, 0, 0}, {1, 0, 0}, {nan, nan, nan}, {2, 0, 0}};
  SensorOrigins origins{{0, 3, 4}, {{10, 0, 0}, {20, 0, 0}, {30, 0, 0}}};  // the middle scan holds only a NaN
  EXPECT_EQ(environment::dropNonFinitePoints(points, &origins), 2u);
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points[2].x(), 2.0);
  EXPECT_EQ(origins.first_point, (std::vector<std::size_t>{0, 2}));
  EXPECT_EQ(origins.origin_m[1].x(), 30.0);
}

TEST(MeshTopology, TellsClosedOutwardInwardAndOpenMeshes) {
  const auto outward = environment::meshTopology(testing::boxMesh({0, 0, 0}, {2, 3, 4}));
  EXPECT_TRUE(outward.closed());
  EXPECT_TRUE(outward.consistently_oriented);
  EXPECT_NEAR(outward.signed_volume_m3, 24.0, 1e-9);
  const auto inward = environment::meshTopology(testing::boxMesh({0, 0, 0}, {2, 3, 4}, false));
  EXPECT_TRUE(inward.closed());
  EXPECT_NEAR(inward.signed_volume_m3, -24.0, 1e-9);
  const auto slab = environment::meshTopology(testing::rectangleMesh({0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  EXPECT_FALSE(slab.closed());
  EXPECT_EQ(slab.boundary_edges, 4u);
  auto flipped = testing::boxMesh({0, 0, 0}, {1, 1, 1});
  std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
  const auto inconsistent = environment::meshTopology(flipped);
  EXPECT_TRUE(inconsistent.closed());
  EXPECT_FALSE(inconsistent.consistently_oriented);
}

TEST(MeshTopology, WeldsTheSeparateCornersOfStlTriangles) {
  const auto box = testing::boxMesh({0, 0, 0}, {1, 1, 1});
  environment::TriangleMesh soup;  // every triangle with its own three vertices, as STL stores them
  for (const auto& t : box.triangles) {
    const std::size_t first = soup.vertices_m.size();
    for (std::size_t v : t) soup.vertices_m.push_back(box.vertices_m[v]);
    soup.triangles.push_back({first, first + 1, first + 2});
  }
  EXPECT_TRUE(environment::meshTopology(soup).closed());
}

TEST(MapBuilders, ATriangleThinnerThanAVoxelStillClosesTheVoxelsItCrosses) {
  // A sloping sheet, never on a voxel centre: every voxel it passes through must be occupied,
  // so no free voxel pair straddles it.
  environment::MeshVoxelisingOptions options;
  options.resolution_m = 0.1;
  options.margin_m = 0.3;
  const auto built =
      environment::mapFromMesh(testing::rectangleMesh({0.013, 0.017, 0.5}, {2, 0, 0.7}, {0, 2, 0.3}), options);
  for (double x = 0.1; x < 1.9; x += 0.037)
    for (double y = 0.1; y < 1.9; y += 0.041) {
      const double z = 0.5 + 0.35 * (x - 0.013) + 0.15 * (y - 0.017);  // on the sheet
      const octomap::OcTreeNode* node = built.tree->search(x, y, z);
      ASSERT_NE(node, nullptr);
      EXPECT_TRUE(built.tree->isNodeOccupied(node)) << x << ", " << y << ", " << z;
    }
}

// "occupied", "free" or "unknown" at a point of a built map.
std::string stateIn(const environment::BuiltMap& built, const Eigen::Vector3d& p) {
  const octomap::OcTreeNode* node = built.tree->search(p.x(), p.y(), p.z());
  return !node ? "unknown" : built.tree->isNodeOccupied(node) ? "occupied" : "free";
}

TEST(MapBuilders, AShellIsOnlyItsSurfaceAndACropThroughAClosedMeshKeepsItsInsideAsWhole) {
  const Eigen::Vector3d min(1.03, 1.07, 0.02), max(5.03, 4.07, 3.02), centre = (min + max) / 2;
  environment::MeshVoxelisingOptions options;
  options.resolution_m = 0.1;
  options.interior = environment::MeshInterior::Shell;  // asked for, on a closed box
  const auto shell = environment::mapFromMesh(testing::boxMesh(min, max), options);
  EXPECT_EQ(stateIn(shell, centre), "free");
  EXPECT_EQ(stateIn(shell, {min.x(), centre.y(), centre.z()}), "occupied");
  EXPECT_EQ(shell.free_space.rfind("closed mesh, triangles facing outward: thin shell, both sides free", 0), 0u)
      << shell.free_space;
  // A room (inward-facing), cut in half by the crop: its inside stays free, its outside unknown,
  // though the crop's face at x = 3 runs through the room.
  options.interior = environment::MeshInterior::Automatic;
  options.crop_m = environment::CropBox(Eigen::Vector3d(3, -5, -5), Eigen::Vector3d(9, 9, 9));
  const auto room = environment::mapFromMesh(testing::boxMesh(min, max, /*outward=*/false), options);
  EXPECT_EQ(stateIn(room, {3.05, centre.y(), centre.z()}), "free");
  EXPECT_EQ(stateIn(room, {4.5, centre.y(), centre.z()}), "free");
  EXPECT_EQ(stateIn(room, {5.6, centre.y(), centre.z()}), "unknown");
  EXPECT_EQ(stateIn(room, {2.5, centre.y(), centre.z()}), "unknown");  // outside the crop
  EXPECT_NE(room.free_space.find("hollow, inside free"), std::string::npos) << room.free_space;
}

TEST(MapBuilders, ACloudAloneVouchesOnlyForSpaceBetweenItsSurfaces) {
  // A floor 8 m x 6 m, and a ceiling 3 m up over its first 4 m only (a hall with an open yard).
  auto points = testing::sampleRectangle({0.01, 0.02, 0.013}, {8, 0, 0}, {0, 6, 0}, 0.05);
  const auto ceiling = testing::sampleRectangle({0.01, 0.02, 3.033}, {4, 0, 0}, {0, 6, 0}, 0.05);
  points.insert(points.end(), ceiling.begin(), ceiling.end());
  environment::PointAssumptionOptions options;
  options.resolution_m = 0.1;
  options.free_distance_m = 0.0;
  const auto between = environment::mapFromPointsAlone(points, options);
  EXPECT_EQ(stateIn(between, {2.0, 3.0, 1.5}), "free");     // under the ceiling
  EXPECT_EQ(stateIn(between, {6.0, 3.0, 1.5}), "unknown");  // nothing scanned above: the cloud says nothing
  EXPECT_EQ(stateIn(between, {2.0, 3.0, 3.033}), "occupied");
  EXPECT_NE(between.free_space.find("with a point above and below it in its column is free; beyond the scanned "
                                    "surfaces (outside walls, beside the structure) the cloud says nothing"),
            std::string::npos)
      << between.free_space;
  options.region = environment::AssumedFreeRegion::WholeBox;
  const auto box = environment::mapFromPointsAlone(points, options);
  EXPECT_EQ(stateIn(box, {2.0, 3.0, 1.5}), "free");
  EXPECT_EQ(stateIn(box, {6.0, 3.0, 1.5}), "free");
  EXPECT_NE(box.free_space.find("behind walls and beside the structure too: planning may use space the scan never saw"),
            std::string::npos)
      << box.free_space;
  EXPECT_EQ(environment::assumedFreeRegionFromName("between"), environment::AssumedFreeRegion::BetweenSurfaces);
  EXPECT_EQ(environment::assumedFreeRegionFromName("box"), environment::AssumedFreeRegion::WholeBox);
  EXPECT_THROW(environment::assumedFreeRegionFromName("hull"), InputError);
}

// A scanned ceiling has holes (a lamp's shadow, a voxel between returns): a column under one has a
// floor but no ceiling. A hole of up to two voxels across takes the floor and ceiling around it, so
// it is no pillar of unknown space in the room; a wider one, and the space beyond the ceiling's
// edge, stay unknown: the outline of what was scanned does not grow.
TEST(MapBuilders, ACloudAloneClosesNarrowHolesInItsSurfacesOnly) {
  const auto floor = testing::sampleRectangle({0.01, 0.02, 0.013}, {8, 0, 0}, {0, 6, 0}, 0.05);
  const auto ceiling = testing::sampleRectangle({0.01, 0.02, 3.033}, {4, 0, 0}, {0, 6, 0}, 0.05);
  std::vector<Eigen::Vector3d> points = floor;
  const auto inHole = [](const Eigen::Vector3d& p, double x0, double y0, double width) {
    return p.x() >= x0 && p.x() < x0 + width && p.y() >= y0 && p.y() < y0 + width;
  };
  for (const Eigen::Vector3d& point : ceiling)
    if (!inHole(point, 2.0, 3.0, 0.1) && !inHole(point, 1.0, 1.0, 0.5)) points.push_back(point);
  environment::PointAssumptionOptions options;
  options.resolution_m = 0.1;
  options.free_distance_m = 0.0;
  const auto built = environment::mapFromPointsAlone(points, options);
  EXPECT_EQ(stateIn(built, {2.05, 3.05, 1.5}), "free");      // under the one-voxel hole
  EXPECT_EQ(stateIn(built, {2.05, 3.05, 3.05}), "unknown");  // the hole itself: no ceiling is made up there
  EXPECT_EQ(stateIn(built, {1.25, 1.25, 1.5}), "unknown");   // under the 0.5 m hole
  EXPECT_EQ(stateIn(built, {4.15, 3.05, 1.5}), "unknown");   // beyond the ceiling's edge
  EXPECT_EQ(stateIn(built, {3.95, 3.05, 1.5}), "free");      // inside it
  double closed = -1.0;
  for (const auto& [name, value] : built.figures)
    if (name == "columns_closed_across_holes") closed = value;
  EXPECT_EQ(closed, 1.0);
  EXPECT_NE(built.free_space.find("; holes of up to two voxels across in a scanned floor or ceiling take the floor "
                                  "and ceiling around them (1 column)"),
            std::string::npos)
      << built.free_space;
}

TEST(MapBuilders, RefuseBadResolutionsAndHugeBoxesBeforeAllocating) {
  const std::vector<Eigen::Vector3d> points = {{0, 0, 0}, {1, 1, 1}};
  environment::PointAssumptionOptions options;
  for (double resolution : {0.0, -0.1, 0.001, 5.0, std::numeric_limits<double>::quiet_NaN()}) {
    options.resolution_m = resolution;
    EXPECT_THROW(environment::mapFromPointsAlone(points, options), InputError) << resolution;
  }
  // 1.5 km x 1.5 km x 100 m at 0.05 m is 1.8e12 voxels: refused at once.
  options.resolution_m = 0.05;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_THROW(environment::mapFromPointsAlone({{0, 0, 0}, {1500, 1500, 100}}, options), InputError);
  EXPECT_THROW(
      environment::carveFromScans({{0, 0, 0}, {1500, 1500, 100}}, SensorOrigins{{0}, {{1, 1, 1}}}, {0.05, 0.0}),
      InputError);
  EXPECT_THROW(environment::mapFromMesh(testing::rectangleMesh({0, 0, 0}, {1500, 0, 0}, {0, 1500, 100}), {0.05, 1.0}),
               InputError);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  // Beyond OctoMap's 16-bit key space: 0.01 m holds +-327 m.
  options.resolution_m = 0.01;
  EXPECT_THROW(environment::mapFromPointsAlone({{400, 0, 0}, {401, 0, 0}}, options), InputError);
}

TEST(MapBuilders, RefuseEmptyAndNonFiniteInput) {
  environment::PointAssumptionOptions options;
  EXPECT_THROW(environment::mapFromPointsAlone({}, options), InputError);
  EXPECT_THROW(environment::mapFromPointsAlone({{0, 0, std::numeric_limits<double>::infinity()}}, options), InputError);
  environment::TriangleMesh mesh = testing::boxMesh({0, 0, 0}, {1, 1, 1});
  mesh.triangles[3][1] = 99;
  EXPECT_THROW(environment::mapFromMesh(mesh, {}), InputError);
  EXPECT_THROW(environment::mapFromMesh(environment::TriangleMesh{}, {}), InputError);
}

}  // namespace
}  // namespace ceilplan
