// `ceilplan import` as a user runs it: each import path on a generated structure, then the map's
// gap and clearance queries agree with the source geometry to one voxel.

#include "ceilplan/io/vehicle_file.hpp"
#include "run_command.hpp"
#include "scan_files.hpp"

#include "ceilplan/environment/environment.hpp"
#include "ceilplan/environment/occupancy_map.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace ceilplan {
namespace {

using environment::Environment;
using environment::EnvironmentOptions;
using environment::OccupancyMap;

constexpr double kVoxel = 0.1;
const std::string kVehicle = CEILPLAN_SOURCE_DIR "/maps/vehicles/quad.yaml";

Environment environmentOf(const std::filesystem::path& map, EnvironmentOptions options = {}) {
  return Environment(OccupancyMap::load(map), io::readVehicle(kVehicle).geometry, options);
}

nlohmann::json sidecarOf(const std::filesystem::path& map) {
  return nlohmann::json::parse(testing::readWholeFile(map.string() + ".json"));
}

// State at a point of the written map: "occupied", "free" or "unknown".
std::string stateAt(const std::filesystem::path& map, const Eigen::Vector3d& point) {
  const OccupancyMap loaded = OccupancyMap::load(map);
  const octomap::OcTreeNode* node = loaded.tree().search(point.x(), point.y(), point.z());
  if (!node) return "unknown";
  return loaded.tree().isNodeOccupied(node) ? "occupied" : "free";
}

testing::CommandResult importOk(const std::string& arguments) {
  const auto result = testing::runCeilplan("import " + arguments);
  EXPECT_EQ(result.exit_code, 0) << arguments << "\n" << result.err;
  EXPECT_EQ(result.err, "");  // quiet when stderr is not a terminal, and Open3D says nothing
  return result;
}

// A room 6 x 4 x 3 m, its walls off the voxel grid, sampled every 3 cm.
const Eigen::Vector3d kRoomMin(0.013, 0.017, 0.011), kRoomMax(6.013, 4.017, 3.011);

TEST(ImportPoints, WithSensorOriginsCarvesTheRoomByRayCasting) {
  const auto dir = testing::scratchDirectory("room_origins");
  testing::writePcd(dir / "room.pcd", testing::sampleBoxSurface(kRoomMin, kRoomMax, 0.03), /*binary=*/true);
  std::ofstream(dir / "origins.csv") << "x,y,z\n3.0,2.0,1.5\n";
  const auto result =
      importOk("--points " + (dir / "room.pcd").string() + " --origins " + (dir / "origins.csv").string() +
               " --resolution 0.1 --out " + (dir / "room.bt").string());
  EXPECT_NE(result.out.find("free_space: carved by ray casting from 1 sensor origin (max range none)"),
            std::string::npos)
      << result.out;

  const Environment environment = environmentOf(dir / "room.bt");
  const Eigen::Vector3d at(3.0, 2.0, 1.0);
  EXPECT_NEAR(environment.ceilingGapAt(at), kRoomMax.z() - at.z(), kVoxel);
  EXPECT_NEAR(environment.groundGapAt(at), at.z() - kRoomMin.z(), kVoxel);
  const Eigen::Vector3d centre(3.0, 2.0, 1.5);
  EXPECT_NEAR(environment.clearance_m(centre), centre.z() - kRoomMin.z(), kVoxel);
  EXPECT_TRUE(environment.isStateValid(centre));
  EXPECT_EQ(stateAt(dir / "room.bt", {5.9, 3.9, 2.9}), "free");     // a corner the rays reach
  EXPECT_EQ(stateAt(dir / "room.bt", {7.0, 2.0, 1.5}), "unknown");  // behind the wall: never seen
  const auto sidecar = sidecarOf(dir / "room.bt");
  EXPECT_EQ(sidecar["kind"], "points");
  EXPECT_NE(sidecar["free_space"].get<std::string>().find("ray casting"), std::string::npos);
}

TEST(ImportPoints, PerScanAndPerPointOriginsGiveTheSameRoom) {
  const auto dir = testing::scratchDirectory("room_scans");
  const auto points = testing::sampleBoxSurface(kRoomMin, kRoomMax, 0.03);
  testing::writePlyPoints(dir / "room.ply", points);
  // Two scans from two stations; then the same stations given per point.
  const std::size_t half = points.size() / 2;
  std::ofstream(dir / "scans.csv") << "first_point,x,y,z\n0,1.5,2.0,1.5\n" << half << ",4.5,2.0,1.5\n";
  {
    std::ofstream per_point(dir / "points.csv");
    per_point << "x,y,z\n";
    for (std::size_t i = 0; i < points.size(); ++i) per_point << (i < half ? "1.5" : "4.5") << ",2.0,1.5\n";
  }
  importOk("--points " + (dir / "room.ply").string() + " --origins " + (dir / "scans.csv").string() +
           " --resolution 0.1 --out " + (dir / "scans.bt").string());
  importOk("--points " + (dir / "room.ply").string() + " --origins " + (dir / "points.csv").string() +
           " --resolution 0.1 --out " + (dir / "points.bt").string());
  EXPECT_EQ(testing::readWholeFile(dir / "scans.bt"), testing::readWholeFile(dir / "points.bt"));
  EXPECT_EQ(sidecarOf(dir / "scans.bt")["figures"]["scans"], 2);
  const Environment environment = environmentOf(dir / "scans.bt");
  EXPECT_NEAR(environment.ceilingGapAt({1.0, 1.0, 2.0}), kRoomMax.z() - 2.0, kVoxel);
}

TEST(ImportPoints, AThinWallSeenAtGrazingAnglesStaysClosed) {
  // A 1 cm partition across the room at x = 3.04. One scan sees all of it face on; four more,
  // from stations beside it, see only its far end (y > 3.8), so their rays graze the wall's
  // nearer voxels. Those voxels hold returns of the first scan and must stay occupied.
  const auto dir = testing::scratchDirectory("thin_wall");
  auto points = testing::sampleBoxSurface(kRoomMin, kRoomMax, 0.03);
  const auto wall = testing::sampleRectangle({3.035, kRoomMin.y(), kRoomMin.z()}, {0, 4.0, 0}, {0, 0, 3.0}, 0.03);
  points.insert(points.end(), wall.begin(), wall.end());
  std::ofstream origins(dir / "origins.csv");
  origins << "first_point,x,y,z\n0,1.5,2.0,1.5\n";
  for (double z : {0.5, 1.0, 1.5, 2.0}) {
    origins << points.size() << ",2.93,0.3," << z << "\n";
    for (const Eigen::Vector3d& p : wall)
      if (p.y() > 3.8) points.push_back(p);
  }
  origins.close();
  testing::writePcd(dir / "wall.pcd", points, false);
  importOk("--points " + (dir / "wall.pcd").string() + " --origins " + (dir / "origins.csv").string() +
           " --resolution 0.1 --out " + (dir / "wall.bt").string());
  const OccupancyMap map = OccupancyMap::load(dir / "wall.bt");
  for (double y = 0.05; y < 4.0; y += 0.1)
    for (double z = 0.05; z < 3.0; z += 0.1) {
      const octomap::OcTreeNode* node = map.tree().search(3.04, y, z);
      ASSERT_NE(node, nullptr) << y << ", " << z;
      EXPECT_TRUE(map.tree().isNodeOccupied(node)) << y << ", " << z;
    }
}

// A bridge-like scene for clouds without origins: ground at z = 0.013, a deck from 3.033 to 3.433.
std::vector<Eigen::Vector3d> deckAndGround() {
  auto points = testing::sampleRectangle({0.01, 0.02, 0.013}, {8, 0, 0}, {0, 6, 0}, 0.03);
  for (double z : {3.033, 3.433}) {
    const auto deck = testing::sampleRectangle({0.01, 0.02, z}, {8, 0, 0}, {0, 6, 0}, 0.03);
    points.insert(points.end(), deck.begin(), deck.end());
  }
  return points;
}

TEST(ImportPoints, WithoutOriginsFreeSpaceIsAssumedAndSaidSo) {
  const auto dir = testing::scratchDirectory("deck_alone");
  testing::writePcd(dir / "deck.pcd", deckAndGround(), false);
  const auto result = importOk("--points " + (dir / "deck.pcd").string() +
                               " --resolution 0.1 --free-distance 0 --out " + (dir / "deck.bt").string());
  EXPECT_NE(result.out.find("free_space: assumed, no sensor origins"), std::string::npos) << result.out;
  const Environment environment = environmentOf(dir / "deck.bt");
  const Eigen::Vector3d at(4.0, 3.0, 2.0);
  EXPECT_NEAR(environment.ceilingGapAt(at), 3.033 - at.z(), kVoxel);
  EXPECT_NEAR(environment.groundGapAt(at), at.z() - 0.013, kVoxel);
  EXPECT_TRUE(environment.isStateValid(at));
}

TEST(ImportPoints, WithoutOriginsTheDefaultKeepsTwoVoxelsNextToPointsUnknown) {
  const auto dir = testing::scratchDirectory("deck_band");
  testing::writePcd(dir / "deck.pcd", deckAndGround(), true);
  const auto result =
      importOk("--points " + (dir / "deck.pcd").string() + " --resolution 0.1 --out " + (dir / "deck.bt").string());
  const std::string rule = sidecarOf(dir / "deck.bt")["free_space"];
  EXPECT_NE(rule.find("farther than 0.2 m from them is free; the rest is unknown"), std::string::npos) << rule;
  EXPECT_NE(result.out.find(rule), std::string::npos);
  // The default gap rule sees unknown before the deck: no ceiling. Counting unknown as a
  // surface, the ceiling starts where the band does.
  const Eigen::Vector3d at(4.0, 3.0, 2.0);
  EXPECT_TRUE(std::isinf(environmentOf(dir / "deck.bt").ceilingGapAt(at)));
  EnvironmentOptions options;
  options.unknown_is_surface = true;
  EXPECT_NEAR(environmentOf(dir / "deck.bt", options).ceilingGapAt(at), 3.033 - 0.2 - at.z(), kVoxel);
  EXPECT_EQ(stateAt(dir / "deck.bt", {4.0, 3.0, 3.05}), "occupied");
  EXPECT_EQ(stateAt(dir / "deck.bt", {4.0, 3.0, 2.95}), "unknown");
}

TEST(ImportMesh, AClosedSolidIsFilledAndTheSpaceAroundItIsFree) {
  const auto dir = testing::scratchDirectory("pier");
  const Eigen::Vector3d min(1.03, 1.07, 0.02), max(3.03, 3.07, 3.02);
  testing::writeStlBinary(dir / "pier.stl", testing::boxMesh(min, max));
  const auto result =
      importOk("--mesh " + (dir / "pier.stl").string() + " --resolution 0.1 --out " + (dir / "pier.bt").string());
  EXPECT_NE(result.out.find("closed mesh, triangles facing outward"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("filled as occupied"), std::string::npos) << result.out;
  EXPECT_EQ(stateAt(dir / "pier.bt", (min + max) / 2), "occupied");
  EXPECT_EQ(stateAt(dir / "pier.bt", {0.1, 0.1, 3.9}), "free");  // in the 1 m margin
  const Environment environment = environmentOf(dir / "pier.bt");
  EXPECT_NEAR(environment.clearance_m({0.53, 2.0, 1.5}), 0.5, kVoxel);
  EXPECT_NEAR(environment.groundGapAt({2.0, 2.0, 3.5}), 3.5 - max.z(), kVoxel);
  const auto sidecar = sidecarOf(dir / "pier.bt");
  EXPECT_EQ(sidecar["kind"], "mesh");
  EXPECT_EQ(sidecar["figures"]["boundary_edges"], 0);
  // Filled volume: the box's, plus at most a voxel-thick shell around its surface.
  const Eigen::Vector3d size = max - min;
  const double area = 2.0 * (size.x() * size.y() + size.y() * size.z() + size.z() * size.x());
  EXPECT_GE(sidecar["figures"]["occupied_m3"].get<double>(), size.prod());
  EXPECT_LE(sidecar["figures"]["occupied_m3"].get<double>(), size.prod() + area * kVoxel);
}

TEST(ImportMesh, AClosedInwardFacingMeshIsARoom) {
  const auto dir = testing::scratchDirectory("hall");
  testing::writeObj(dir / "hall.obj", testing::boxMesh(kRoomMin, kRoomMax, /*outward=*/false));
  const auto result =
      importOk("--mesh " + (dir / "hall.obj").string() + " --resolution 0.1 --out " + (dir / "hall.bt").string());
  EXPECT_NE(result.out.find("facing inward"), std::string::npos) << result.out;
  EXPECT_EQ(stateAt(dir / "hall.bt", {3.0, 2.0, 1.5}), "free");
  EXPECT_EQ(stateAt(dir / "hall.bt", {-0.5, 2.0, 1.5}), "unknown");  // outside the room
  const Environment environment = environmentOf(dir / "hall.bt");
  EXPECT_NEAR(environment.ceilingGapAt({3.0, 2.0, 1.0}), kRoomMax.z() - 1.0, kVoxel);
  EXPECT_NEAR(environment.clearance_m({3.0, 2.0, 1.5}), 1.5 - kRoomMin.z(), kVoxel);
  // The same mesh forced solid fills the room.
  importOk("--mesh " + (dir / "hall.obj").string() + " --interior solid --resolution 0.1 --out " +
           (dir / "solid.bt").string());
  EXPECT_EQ(stateAt(dir / "solid.bt", {3.0, 2.0, 1.5}), "occupied");
}

TEST(ImportMesh, AnOpenSlabIsVoxelisedWithFreeSpaceOnBothSides) {
  const auto dir = testing::scratchDirectory("slab");
  const auto slab = testing::rectangleMesh({0.01, 0.02, 2.97}, {6, 0, 0}, {0, 4, 0});
  testing::writeObj(dir / "slab.obj", slab);
  testing::writePlyMesh(dir / "slab.ply", slab);
  for (const std::string name : {"slab.obj", "slab.ply"}) {
    const std::filesystem::path map = dir / (name + ".bt");
    const auto result = importOk("--mesh " + (dir / name).string() + " --resolution 0.1 --out " + map.string());
    EXPECT_NE(result.out.find("open mesh (4 boundary edges"), std::string::npos) << result.out;
    const Environment environment = environmentOf(map);
    EXPECT_NEAR(environment.ceilingGapAt({3.0, 2.0, 2.3}), 2.97 - 2.3, kVoxel) << name;
    EXPECT_TRUE(std::isinf(environment.groundGapAt({3.0, 2.0, 2.3}))) << name;
    EXPECT_EQ(stateAt(map, {3.0, 2.0, 3.5}), "free") << name;
    EXPECT_EQ(stateAt(map, {3.0, 2.0, 2.97}), "occupied") << name;
  }
}

TEST(ImportMesh, AnOpenBoxIsNotFilled) {
  // A room without its ceiling: not closed, so nothing is enclosed.
  const auto dir = testing::scratchDirectory("open_box");
  auto mesh = testing::boxMesh(kRoomMin, kRoomMax);
  mesh.triangles.erase(mesh.triangles.begin() + 2, mesh.triangles.begin() + 4);  // the top face
  testing::writeStlBinary(dir / "open.stl", mesh);
  const auto result =
      importOk("--mesh " + (dir / "open.stl").string() + " --resolution 0.1 --out " + (dir / "open.bt").string());
  EXPECT_NE(result.out.find("it encloses no space"), std::string::npos) << result.out;
  EXPECT_EQ(stateAt(dir / "open.bt", {3.0, 2.0, 1.5}), "free");
}

// The free-space line of a summary: one line, printed and in the sidecar.
std::string freeSpaceLine(const testing::CommandResult& result, const std::filesystem::path& map) {
  const std::string rule = sidecarOf(map)["free_space"];
  EXPECT_EQ(rule.find('\n'), std::string::npos) << rule;
  EXPECT_NE(result.out.find("free_space: " + rule + "\n"), std::string::npos) << result.out;
  return rule;
}

// A box mesh with two of its faces (0 z-min, 1 z-max, 2 y-min, 3 y-max, 4 x-min, 5 x-max) left out.
environment::TriangleMesh boxWithout(const Eigen::Vector3d& min, const Eigen::Vector3d& max, int face_a, int face_b) {
  const environment::TriangleMesh box = testing::boxMesh(min, max);
  environment::TriangleMesh mesh = box;
  mesh.triangles.clear();
  for (int t = 0; t < 12; ++t)
    if (t / 2 != face_a && t / 2 != face_b) mesh.triangles.push_back(box.triangles[t]);
  return mesh;
}

TEST(ImportMesh, AnOpenSweptTubeIsAThinShellWithItsInsideFree) {
  // A deck modelled as a box profile swept along x, its ends open: its inside is free space the
  // vehicle can fly in, its inner faces are surfaces to be seen from there.
  const auto dir = testing::scratchDirectory("open_tube");
  const Eigen::Vector3d min(0.03, -1.23, 2.02), max(10.03, 1.27, 3.82);
  testing::writeObj(dir / "tube.obj", boxWithout(min, max, 4, 5));
  const auto result =
      importOk("--mesh " + (dir / "tube.obj").string() + " --resolution 0.1 --out " + (dir / "tube.bt").string());
  const std::string rule = freeSpaceLine(result, dir / "tube.bt");
  EXPECT_EQ(rule.rfind("open mesh (8 boundary edges, 0 shared by more than two triangles, so not watertight): thin "
                       "shell, both sides free; surface voxelised",
                       0),
            0u)
      << rule;
  EXPECT_NE(rule.find("planning may use both sides of every surface"), std::string::npos) << rule;
  const Eigen::Vector3d inside(5.0, 0.0, 2.9);
  EXPECT_EQ(stateAt(dir / "tube.bt", inside), "free");
  EXPECT_EQ(stateAt(dir / "tube.bt", {5.0, 0.0, 3.82}), "occupied");  // the deck's soffit, seen from inside
  EXPECT_EQ(stateAt(dir / "tube.bt", {5.0, 0.0, 4.3}), "free");       // and above it
  const Environment environment = environmentOf(dir / "tube.bt");
  EXPECT_TRUE(environment.isStateValid(inside));
  EXPECT_NEAR(environment.ceilingGapAt(inside), max.z() - inside.z(), kVoxel);
  EXPECT_NEAR(environment.groundGapAt(inside), inside.z() - min.z(), kVoxel);
}

TEST(ImportMesh, OnlyClosedMeshesAreFilled) {
  const auto dir = testing::scratchDirectory("closed_or_not");
  const Eigen::Vector3d min(1.03, 1.07, 0.02), max(3.03, 3.07, 3.02), centre = (min + max) / 2;
  testing::writeStlBinary(dir / "closed.stl", testing::boxMesh(min, max));
  const auto closed =
      importOk("--mesh " + (dir / "closed.stl").string() + " --resolution 0.1 --out " + (dir / "closed.bt").string());
  EXPECT_EQ(freeSpaceLine(closed, dir / "closed.bt")
                .rfind("closed mesh, triangles facing outward: solid, interior filled; surface voxelised", 0),
            0u);
  EXPECT_EQ(stateAt(dir / "closed.bt", centre), "occupied");
  // The same box with its lid 1 mm above its walls: not watertight, though at 0.1 m its surface
  // voxels enclose the inside. Only a closed mesh is filled.
  environment::TriangleMesh lifted = boxWithout(min, max, 1, 1);
  const std::size_t first = lifted.vertices_m.size();
  const environment::TriangleMesh lid =
      testing::rectangleMesh({min.x(), min.y(), max.z() + 0.001}, {max.x() - min.x(), 0, 0}, {0, max.y() - min.y(), 0});
  for (const Eigen::Vector3d& v : lid.vertices_m) lifted.vertices_m.push_back(v);
  for (const auto& t : lid.triangles) lifted.triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
  testing::writeStlBinary(dir / "lifted.stl", lifted);
  const auto open =
      importOk("--mesh " + (dir / "lifted.stl").string() + " --resolution 0.1 --out " + (dir / "lifted.bt").string());
  const std::string rule = freeSpaceLine(open, dir / "lifted.bt");
  EXPECT_NE(rule.find("thin shell, both sides free"), std::string::npos) << rule;
  EXPECT_NE(rule.find(" m3 it encloses at 0.1 m is free too"), std::string::npos) << rule;
  EXPECT_EQ(stateAt(dir / "lifted.bt", centre), "free");
  EXPECT_GT(sidecarOf(dir / "lifted.bt")["figures"]["boundary_edges"].get<int>(), 0);
  // Told it is solid, it is filled.
  const auto forced = importOk("--mesh " + (dir / "lifted.stl").string() + " --interior solid --resolution 0.1 --out " +
                               (dir / "forced.bt").string());
  EXPECT_NE(freeSpaceLine(forced, dir / "forced.bt").find("filled as solid (--interior solid)"), std::string::npos);
  EXPECT_EQ(stateAt(dir / "forced.bt", centre), "occupied");
}

TEST(ImportMesh, ACropClipsTrianglesAtItsFacesAndKeepsAClosedSolidFilled) {
  const auto dir = testing::scratchDirectory("crop_mesh");
  const Eigen::Vector3d min(1.03, 1.07, 0.02), max(3.03, 3.07, 3.02);
  testing::writeObj(dir / "pier.obj", testing::boxMesh(min, max));
  const auto result = importOk("--mesh " + (dir / "pier.obj").string() + " --crop 2,0,0,5,5,5 --resolution 0.1 --out " +
                               (dir / "pier.bt").string());
  EXPECT_NE(freeSpaceLine(result, dir / "pier.bt").find("(cropped to (2.00, 0.00, 0.00) to (5.00, 5.00, 5.00))"),
            std::string::npos);
  EXPECT_NE(result.out.find("extent_m: (2.00, 0.00, 0.00) to (4.10, 4.10, 4.10)"), std::string::npos) << result.out;
  // The crop's face runs through the solid: what it keeps of the inside is still filled.
  EXPECT_EQ(stateAt(dir / "pier.bt", {2.05, 2.0, 1.5}), "occupied");
  EXPECT_EQ(stateAt(dir / "pier.bt", {2.5, 2.0, 1.5}), "occupied");
  EXPECT_EQ(stateAt(dir / "pier.bt", {3.5, 2.0, 1.5}), "free");
  EXPECT_EQ(stateAt(dir / "pier.bt", {1.5, 2.0, 1.5}), "unknown");  // outside the map
  const auto sidecar = sidecarOf(dir / "pier.bt");
  EXPECT_EQ(sidecar["crop_m"]["min"], nlohmann::json::parse("[2.0, 0.0, 0.0]"));
  EXPECT_EQ(sidecar["crop_m"]["max"], nlohmann::json::parse("[5.0, 5.0, 5.0]"));
}

TEST(ImportPoints, MaxRangeDropsFarReturnsAndTheMapShrinks) {
  const auto dir = testing::scratchDirectory("max_range");
  const auto points = testing::sampleBoxSurface(kRoomMin, kRoomMax, 0.03);
  testing::writePcd(dir / "room.pcd", points, true);
  std::ofstream(dir / "origins.csv") << "x,y,z\n1.0,2.0,1.5\n";
  const std::string input = "--points " + (dir / "room.pcd").string() + " --origins " + (dir / "origins.csv").string();
  const auto whole = importOk(input + " --resolution 0.1 --out " + (dir / "whole.bt").string());
  EXPECT_NE(whole.out.find("extent_m: (0.00, 0.00, 0.00) to (6.10, 4.10, 3.10)"), std::string::npos) << whole.out;
  const auto near = importOk(input + " --max-range 2.5 --resolution 0.1 --out " + (dir / "near.bt").string());
  EXPECT_NE(near.out.find("free_space: carved by ray casting from 1 sensor origin (max range 2.5 m) along " +
                          std::to_string(points.size()) + " rays"),
            std::string::npos)
      << near.out;
  // The far wall (5 m away) is gone, and the map ends where the nearest returns kept do.
  const auto sidecar = sidecarOf(dir / "near.bt");
  EXPECT_LE(sidecar["extent_m"]["max"][0].get<double>(), 1.0 + 2.5 + kVoxel);
  EXPECT_LT(sidecar["figures"]["returns_within_range"].get<double>(), double(points.size()));
  EXPECT_EQ(stateAt(dir / "near.bt", {6.0, 2.0, 1.5}), "unknown");
  EXPECT_EQ(stateAt(dir / "near.bt", {0.05, 2.0, 1.5}), "occupied");  // the near wall stays
  // Rays to the far wall carve up to 2.5 m, inside the box of what is kept (the floor within
  // 2.5 m reaches x = 3).
  EXPECT_EQ(stateAt(dir / "near.bt", {2.7, 2.0, 1.5}), "free");
  EXPECT_EQ(stateAt(dir / "whole.bt", {6.0, 2.0, 1.5}), "occupied");
}

TEST(ImportPoints, ACropKeepsTheMapInsideTheBoxWithOrWithoutOrigins) {
  const auto dir = testing::scratchDirectory("crop_points");
  testing::writePcd(dir / "room.pcd", testing::sampleBoxSurface(kRoomMin, kRoomMax, 0.03), true);
  std::ofstream(dir / "origins.csv") << "x,y,z\n3.0,2.0,1.5\n";
  const std::string cloud = "--points " + (dir / "room.pcd").string() + " --crop -1,-1,-1,2,5,4 --resolution 0.1";
  const auto rays =
      importOk(cloud + " --origins " + (dir / "origins.csv").string() + " --out " + (dir / "rays.bt").string());
  EXPECT_NE(rays.out.find("extent_m: (0.00, 0.00, 0.00) to (2.10, 4.10, 3.10)"), std::string::npos) << rays.out;
  EXPECT_NE(freeSpaceLine(rays, dir / "rays.bt").find("(cropped to (-1.00, -1.00, -1.00) to (2.00, 5.00, 4.00)) along"),
            std::string::npos);
  EXPECT_EQ(stateAt(dir / "rays.bt", {0.05, 2.0, 1.5}), "occupied");
  EXPECT_EQ(stateAt(dir / "rays.bt", {1.0, 2.0, 1.5}), "free");  // carved by rays from an origin outside the crop
  EXPECT_EQ(stateAt(dir / "rays.bt", {3.0, 2.0, 1.5}), "unknown");
  EXPECT_LT(sidecarOf(dir / "rays.bt")["figures"]["returns_in_crop"].get<double>(),
            sidecarOf(dir / "rays.bt")["figures"]["points"].get<double>());
  const auto alone = importOk(cloud + " --out " + (dir / "alone.bt").string());
  EXPECT_LE(sidecarOf(dir / "alone.bt")["extent_m"]["max"][0].get<double>(), 2.0 + kVoxel + 1e-9);  // whole voxels
  EXPECT_GT(sidecarOf(dir / "alone.bt")["figures"]["points_in_crop"].get<double>(), 0.0);
}

TEST(ImportFreeSpace, OneLineSaysWhatWasAssumedAndWhatItMeansForPlanning) {
  const auto dir = testing::scratchDirectory("free_space_line");
  const auto points = deckAndGround();
  testing::writePcd(dir / "deck.pcd", points, true);
  std::ofstream(dir / "origins.csv") << "x,y,z\n4.0,3.0,1.5\n";
  const std::string deck = "--points " + (dir / "deck.pcd").string() + " --resolution 0.1 --out ";
  const auto rays = importOk(deck + (dir / "rays.bt").string() + " --origins " + (dir / "origins.csv").string());
  EXPECT_EQ(freeSpaceLine(rays, dir / "rays.bt"),
            "carved by ray casting from 1 sensor origin (max range none) along " + std::to_string(points.size()) +
                " rays: space a ray crossed is free, a voxel holding a return is occupied, space no ray crossed is "
                "unknown: an obstacle for planning unless --unknown free or fill");
  const auto band = importOk(deck + (dir / "band.bt").string());
  EXPECT_EQ(freeSpaceLine(band, dir / "band.bt"),
            "assumed, no sensor origins: voxels holding a point are occupied; every other voxel of the points' "
            "bounding box with a point above and below it in its column whose centre lies farther than 0.2 m from "
            "them is free; the rest is unknown: an obstacle for planning unless --unknown free or fill, and no "
            "ceiling is seen through that band; beyond the scanned surfaces (outside walls, beside the structure) "
            "the cloud says nothing, so that space is unknown");
  const auto dense = importOk(deck + (dir / "dense.bt").string() + " --free-distance 0");
  EXPECT_EQ(freeSpaceLine(dense, dir / "dense.bt"),
            "assumed, no sensor origins: voxels holding a point are occupied; every other voxel of the points' "
            "bounding box with a point above and below it in its column is free; beyond the scanned surfaces "
            "(outside walls, beside the structure) the cloud says nothing, so that space is unknown");
  const auto whole_box = importOk(deck + (dir / "box.bt").string() + " --free-distance 0 --free-region box");
  EXPECT_EQ(freeSpaceLine(whole_box, dir / "box.bt"),
            "assumed, no sensor origins: voxels holding a point are occupied; every other voxel of the points' "
            "bounding box is free, behind walls and beside the structure too: planning may use space the scan "
            "never saw");
  testing::writeObj(dir / "hall.obj", testing::boxMesh(kRoomMin, kRoomMax, /*outward=*/false));
  const auto hall =
      importOk("--mesh " + (dir / "hall.obj").string() + " --resolution 0.1 --out " + (dir / "hall.bt").string());
  const std::string hollow = freeSpaceLine(hall, dir / "hall.bt");
  EXPECT_EQ(hollow.rfind("closed mesh, triangles facing inward: hollow, inside free; ", 0), 0u) << hollow;
  EXPECT_NE(hollow.find("stays unknown (hollow interior): an obstacle for planning unless --unknown free or fill"),
            std::string::npos)
      << hollow;
}

}  // namespace
}  // namespace ceilplan
