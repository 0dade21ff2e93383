// One body position probed (environment::probePosition) on an analytic room with exact answers.

#include "analytic_maps.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/environment/position_probe.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ceilplan::environment {
namespace {

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

  EXPECT_FALSE(probe.assumes_free);  // the occupied policy assumes nothing
  EXPECT_FALSE(probe.point_assumed_free);

  const PositionProbe in_the_slab = probePosition(environment, {0.0, 0.0, 3.1});
  ASSERT_TRUE(in_the_slab.violation);
  EXPECT_EQ(in_the_slab.violation->kind, ViolationKind::Occupied);
  EXPECT_THROW(probePosition(environment, {100.0, 0.0, 2.0}), InputError);
}

TEST(PositionProbe, SaysWhenItReliesOnUnknownSpaceAssumedFree) {
  // The room with an unscanned pocket in mid-air, assumed free by the free policy.
  const OccupancyMap map = testing::analyticMap({-2, -2, 0}, {2, 2, 3.4}, 0.1, [](const Eigen::Vector3d& c) {
    if (c.z() < 0.2 || c.z() > 3.0) return testing::CellState::Occupied;
    const bool pocket = c.x() > 1.0 && c.x() < 1.6 && std::abs(c.y()) < 0.3 && c.z() > 1.0 && c.z() < 1.6;
    return pocket ? testing::CellState::Unknown : testing::CellState::Free;
  });
  MapIndexOptions free_policy;
  free_policy.unknown.policy = UnknownPolicy::Free;
  const Environment environment(map, quad(), EnvironmentOptions{}, free_policy);
  const PositionProbe inside = probePosition(environment, {1.3, 0.0, 1.3});
  EXPECT_TRUE(inside.point_assumed_free);
  EXPECT_TRUE(inside.assumes_free);
  const PositionProbe beside = probePosition(environment, {0.7, 0.0, 1.3});  // the pocket within its clearance
  EXPECT_FALSE(beside.point_assumed_free);
  EXPECT_TRUE(beside.assumes_free);
  const PositionProbe away = probePosition(environment, {-1.0, 0.0, 1.5});
  EXPECT_FALSE(away.point_assumed_free);
  EXPECT_FALSE(away.assumes_free);
}

}  // namespace
}  // namespace ceilplan::environment
