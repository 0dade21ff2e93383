// Regions: shapes, face kinds, the refusal of bad regions (overlap of 100 % or more,
// GSD <= 0, a camera that cannot reach the GSD beyond its minimum focus, a gimbal that cannot
// point at the faces, a region with no surface), and contact grids as tour targets.

#include "coverage_fixtures.hpp"

#include "ceilplan/mission/contact_points.hpp"
#include "ceilplan/mission/region_surface.hpp"

#include <gtest/gtest.h>

namespace ceilplan::mission {
namespace {

std::string errorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const ceilplan::InputError& e) {
    return e.what();
  }
  return "no error";
}

::testing::AssertionResult mentions(const std::string& message, const std::vector<std::string>& words) {
  for (const std::string& word : words)
    if (message.find(word) == std::string::npos)
      return ::testing::AssertionFailure() << "'" << word << "' not in: " << message;
  return ::testing::AssertionSuccess();
}

CoverageRegion ceilingRegion() {
  CoverageRegion region;
  region.name = "ceiling";
  region.shape = RegionShape::makeBox({-2, -2, 2.9}, {2, 2, 3.1});
  region.faces.down = true;
  return region;
}

TEST(Regions, FaceKindsSplitAt45Degrees) {
  EXPECT_EQ(faceKindOf(-Eigen::Vector3d::UnitZ()), FaceKind::Down);
  EXPECT_EQ(faceKindOf(Eigen::Vector3d::UnitZ()), FaceKind::Up);
  EXPECT_EQ(faceKindOf(Eigen::Vector3d::UnitX()), FaceKind::Side);
  EXPECT_EQ(faceKindOf(Eigen::Vector3d(0, 0.6, -0.8)), FaceKind::Down);
  EXPECT_EQ(faceKindOf(Eigen::Vector3d(0, 0.8, -0.6)), FaceKind::Side);
  EXPECT_EQ(FaceSet({true, false, true}).describe(), "[down, up]");
}

