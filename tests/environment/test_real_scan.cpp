// geb079.bt (liboctomap-dev's indoor scan, nobody here made it): its under-scanned corridor
// under each unknown-space policy, and the docs' own example on it.

#include "analytic_maps.hpp"
#include "run_command.hpp"

#include "ceilplan/environment/environment.hpp"
#include "ceilplan/environment/map_index.hpp"
#include "ceilplan/environment/map_statistics.hpp"
#include "ceilplan/environment/visibility.hpp"

#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <thread>

namespace ceilplan::environment {
namespace {

const std::string kGeb079 = "/usr/share/doc/liboctomap-dev/examples/data/geb079.bt";
const std::string kVehicle = CEILPLAN_SOURCE_DIR "/maps/vehicles/quad.yaml";

const OccupancyMap& geb079() {
  static const OccupancyMap map = OccupancyMap::load(kGeb079);
  return map;
}

std::shared_ptr<const MapIndex> indexed(UnknownPolicy policy) {
  MapIndexOptions options;
  options.unknown.policy = policy;  // fill: the default 2 m pockets
  return MapIndex::build(geb079(), options);
}

TEST(Geb079, LinesOfSightCrossingFreeBlocksGiveTheVoxelWalksAnswer) {
  // Sights between known-free voxels of the scan (camera to surface: the coverage views' casts)
  // and between arbitrary points of its box; the index's free blocks must change no answer.
  const auto index = indexed(UnknownPolicy::Occupied);
  const VoxelGrid& grid = index->grid();
  const GridFrame& frame = grid.frame();
  std::mt19937 random(7);
  std::vector<Eigen::Vector3d> free_points;
  std::uniform_int_distribution<std::size_t> voxel(0, frame.voxelCount() - 1);
  std::uniform_real_distribution<double> within(0.0, 1.0);
  while (free_points.size() < 2000) {
    const Index3 v = frame.unlinear(voxel(random));
    if (grid.at(v[0], v[1], v[2]) != CellState::Free) continue;
    free_points.emplace_back(frame.faceOf(0, v[0]) + within(random) * frame.resolution_m(),
                             frame.faceOf(1, v[1]) + within(random) * frame.resolution_m(),
                             frame.faceOf(2, v[2]) + within(random) * frame.resolution_m());
  }
  int clear = 0, blocked = 0;
  for (std::size_t n = 0; n < 20000; ++n) {
    const Eigen::Vector3d& a = free_points[n % free_points.size()];
    const Eigen::Vector3d& b = free_points[(n * 7919 + 13) % free_points.size()];
    const bool expected = lineOfSight(grid, a, b);
    ASSERT_EQ(lineOfSight(grid, index->freeBlocks(), a, b), expected) << a.transpose() << " -> " << b.transpose();
    ++(expected ? clear : blocked);
  }
  EXPECT_GT(clear, 1000);  // both answers are exercised
  EXPECT_GT(blocked, 1000);
}

TEST(Geb079, TheFreeBlocksAreBuiltOnceOnFirstUseFromAnyThread) {
  // Commands that cast no line of sight (plan, probe, point tours) must not pay for the blocks;
  // the coverage views ask for them from several threads at once.
  const auto index = indexed(UnknownPolicy::Occupied);
  const std::size_t before_bytes = index->memoryBytes();
  const FreeBlocks* seen[4] = {};
  std::vector<std::thread> threads;
  for (const FreeBlocks*& blocks : seen) threads.emplace_back([&index, &blocks] { blocks = &index->freeBlocks(); });
  for (std::thread& thread : threads) thread.join();
  for (const FreeBlocks* blocks : seen) EXPECT_EQ(blocks, seen[0]);
  EXPECT_EQ(index->memoryBytes(), before_bytes + seen[0]->memoryBytes());
  EXPECT_GT(seen[0]->memoryBytes(), 0u);
}

TEST(Geb079, FillFreesTheCorridorThatUnknownPocketsCutUp) {
  const Environment occupied(indexed(UnknownPolicy::Occupied), testing::quad());
  const Environment fill(indexed(UnknownPolicy::Fill), testing::quad());
  // Points along the corridor at 1 m, where only under-scanned air lies around the vehicle.
  for (const double x : {-3.0, 0.0, 3.0, 6.0, 9.0, 13.0, 16.0, 19.0, 25.0}) {
    const Eigen::Vector3d p(x, 0.0, 1.0);
    EXPECT_TRUE(fill.isStateValid(p)) << x;
    EXPECT_TRUE(fill.assumesFree(p)) << x;
    const auto violation = occupied.stateViolation(p);
    ASSERT_TRUE(violation) << x;
    EXPECT_EQ(violation->kind, ViolationKind::Unknown) << x;
  }
  // Along the corridor's centre line from x = -5 to 25 m.
  int valid_fill = 0, valid_occupied = 0, states = 0;
  for (double x = -5.0; x <= 25.0; x += 0.1, ++states) {
    valid_fill += fill.isStateValid({x, 0.0, 1.0});
    valid_occupied += occupied.isStateValid({x, 0.0, 1.0});
  }
  EXPECT_GT(valid_fill, states * 9 / 10);
  EXPECT_LT(valid_occupied, states * 3 / 10);
  // The large unknown regions (the rooms behind the doors, outside the walls) stay obstacles.
  EXPECT_FALSE(fill.isStateValid({5.0, 4.0, 1.0}));
  EXPECT_LT(fill.index()->unknownSummary().assumed_free_volume_m3,
            0.01 * fill.index()->unknownSummary().unknown_volume_m3);
}

TEST(Geb079, UnderTheOccupiedPolicyAValidPlaceExists) {
  const Environment occupied(indexed(UnknownPolicy::Occupied), testing::quad());
  EXPECT_TRUE(occupied.isStateValid({22.5, 0.0, 1.0}));
  EXPECT_TRUE(occupied.isStateValid({5.0, 0.0, 2.4}));  // close under the ceiling
  EXPECT_NEAR(occupied.ceiling({5.0, 0.0, 2.4}).nearest_gap_m, 0.21, 1e-9);
}

TEST(Geb079, OnlyTheCorridorHasAScannedCeiling) {
  // The rays into the rooms saw floors and walls but no ceiling: a fifth of the floor is under one.
  const double share = computeStatistics(geb079(), *indexed(UnknownPolicy::Occupied)).ceiling_area_share;
  EXPECT_GT(share, 0.1);
  EXPECT_LT(share, 0.3);
}

TEST(Geb079, ProbeSucceedsInTheCorridorUnderEitherPolicy) {
  const auto fill =
      testing::runCeilplan("probe --map " + kGeb079 + " --at 9,0,1 --vehicle " + kVehicle + " --unknown fill");
  ASSERT_EQ(fill.exit_code, 0) << fill.err;
  EXPECT_NE(fill.out.find("valid: true"), std::string::npos) << fill.out;
  EXPECT_NE(fill.out.find("assumed_free: true"), std::string::npos) << fill.out;
  const auto occupied = testing::runCeilplan("probe --map " + kGeb079 + " --at 22.5,0,1 --vehicle " + kVehicle);
  ASSERT_EQ(occupied.exit_code, 0) << occupied.err;
  EXPECT_NE(occupied.out.find("valid: true"), std::string::npos) << occupied.out;
  EXPECT_NE(occupied.out.find("unknown: occupied"), std::string::npos) << occupied.out;
}

TEST(Geb079, TheDocsProbeExampleRunsAsShown) {
  // docs/environment.md shows a probe of geb079: run its command, and find each line it shows.
  std::istringstream docs(testing::readWholeFile(CEILPLAN_SOURCE_DIR "/docs/environment.md"));
  std::string line, command;
  std::vector<std::string> shown;
  while (std::getline(docs, line)) {
    if (command.empty()) {
      if (line.rfind("$ ceilplan probe --map /usr/share/doc/liboctomap-dev/examples/data/geb079.bt", 0) == 0)
        command = line.substr(std::string("$ ceilplan ").size());
      continue;
    }
    if (line.rfind("```", 0) == 0) break;
    if (line != "...") shown.push_back(line);
  }
  ASSERT_FALSE(command.empty()) << "no geb079 probe example in docs/environment.md";
  ASSERT_GE(shown.size(), 3u);
  const std::string vehicle = "maps/vehicles/quad.yaml";
  command.replace(command.find(vehicle), vehicle.size(), kVehicle);
  const auto result = testing::runCeilplan(command);
  ASSERT_EQ(result.exit_code, 0) << command << "\n" << result.err;
  EXPECT_NE(result.out.find("valid: true"), std::string::npos) << result.out;
  for (const std::string& expected : shown) EXPECT_NE(result.out.find(expected), std::string::npos) << expected;
}

}  // namespace
}  // namespace ceilplan::environment
