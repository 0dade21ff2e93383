#include "ceilplan/environment/scenes.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <cmath>
#include <random>
#include <stdexcept>

namespace ceilplan::environment {
namespace {

using Eigen::Vector3d;
constexpr auto kOccupied = CellState::Occupied;
constexpr auto kFree = CellState::Free;
constexpr auto kUnknown = CellState::Unknown;

// Uniform doubles from the standard 64-bit Mersenne twister, bit for bit the same everywhere
// (std::uniform_real_distribution is not specified exactly).
class SceneRandom {
 public:
  explicit SceneRandom(std::uint64_t seed) : engine_(seed) {}
  double uniform(double lo, double hi) { return lo + (hi - lo) * (static_cast<double>(engine_() >> 11) * 0x1.0p-53); }
  // A multiple of 0.1 m in [lo, hi], so clutter stays on voxel faces.
  double decimetres(double lo, double hi) { return std::round(uniform(lo, hi) * 10.0) / 10.0; }

 private:
  std::mt19937_64 engine_;
};

VoxelGrid emptyGrid(double resolution_m, const Vector3d& min_m, const Vector3d& max_m) {
  Index3 origin, size;
  for (int axis = 0; axis < 3; ++axis) {
    origin[axis] = static_cast<int>(std::floor(min_m[axis] / resolution_m + 1e-9));
    size[axis] = static_cast<int>(std::ceil(max_m[axis] / resolution_m - 1e-9)) - origin[axis];
  }
  return VoxelGrid(GridFrame(resolution_m, origin, size));
}

void box(VoxelGrid& grid, double x0, double x1, double y0, double y1, double z0, double z1, CellState state) {
  grid.fillBox(Vector3d(x0, y0, z0), Vector3d(x1, y1, z1), state);
}

// `count` boulders on open ground, away from the home area (x < 2), x up to `x_max`.
void boulders(VoxelGrid& grid, SceneRandom& random, int count = 8, double x_max = 46.0) {
  for (int b = 0; b < count; ++b) {
    const double x = random.decimetres(3.0, x_max), y = random.decimetres(-9.0, 9.0);
    const double half = random.decimetres(0.2, 0.4), height = random.decimetres(0.3, 0.8);
    box(grid, x - half, x + half, y - half, y + half, 0.0, height, kOccupied);
  }
}

// A road bridge seen from below, spanning `length` metres between its abutments (48 m shipped):
// deck underside at 6 m, four steel girders (inner 0.8 m, outer 1.0 m deep), cross-frames every
// 4 m, piers with caps and bearings every 16 m (none closer than 16 m to the far abutment),
// abutments, and 8 boulders per 48 m.
VoxelGrid bridge(double resolution_m, SceneRandom& random, double length) {
  const double end = length + 6;
  VoxelGrid grid = emptyGrid(resolution_m, Vector3d(-6, -10, -0.4), Vector3d(end, 10, 7.0));
  box(grid, -6, end, -10, 10, 0.0, 7.0, kFree);               // what the scan from below saw
  box(grid, -2, length + 2, -5.5, 5.5, 6.3, 7.0, kUnknown);   // above the deck: hidden from below
  box(grid, -6, end, -10, 10, -0.4, 0.0, kOccupied);          // ground
  box(grid, -2, length + 2, -5.5, 5.5, 6.0, 6.3, kOccupied);  // deck slab
  for (const double x : {-2.0, length}) box(grid, x, x + 2, -5.5, 5.5, 0.0, 6.0, kOccupied);  // abutments
  const double girders[4] = {-4.2, -1.4, 1.4, 4.2};
  for (const double y : girders) {
    const double depth = std::abs(y) > 3 ? 1.0 : 0.8;
    box(grid, 0, length, y - 0.2, y + 0.2, 6.0 - depth, 6.0, kOccupied);
  }
  const auto pier = [length](int x) { return x % 16 == 0 && x <= length - 16; };
  for (int x = 4; x <= length - 4; x += 4) {
    if (pier(x)) continue;  // the pier caps stand there
    for (int g = 0; g < 3; ++g)
      box(grid, x - 0.1, x + 0.1, girders[g] + 0.2, girders[g + 1] - 0.2, 5.4, 6.0, kOccupied);
  }
  for (int x = 16; pier(x); x += 16) {
    box(grid, x - 0.6, x + 0.6, -5.0, 5.0, 4.2, 5.0, kOccupied);                                            // pier cap
    for (const double y : {-1.4, 1.4}) box(grid, x - 0.2, x + 0.2, y - 0.2, y + 0.2, 5.0, 5.2, kOccupied);  // bearings
    for (const double y : {-2.5, 2.5}) box(grid, x - 0.5, x + 0.5, y - 0.5, y + 0.5, 0.0, 4.2, kOccupied);  // columns
  }
  boulders(grid, random, static_cast<int>(std::lround(8 * length / kShippedBridgeLength_m)), length - 2);
  return grid;
}

// The bridge's extent with nothing overhead: the control case.
VoxelGrid open(double resolution_m, SceneRandom& random) {
  VoxelGrid grid = emptyGrid(resolution_m, Vector3d(-6, -10, -0.4), Vector3d(54, 10, 7.0));
  box(grid, -6, 54, -10, 10, 0.0, 7.0, kFree);
  box(grid, -6, 54, -10, 10, -0.4, 0.0, kOccupied);
  boulders(grid, random);
  return grid;
}

// A 40 m road tunnel: 8 m wide, vertical walls to 3 m, a semicircular arch (crown at 7 m),
// 0.4 m lining, headwalls at both portals, a cable tray and lamps.
VoxelGrid tunnel(double resolution_m, SceneRandom& random) {
  VoxelGrid grid = emptyGrid(resolution_m, Vector3d(-6, -8, -0.4), Vector3d(46, 8, 8.0));
  const GridFrame& frame = grid.frame();
  box(grid, -6, 46, -8, 8, 0.0, 7.6, kFree);    // the approaches, seen from the road
  box(grid, 0, 40, -8, 8, 0.0, 8.0, kUnknown);  // rock around the bore, unseen
  const auto bore = [](double y, double z) {
    return z >= 0 && (z < 3 ? std::abs(y) < 4 : y * y + (z - 3) * (z - 3) < 16);
  };
  const auto lining = [](double y, double z) {
    return z >= 0 && (z < 3 ? std::abs(y) < 4.4 : y * y + (z - 3) * (z - 3) < 4.4 * 4.4);
  };
  for (int k = 0; k < frame.size()[2]; ++k)
    for (int j = 0; j < frame.size()[1]; ++j)
      for (int i = 0; i < frame.size()[0]; ++i) {
        const double x = frame.centreOf(0, i), y = frame.centreOf(1, j), z = frame.centreOf(2, k);
        if (x < 0 || x >= 40) continue;
        const bool headwall = x < 0.4 || x >= 39.6;
        if (bore(y, z)) {
          grid.set(i, j, k, kFree);
        } else if (lining(y, z) || (headwall && z < 7.6)) {
          grid.set(i, j, k, kOccupied);
        }
      }
  box(grid, -6, 46, -8, 8, -0.4, 0.0, kOccupied);         // road and ground
  box(grid, 0.4, 39.6, -4.0, -3.7, 2.4, 2.5, kOccupied);  // cable tray on the left wall
  for (double x = random.decimetres(2, 4); x < 38; x += random.decimetres(5, 7))
    box(grid, x, x + 0.6, -1.5, -0.9, 6.4, 6.9, kOccupied);  // lamps beside the crown
  return grid;
}

// A 40 x 24 m hall: flat roof underside at 8 m, roof trusses every 5 m (bottom chord at
// 6.8 m), columns, three rows of pallet racks with shelves at 1.5, 3.0 and 4.5 m.
VoxelGrid warehouse(double resolution_m, SceneRandom& random) {
  VoxelGrid grid = emptyGrid(resolution_m, Vector3d(-0.4, -0.4, -0.4), Vector3d(40.4, 24.4, 8.4));
  box(grid, -0.4, 40.4, -0.4, 24.4, -0.4, 8.4, kOccupied);  // walls, floor and roof
  box(grid, 0, 40, 0, 24, 0, 8.0, kFree);
  for (int x = 5; x <= 35; x += 5) {
    box(grid, x - 0.1, x + 0.1, 0, 24, 7.8, 8.0, kOccupied);  // top chord
    box(grid, x - 0.1, x + 0.1, 0, 24, 6.8, 7.0, kOccupied);  // bottom chord
    for (int y = 2; y <= 22; y += 2) box(grid, x - 0.1, x + 0.1, y - 0.1, y + 0.1, 7.0, 7.8, kOccupied);
  }
  for (const double x : {10.0, 20.0, 30.0})
    for (const double y : {8.0, 16.0}) box(grid, x - 0.2, x + 0.2, y - 0.2, y + 0.2, 0, 6.8, kOccupied);
  for (const double y0 : {3.5, 11.4, 19.3}) {
    const double y1 = y0 + 1.2;
    for (double x = 3.0; x <= 37.0 + 1e-9; x += 2.7) {
      for (const double y : {y0, y1 - 0.1}) box(grid, x, x + 0.1, y, y + 0.1, 0, 4.6, kOccupied);  // uprights
      if (x + 2.7 > 37.0 + 1e-9) break;
      for (const double shelf : {0.0, 1.5, 3.0}) {  // pallets on the floor and the lower shelves
        if (random.uniform(0, 1) < 0.4) continue;
        const double base = shelf == 0.0 ? 0.0 : shelf + 0.1;
        box(grid, x + 0.3, x + 2.4, y0 + 0.1, y1 - 0.1, base, base + random.decimetres(0.8, 1.2), kOccupied);
      }
    }
    for (const double shelf : {1.5, 3.0, 4.5}) box(grid, 3.0, 37.1, y0, y1, shelf, shelf + 0.1, kOccupied);
  }
  return grid;
}

}  // namespace

const std::vector<std::string>& sceneNames() {
  static const std::vector<std::string> names{"bridge", "tunnel", "warehouse", "open"};
  return names;
}

Scene sceneFromName(const std::string& name) {
  if (name == "bridge") return Scene::Bridge;
  if (name == "tunnel") return Scene::Tunnel;
  if (name == "warehouse") return Scene::Warehouse;
  if (name == "open") return Scene::Open;
  throw ceilplan::InputError("unknown scene '" + name + "'; choose bridge, tunnel, warehouse or open");
}

VoxelGrid generateScene(Scene scene, const SceneOptions& options) {
  const double resolution_m = options.resolution_m;
  if (!(resolution_m >= 0.02 && resolution_m <= 1.0))
    throw ceilplan::InputError("scene resolution must lie between 0.02 and 1 m, got " + formatNumber(resolution_m));
  const double length = options.bridge_length_m;
  if (!(length >= 16.0 && length <= 2000.0) || std::abs(length / 4.0 - std::round(length / 4.0)) > 1e-9)
    throw ceilplan::InputError("bridge length must be a multiple of 4 m between 16 and 2000 m, got " +
                               formatNumber(length));
  if (scene != Scene::Bridge && length != kShippedBridgeLength_m)
    throw ceilplan::InputError("a bridge length applies only to the bridge scene");
  SceneRandom random(options.seed);
  switch (scene) {
    case Scene::Bridge:
      return bridge(resolution_m, random, std::round(length));
    case Scene::Tunnel:
      return tunnel(resolution_m, random);
    case Scene::Warehouse:
      return warehouse(resolution_m, random);
    case Scene::Open:
      return open(resolution_m, random);
  }
  throw ceilplan::InputError("unknown scene");
}

VoxelGrid generateScene(Scene scene, double resolution_m, std::uint64_t seed) {
  SceneOptions options;
  options.resolution_m = resolution_m;
  options.seed = seed;
  return generateScene(scene, options);
}

}  // namespace ceilplan::environment
