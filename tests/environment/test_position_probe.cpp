// One body position probed (environment::probePosition) and a map summarised in one call
// (computeStatistics(map)), on an analytic room with exact answers.

#include "analytic_maps.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/environment/map_statistics.hpp"
#include "ceilplan/environment/position_probe.hpp"

#include <gtest/gtest.h>

namespace ceilplan::environment {
namespace {

using testing::CellState;
using testing::quad;
using testing::room;

TEST(PositionProbe, GivesTheGapsClearanceAndValidityOfOnePosition) {
  const OccupancyMap map = room([](double, double) { return 3.0; });
  const Environment environment(map, quad());
  const PositionProbe probe = probePosition(environment, {0.0, 0.0, 2.7});
  EXPECT_EQ(probe.body_m, Eigen::Vector3d(0.0, 0.0, 2.7));
  ASSERT_EQ(probe.ceiling.rotors.size(), 4u);
  EXPECT_NEAR(probe.ceiling.nearest_gap_m, 3.0 - 2.73, 1e-6);  // rotor plane 3 cm above the body centre
  EXPECT_NEAR(probe.ground.nearest_gap_m, 2.73 - 0.2, 1e-6);
  EXPECT_EQ(probe.clearance_m, environment.clearance_m({0.0, 0.0, 2.7}));
  EXPECT_EQ(probe.violation.has_value(), !environment.isStateValid({0.0, 0.0, 2.7}));

  const PositionProbe in_the_slab = probePosition(environment, {0.0, 0.0, 3.1});
  ASSERT_TRUE(in_the_slab.violation);
  EXPECT_EQ(in_the_slab.violation->kind, ViolationKind::Occupied);
  EXPECT_THROW(probePosition(environment, {100.0, 0.0, 2.0}), InputError);
}

TEST(MapStatistics, IndexingTheMapItselfGivesTheSameSummary) {
  // A ceiling over the half x < 0 only.
  const OccupancyMap map = testing::analyticMap({-2, -2, 0}, {2, 2, 4}, 0.1, [](const Eigen::Vector3d& c) {
    if (c.z() < 0.2 || (c.x() < 0 && c.z() >= 3.0 && c.z() < 3.4)) return CellState::Occupied;
    return c.x() < 0 && c.z() >= 3.4 ? CellState::Unknown : CellState::Free;
  });
  const VoxelGrid grid = VoxelGrid::fromTree(map.tree());
  const MapStatistics expected = computeStatistics(map, grid, ColumnIndex(grid), 1.5);
  const MapStatistics stats = computeStatistics(map, 1.5);
  EXPECT_EQ(stats.occupied_leaves, expected.occupied_leaves);
  EXPECT_EQ(stats.free_volume_m3, expected.free_volume_m3);
  EXPECT_EQ(stats.ceiling_area_share, expected.ceiling_area_share);
  EXPECT_NEAR(stats.ceiling_area_share, 0.5, 1e-12);
}

}  // namespace
}  // namespace ceilplan::environment
