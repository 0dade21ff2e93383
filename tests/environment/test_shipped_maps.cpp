// The shipped scenes are up to date, small, and their missions' targets are reachable.

#include "analytic_maps.hpp"
#include "ceilplan/io/vehicle_file.hpp"
#include "run_command.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/environment/environment.hpp"
#include "ceilplan/environment/scenes.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>

namespace ceilplan::environment {
namespace {

const std::filesystem::path kMaps = CEILPLAN_SOURCE_DIR "/maps";

class ShippedScene : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedScene, RegeneratingItGivesTheCommittedFileByteForByte) {
  const auto dir = testing::scratchDirectory("regenerate_" + GetParam());
  const auto result = testing::runCeilplan("mapgen --scene " + GetParam() + " --out " + (dir / "scene.bt").string());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("seed 1"), std::string::npos) << result.out;
  const std::string committed = testing::readWholeFile(kMaps / (GetParam() + ".bt"));
  EXPECT_LT(committed.size(), 5u * 1024 * 1024);
  EXPECT_TRUE(committed == testing::readWholeFile(dir / "scene.bt"))
      << "maps/" << GetParam() << ".bt is out of date: run ceilplan mapgen --scene " << GetParam() << " --out maps/"
      << GetParam() << ".bt";
}

// Viewpoints at the ends and middle of the standoff range, straight away from the surface
// side or tilted up to 60 degrees around it.
bool hasValidViewpoint(const Environment& environment, const Eigen::Vector3d& target, double near_m, double far_m) {
  for (const double distance : {near_m, 0.5 * (near_m + far_m), far_m})
    for (const double tilt : {0.0, 0.5, 1.0})
      for (int azimuth = 0; azimuth < 8; ++azimuth)
        for (const double vertical : {-1.0, 1.0}) {
          const double a = azimuth * M_PI / 4;
          const Eigen::Vector3d direction(std::sin(tilt) * std::cos(a), std::sin(tilt) * std::sin(a),
                                          vertical * std::cos(tilt));
          if (environment.isStateValid(target + distance * direction)) return true;
        }
  return false;
}

TEST_P(ShippedScene, EveryMissionTargetLiesOnAnOccupiedSurfaceAndCanBeViewed) {
  const std::filesystem::path mission_file = kMaps / (GetParam() + ".yaml");
  const YAML::Node mission = YAML::LoadFile(mission_file.string());
  const OccupancyMap map = OccupancyMap::load(kMaps / mission["map"].as<std::string>());
  const VehicleGeometry vehicle =
      io::readVehicle(mission_file.parent_path() / mission["vehicle"].as<std::string>()).geometry;
  const Environment environment(map, vehicle);

  const auto home = mission["home"].as<std::vector<double>>();
  EXPECT_TRUE(environment.isStateValid({home[0], home[1], home[2]}));
  EXPECT_GE(mission["targets"].size(), 8u);
  EXPECT_LE(mission["targets"].size(), 20u);
  for (const auto& target : mission["targets"]) {
    const auto p = target["point"].as<std::vector<double>>();
    const auto standoff = target["standoff_m"].as<std::vector<double>>();
    const Eigen::Vector3d point(p[0], p[1], p[2]);
    const std::string name = target["name"].as<std::string>();
    EXPECT_TRUE(testing::onOccupiedSurface(environment.grid(), point)) << name;
    EXPECT_TRUE(hasValidViewpoint(environment, point, standoff[0], standoff[1])) << name;
    EXPECT_GT(target["dwell_s"].as<double>(), 0.0) << name;
  }
}

INSTANTIATE_TEST_SUITE_P(Maps, ShippedScene, ::testing::Values("bridge", "tunnel", "warehouse", "open"));

TEST(Scenes, DifferentSeedsMoveTheClutterAndTheSameSeedRepeatsIt) {
  const VoxelGrid a = generateScene(Scene::Warehouse, 0.1, 3), b = generateScene(Scene::Warehouse, 0.1, 3),
                  c = generateScene(Scene::Warehouse, 0.1, 4);
  std::size_t same_ab = 0, same_ac = 0;
  for (std::size_t v = 0; v < a.frame().voxelCount(); ++v) {
    same_ab += a.atLinear(v) == b.atLinear(v);
    same_ac += a.atLinear(v) == c.atLinear(v);
  }
  EXPECT_EQ(same_ab, a.frame().voxelCount());
  EXPECT_LT(same_ac, a.frame().voxelCount());
  EXPECT_THROW(sceneFromName("castle"), ceilplan::InputError);
}

