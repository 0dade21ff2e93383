// libFuzzer target: any bytes given to the map loader give a map or a ceilplan::InputError,
// never a crash, a hang or a leak. Build and run: scripts/fuzz-map-loader (docs/environment.md).

#include "ceilplan/core/error.hpp"
#include "ceilplan/environment/occupancy_map.hpp"
#include "ceilplan/environment/voxel_grid.hpp"

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const auto map = ceilplan::environment::OccupancyMap::read(in, "fuzz input");
    // Index small maps too: the grid must refuse or hold whatever the loader accepts.
    if (map.tree().size() < 4096) {
      try {
        ceilplan::environment::VoxelGrid::fromTree(map.tree());
      } catch (const ceilplan::InputError&) {
      }
    }
  } catch (const ceilplan::InputError&) {
  }
  return 0;
}
