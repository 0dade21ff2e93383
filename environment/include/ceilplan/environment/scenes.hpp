#pragma once
/// @file
/// The shipped inspection scenes, built as voxel grids a sensor could have left: structure
/// occupied, the space a scan from below would see free, everything else unknown.

#include "ceilplan/core/error.hpp"
#include "ceilplan/environment/voxel_grid.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace ceilplan::environment {

/// The shipped inspection scenes (`ceilplan mapgen`): a bridge, a tunnel, a warehouse, open ground.
enum class Scene {
  Bridge,     ///< a road bridge from below: deck, girders, cross-frames, piers (48 m by default)
  Tunnel,     ///< a 40 m road tunnel with an arched crown
  Warehouse,  ///< a hall with roof trusses, columns and racks
  Open        ///< the bridge's extent with only the ground and boulders: no ceiling
};

/// "bridge", "tunnel", "warehouse", "open"; throws ceilplan::InputError for any other name.
Scene sceneFromName(const std::string& name);
/// The scenes' names, in Scene's order.
const std::vector<std::string>& sceneNames();

/// The shipped bridge spans 48 m between its abutments.
constexpr double kShippedBridgeLength_m = 48.0;

/// How generateScene builds a scene.
struct SceneOptions {
  double resolution_m = 0.1;                        ///< in [0.02, 1] m
  std::uint64_t seed = 1;                           ///< places the clutter (boulders, lamps, pallets)
  double bridge_length_m = kShippedBridgeLength_m;  ///< bridge only: a multiple of 4 m in [16, 2000]
};

/// Deterministic for given options. Geometry lies on multiples of 0.1 m, so at 0.1 m and finer
/// every surface is a voxel face. Throws ceilplan::InputError for an option out of range, or a
/// bridge length given for another scene.
VoxelGrid generateScene(Scene scene, const SceneOptions& options);
/// The same with default options but `resolution_m` and `seed`.
VoxelGrid generateScene(Scene scene, double resolution_m, std::uint64_t seed);

}  // namespace ceilplan::environment