TEST(Scenes, TheBridgeDeckUndersideIsSixMetresUpAndTheOpenSceneHasNoCeiling) {
  const VoxelGrid bridge = generateScene(Scene::Bridge, 0.1, 1);
  const ColumnIndex columns(bridge);
  const GridFrame& frame = bridge.frame();
  const int i = frame.indexOf(0, 6.05), j = frame.indexOf(1, 0.05);
  EXPECT_NEAR(columns.above(i, j, 3.0).face_m, 6.0, 1e-9);
  EXPECT_EQ(columns.above(i, j, 3.0).state, CellState::Occupied);
  EXPECT_NEAR(columns.below(i, j, 3.0).face_m, 0.0, 1e-9);
  const VoxelGrid open = generateScene(Scene::Open, 0.1, 1);
  EXPECT_EQ(ColumnIndex(open).above(i, j, 3.0).state, CellState::Unknown);
}

void expectSameGaps(const SurfaceGaps& together, const SurfaceGaps& alone, const Eigen::Vector3d& at) {
  ASSERT_EQ(together.rotors.size(), alone.rotors.size());
  for (std::size_t r = 0; r < alone.rotors.size(); ++r) {
    EXPECT_EQ(together.rotors[r].nearest_gap_m, alone.rotors[r].nearest_gap_m) << at.transpose();
    EXPECT_EQ(together.rotors[r].coverage, alone.rotors[r].coverage) << at.transpose();
    EXPECT_EQ(together.rotors[r].mean_gap_m, alone.rotors[r].mean_gap_m) << at.transpose();
  }
  EXPECT_EQ(together.nearest_gap_m, alone.nearest_gap_m) << at.transpose();
  EXPECT_EQ(together.coverage, alone.coverage) << at.transpose();
  EXPECT_EQ(together.mean_gap_m, alone.mean_gap_m) << at.transpose();
}

// The cost model asks for both gaps at every sample: one search of each column for the two
// gives what each query alone gives, to the bit, under the deck, its girders and cross-frames,
// beside the piers, at voxel faces and with unknown space counted as a surface or not.
TEST(Scenes, TheCeilingAndGroundLookedUpTogetherAreEachLookedUpAlone) {
  const OccupancyMap map = OccupancyMap::load(kMaps / "bridge.bt");
  const VehicleGeometry vehicle = io::readVehicle(kMaps / "vehicles/quad.yaml").geometry;
  const Environment environment(map, vehicle);
  EnvironmentOptions unknown_surface;
  unknown_surface.unknown_is_surface = true;
  const Environment counting_unknown(environment.index(), vehicle, unknown_surface);
  const ColumnIndex& columns = environment.columns();
  const GridFrame& frame = environment.grid().frame();
  const double resolution = frame.resolution_m();
  int compared = 0, partly_covered = 0;
  for (double x = -1.97; x < 50.0; x += 0.61)
    for (double y = -4.93; y < 5.0; y += 0.37)
      for (double z = 0.3; z < 7.5; z += 0.29) {
        const Eigen::Vector3d at(x, y, z);
        if (!environment.contains(at)) continue;
        for (const Environment* env : {&environment, &counting_unknown}) {
          const Environment::CeilingAndGround both = env->ceilingAndGround(at);
          expectSameGaps(both.ceiling, env->ceiling(at), at);
          expectSameGaps(both.ground, env->ground(at), at);
          partly_covered += both.ceiling.coverage > 0.0 && both.ceiling.coverage < 1.0;
        }
        // Also on a voxel face, where above() and below() treat the boundary differently.
        const int i = frame.indexOf(0, x), j = frame.indexOf(1, y);
        for (const double height : {z, std::round(z / resolution) * resolution}) {
          const ColumnIndex::Boundaries around = columns.around(i, j, height);
          const ColumnIndex::Boundary above = columns.above(i, j, height), below = columns.below(i, j, height);
          EXPECT_EQ(around.above.face_m, above.face_m);
          EXPECT_EQ(around.above.state, above.state);
          EXPECT_EQ(around.below.face_m, below.face_m);
          EXPECT_EQ(around.below.state, below.state);
        }
        ++compared;
      }
  EXPECT_GT(compared, 10000);
  EXPECT_GT(partly_covered, 100);  // discs over an edge, where each column is weighed
}

}  // namespace
}  // namespace ceilplan::environment
