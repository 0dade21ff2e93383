#pragma once
// The shipped inspection scenes, built as voxel grids a sensor could have left: structure
// occupied, the space a scan from below would see free, everything else unknown.

#include "ceilplan/environment/voxel_grid.hpp"
#include "ceilplan/core/error.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace ceilplan::environment {

enum class Scene { Bridge, Tunnel, Warehouse, Open };

// "bridge", "tunnel", "warehouse", "open"; throws ceilplan::InputError for any other name.
Scene sceneFromName(const std::string& name);
const std::vector<std::string>& sceneNames();

// Deterministic for a given (scene, resolution, seed): the seed places the scene's clutter
// (boulders, lamps, pallets). Geometry lies on multiples of 0.1 m, so at 0.1 m and finer every
// surface is a voxel face. Throws ceilplan::InputError for a resolution outside [0.02, 1] m.
VoxelGrid generateScene(Scene scene, double resolution_m, std::uint64_t seed);

}  // namespace ceilplan::environment
