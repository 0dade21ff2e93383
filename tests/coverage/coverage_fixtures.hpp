#pragma once
// Scenes, cameras and regions shared by the coverage tests: the shipped bridge with the default
// vehicle and the paper's energy model, in ceiling mode (proximity effects on) and free mode
// (proximity effects off, as a conventional planner prices hover).

#include "analytic_maps.hpp"

#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/energy/paper_quad.hpp"
#include "ceilplan/environment/environment.hpp"
#include "ceilplan/environment/occupancy_map.hpp"
#include "ceilplan/mission/camera.hpp"
#include "ceilplan/mission/coverage_region.hpp"
#include "ceilplan/planner/flight_cost_model.hpp"

#include <filesystem>
#include <memory>

namespace ceilplan::testing {

inline std::filesystem::path shippedFile(const std::string& name) {
  return std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps" / name;
}

// A map indexed for the default vehicle, with the paper's energy model and both modes' cost models.
struct CoverageScene {
  explicit CoverageScene(environment::OccupancyMap scene_map) : map(std::move(scene_map)) {}
  environment::OccupancyMap map;
  environment::Environment environment{map, quad()};
  energy::EnergyModel energy{energy::paperQuadParameters()};
  planner::FlightCostModel ceiling_model{environment, energy, planner::CostModelOptions{}};
  planner::FlightCostModel free_model{environment, energy, [] {
                                        planner::CostModelOptions options;
                                        options.proximity_effects = false;
                                        return options;
                                      }()};
};

// The shipped bridge (maps/bridge.bt), indexed once per test program.
inline const CoverageScene& bridgeScene() {
  static const CoverageScene scene(environment::OccupancyMap::load(shippedFile("bridge.bt")));
  return scene;
}

// 4 x 4 m, floor top at 0.2 m, ceiling underside at 3.0 m (unknown above); a beam across it at
// x in [0, 0.3) down to 2.4 m; a closet in the corner x, y in [1.0, 2.0) with 0.1 m walls from
// floor to ceiling, 0.9 m wide inside: too narrow for the 0.92 m inflated airframe.
inline environment::OccupancyMap roomWithBeamAndCloset() {
  using environment::CellState;
  return analyticMap({-2, -2, 0}, {2, 2, 3.4}, 0.1, [](const Eigen::Vector3d& c) {
    if (c.z() < 0.2 || c.z() >= 3.0) return CellState::Occupied;
    if (c.x() >= 0.0 && c.x() < 0.3 && c.z() >= 2.4) return CellState::Occupied;
    const bool in_closet_box = c.x() >= 1.0 && c.y() >= 1.0;
    if (in_closet_box && (c.x() < 1.1 || c.y() < 1.1)) return CellState::Occupied;
    return CellState::Free;
  });
}

inline const CoverageScene& roomScene() {
  static const CoverageScene scene(roomWithBeamAndCloset());
  return scene;
}

// The H20 wide camera on an upward gimbal (its published tilt range flipped), a little above the
// body centre, shooting from the hover.
inline mission::Camera upwardCamera() {
  mission::Camera camera = mission::cameraPreset("zenmuse_h20_wide").camera;
  camera.gimbal_pitch_min_deg = -30.0;
  camera.gimbal_pitch_max_deg = 90.0;
  camera.mount_offset_m = Eigen::Vector3d(0.0, 0.0, 0.05);
  return camera;
}

// The deck's underside between the girders of the shipped bridge: three bays 2.4 m wide.
inline mission::CoverageRegion bridgeSoffit(double gsd_mm_px = 1.0) {
  mission::CoverageRegion region;
  region.name = "soffit_between_girders";
  region.shape = mission::RegionShape::makeBox({0.0, -4.0, 5.95}, {48.0, 4.0, 6.05});
  region.faces.down = true;
  region.gsd_mm_px = gsd_mm_px;
  region.overlap_front_pct = 70.0;
  region.overlap_side_pct = 60.0;
  region.max_incidence_deg = 45.0;
  return region;
}

}  // namespace ceilplan::testing
