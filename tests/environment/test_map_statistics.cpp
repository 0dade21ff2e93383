// mapinfo's summary: the share of the floor under a ceiling counts ceilings, not furniture.

#include "analytic_maps.hpp"

#include "ceilplan/environment/map_index.hpp"
#include "ceilplan/environment/map_statistics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace ceilplan::environment {
namespace {

using testing::analyticMap;

bool inBox(const Eigen::Vector3d& c, double x0, double x1, double y0, double y1, double z0, double z1) {
  return c.x() >= x0 && c.x() < x1 && c.y() >= y0 && c.y() < y1 && c.z() >= z0 && c.z() < z1;
}

// An 8 x 6 m office scanned from inside: floor, walls to 2.6 m, a cluster of four desks pushed
// together (3.2 x 1.6 m, tops at 0.75 m), a shelf at 1.8 m, a lamp; free air up to 3.0 m,
// unknown above. With `ceiling`, a slab closes the room at 2.6 m.
OccupancyMap office(bool ceiling) {
  return analyticMap({-4.2, -3.2, 0}, {4.2, 3.2, 3.4}, 0.1, [ceiling](const Eigen::Vector3d& c) {
    if (c.z() < 0.2) return CellState::Occupied;                                                      // floor
    if ((std::abs(c.x()) > 4.0 || std::abs(c.y()) > 3.0) && c.z() < 2.6) return CellState::Occupied;  // walls
    if (ceiling && c.z() >= 2.6) return c.z() < 2.8 ? CellState::Occupied : CellState::Unknown;
    if (c.z() >= 3.0) return CellState::Unknown;
    if (inBox(c, -1.6, 1.6, -0.8, 0.8, 0.7, 0.8)) return CellState::Occupied;  // desk tops
    if (inBox(c, -3.9, -1.9, 2.5, 2.9, 1.8, 1.9)) return CellState::Occupied;  // shelf
    if (inBox(c, 2.0, 2.4, -0.2, 0.2, 2.3, 2.4)) return CellState::Occupied;   // lamp
    return CellState::Free;
  });
}

double ceilingShare(const OccupancyMap& map) { return computeStatistics(map, MapIndex(map)).ceiling_area_share; }

TEST(CeilingShare, ARoomWithDesksAndShelvesButNoCeilingHasNone) { EXPECT_LT(ceilingShare(office(false)), 0.005); }

TEST(CeilingShare, TheSameRoomWithACeilingIsAllUnderIt) { EXPECT_GT(ceilingShare(office(true)), 0.99); }

TEST(CeilingShare, HeadroomAndAreaAreTheCriteria) {
  const OccupancyMap map = office(false);
  const MapIndex index(map);
  // The floor: all 84 x 64 columns hold free space (the walls' above 2.6 m).
  const std::vector<std::uint8_t> columns = ceilingColumns(index);
  ASSERT_EQ(columns.size(), 84u * 64u);
  EXPECT_EQ(std::count(columns.begin(), columns.end(), 0), 0);
  // With half a metre of headroom enough, the desks (32 x 16 columns, 5.1 m2) count.
  CeilingCriteria low;
  low.min_headroom_m = 0.5;
  EXPECT_NEAR(computeStatistics(map, index, low).ceiling_area_share, 32.0 * 16 / (84 * 64), 1e-12);
  // With tiny patches enough, the shelf (20 x 4) and the lamp (4 x 4) count.
  CeilingCriteria small;
  small.min_area_m2 = 0.1;
  EXPECT_NEAR(computeStatistics(map, index, small).ceiling_area_share, (20.0 * 4 + 4 * 4) / (84 * 64), 1e-12);
}

TEST(CeilingShare, TheShippedScenesKeepSensibleShares) {
  const auto share = [](const std::string& name) {
    return ceilingShare(OccupancyMap::load(CEILPLAN_SOURCE_DIR "/maps/" + name + ".bt"));
  };
  EXPECT_NEAR(share("bridge"), 0.457, 0.05);  // the deck and the pier caps over 60 x 20 m
  EXPECT_NEAR(share("tunnel"), 0.625, 0.05);  // the bore, not the approaches
  EXPECT_GT(share("warehouse"), 0.99);        // the roof
  EXPECT_LT(share("open"), 0.001);            // nothing overhead
}

}  // namespace
}  // namespace ceilplan::environment