TEST(Regions, PrismsHoldWhatTheirPolygonHolds) {
  // An L-shaped prism between 1 and 2 m.
  const RegionShape l = RegionShape::makePrism({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 1.0, 2.0);
  EXPECT_NO_THROW(l.validate("l"));
  EXPECT_TRUE(l.contains({0.5, 1.5, 1.5}));
  EXPECT_TRUE(l.contains({1.5, 0.5, 1.0}));   // on the bottom face
  EXPECT_TRUE(l.contains({2.0, 0.5, 1.5}));   // on an edge
  EXPECT_FALSE(l.contains({1.5, 1.5, 1.5}));  // the notch
  EXPECT_FALSE(l.contains({0.5, 0.5, 2.5}));
  EXPECT_TRUE(mentions(errorOf([] {
                         RegionShape::makePrism({{0, 0}, {1, 0}}, 0, 1).validate("p");
                       }),
                       {"p", "3 vertices"}));
  EXPECT_TRUE(mentions(errorOf([] {
                         RegionShape::makePrism({{0, 0}, {2, 2}, {2, 0}, {0, 1}}, 0, 1).validate("p");
                       }),
                       {"crosses itself"}));
  EXPECT_TRUE(mentions(errorOf([] {
                         RegionShape::makePrism({{0, 0}, {1, 0}, {0, 1}}, 1, 1).validate("p");
                       }),
                       {"prism.z"}));
  EXPECT_TRUE(mentions(errorOf([] { RegionShape::makeBox({0, 0, 0}, {1, 0, 1}).validate("b"); }), {"box"}));
}

TEST(Regions, BadRegionsAreRefusedNamingTheKey) {
  const auto refused = [](void (*change)(CoverageRegion&), const std::vector<std::string>& words) {
    CoverageRegion region = ceilingRegion();
    change(region);
    EXPECT_TRUE(mentions(errorOf([&] { region.validate(); }), words));
  };
  refused([](CoverageRegion& r) { r.overlap_front_pct = 100.0; }, {"ceiling", "overlap.front", "[0, 100)"});
  refused([](CoverageRegion& r) { r.overlap_side_pct = 120.0; }, {"overlap.side"});
  refused([](CoverageRegion& r) { r.gsd_mm_px = 0.0; }, {"gsd_mm_px"});
  refused([](CoverageRegion& r) { r.gsd_mm_px = -1.0; }, {"gsd_mm_px"});
  refused([](CoverageRegion& r) { r.gsd_mm_px = NAN; }, {"gsd_mm_px"});
  refused([](CoverageRegion& r) { r.max_incidence_deg = 90.0; }, {"max_incidence_deg"});
  refused([](CoverageRegion& r) { r.faces = FaceSet{}; }, {"faces"});
  refused([](CoverageRegion& r) { r.name.clear(); }, {"name"});
}

TEST(Regions, ACameraMustReachTheGsdBeyondItsMinimumFocus) {
  Camera camera = testing::upwardCamera();  // 0.338 mm/px per metre, focus from 0.5 m
  CoverageRegion region = ceilingRegion();
  region.gsd_mm_px = 0.1;  // needs 0.30 m
  EXPECT_TRUE(mentions(errorOf([&] { checkCameraReaches(camera, region); }),
                       {"ceiling", "gsd_mm_px", "0.296 m", "camera.min_focus_m"}));
  region.gsd_mm_px = 0.2;  // 0.59 m: beyond 0.5 m
  EXPECT_NO_THROW(checkCameraReaches(camera, region));
}

TEST(Regions, AGimbalMustPointAtTheFaces) {
  CoverageRegion region = ceilingRegion();
  region.max_incidence_deg = 30.0;  // down faces need pitch >= 60
  Camera camera = testing::upwardCamera();
  camera.gimbal_pitch_max_deg = 30.0;  // as published, mounted below
  EXPECT_TRUE(mentions(errorOf([&] { checkCameraReaches(camera, region); }),
                       {"'faces' includes down", "camera.gimbal_pitch_deg", "60"}));
  camera.gimbal_pitch_max_deg = 60.0;
  EXPECT_NO_THROW(checkCameraReaches(camera, region));
  region.faces = FaceSet{false, false, true};  // floors need pitch <= -60
  camera.gimbal_pitch_min_deg = -30.0;
  EXPECT_TRUE(mentions(errorOf([&] { checkCameraReaches(camera, region); }), {"'faces' includes up"}));
  region.faces = FaceSet{false, true, false};  // walls: a pitch within +-30
  camera.gimbal_pitch_min_deg = 45.0;
  camera.gimbal_pitch_max_deg = 90.0;
  EXPECT_TRUE(mentions(errorOf([&] { checkCameraReaches(camera, region); }), {"'faces' includes side"}));
}

TEST(Regions, ARegionWithNoSurfaceIsAnError) {
  const environment::OccupancyMap map = testing::room([](double, double) { return 3.0; });
  const auto grid = environment::VoxelGrid::fromTree(map.tree());
  // Mid-air: no face at all.
  EXPECT_TRUE(mentions(errorOf([&] {
                         extractRegionSurface(grid, RegionShape::makeBox({-1, -1, 1}, {1, 1, 2}),
                                              FaceSet{true, true, true}, "surface region 'air'");
                       }),
                       {"surface region 'air'", "no occupied voxel face facing [down, side, up]", "'box'"}));
  // The ceiling faces down, not up.
  EXPECT_TRUE(
      mentions(errorOf([&] {
                 extractRegionSurface(grid, ceilingRegion().shape, FaceSet{false, false, true}, "surface region 'c'");
               }),
               {"facing [up]"}));
  const RegionSurface ceiling = extractRegionSurface(grid, ceilingRegion().shape, FaceSet{true, false, false}, "c");
  EXPECT_EQ(ceiling.elements.size(), 40u * 40u);
  EXPECT_NEAR(ceiling.area_m2, 16.0, 1e-9);
}

TEST(Regions, PrismsSelectTheirFaces) {
  const environment::OccupancyMap map = testing::room([](double, double) { return 3.0; });
  const auto grid = environment::VoxelGrid::fromTree(map.tree());
  // The triangle (0, 0), (1.02, 0), (0, 1.02) of the ceiling holds the face centres (0.05 + 0.1 i,
  // 0.05 + 0.1 j) with i + j <= 9: 10 + 9 + ... + 1 of them.
  const RegionSurface triangle = extractRegionSurface(
      grid, RegionShape::makePrism({{0, 0}, {1.02, 0}, {0, 1.02}}, 2.9, 3.1), FaceSet{true, false, false}, "t");
  EXPECT_EQ(triangle.elements.size(), 55u);
  for (const auto& element : triangle.elements) EXPECT_LE(element.centre_m.x() + element.centre_m.y(), 1.0 + 1e-9);
}

TEST(Regions, ContactGridsBecomeTargetsOnTheSurface) {
  const environment::OccupancyMap map = testing::room([](double, double) { return 3.0; });
  const auto grid = environment::VoxelGrid::fromTree(map.tree());
  ContactGrid contact;
  contact.name = "thickness";
  contact.shape = RegionShape::makeBox({-1.5, -1.0, 2.95}, {1.5, 1.0, 3.05});
  contact.faces.down = true;
  contact.spacing_m = 1.0;
  contact.dwell_s = 12.0;
  const std::vector<InspectionTarget> targets = contactTargets(grid, contact);
  // Faces span x in [-1.45, 1.45] (2.9 m: 3 nodes at -1, 0, 1) and y in [-0.95, 0.95] (2 nodes).
  ASSERT_EQ(targets.size(), 6u);
  EXPECT_EQ(targets.front().name, "thickness_1");
  EXPECT_EQ(targets.back().name, "thickness_6");
  for (const InspectionTarget& target : targets) {
    EXPECT_NO_THROW(target.validate());
    EXPECT_DOUBLE_EQ(target.point_m.z(), 3.0);               // on the ceiling's faces
    EXPECT_NEAR(std::abs(target.point_m.y()), 0.45, 0.051);  // nearest face centre to +-0.45
    EXPECT_DOUBLE_EQ(target.dwell_s, 12.0);
    EXPECT_DOUBLE_EQ(target.standoff_max_m, 0.5);
  }
  contact.spacing_m = 0.0;
  EXPECT_TRUE(mentions(errorOf([&] { contactTargets(grid, contact); }), {"thickness", "spacing_m"}));
}

}  // namespace
}  // namespace ceilplan::mission
