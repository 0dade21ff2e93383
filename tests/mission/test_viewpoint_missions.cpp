// Every target of every shipped mission gets a viewpoint in both modes on its map: valid, in
// its own standoff range, seeing the target, and the vehicle's home is a valid state.

#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/mission/viewpoint.hpp"

#include <gtest/gtest.h>

namespace ceilplan::mission {
namespace {

class ShippedMission : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedMission, EveryTargetHasAViewpointInBothModes) {
  const Mission mission = io::readMission(std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps" / (GetParam() + ".yaml"));
  const environment::OccupancyMap map = environment::OccupancyMap::load(mission.map_file);
  const environment::Environment environment(map, mission.vehicle.geometry);
  const energy::EnergyModel model(mission.vehicle.energy);
  EXPECT_TRUE(environment.isStateValid(mission.home_m));
  ViewpointOptions free_mode;
  free_mode.mode = FlightMode::Free;
  for (const InspectionTarget& target : mission.targets)
    for (const ViewpointOptions& options : {ViewpointOptions{}, free_mode}) {
      const Viewpoint viewpoint = chooseViewpoint(target, environment, model, options);
      EXPECT_TRUE(environment.isStateValid(viewpoint.position_m)) << target.name;
      EXPECT_GE(viewpoint.distance_m, target.standoff_min_m) << target.name;
      EXPECT_LE(viewpoint.distance_m, target.standoff_max_m) << target.name;
      EXPECT_GT(viewpoint.dwell_current_a, 0.0) << target.name;
    }
}

INSTANTIATE_TEST_SUITE_P(Maps, ShippedMission, ::testing::Values("bridge", "tunnel", "warehouse", "open"));

}  // namespace
}  // namespace ceilplan::mission
