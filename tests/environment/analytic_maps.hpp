#pragma once
// Small OctoMaps built voxel by voxel through OctoMap's own API, with surfaces on voxel faces,
// so tests can state exact expected gaps.

#include "ceilplan/environment/occupancy_map.hpp"
#include "ceilplan/environment/vehicle_geometry.hpp"
#include "ceilplan/environment/voxel_grid.hpp"

#include <octomap/OcTree.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

namespace ceilplan::testing {

using environment::CellState;

// Every voxel whose centre lies in [min, max) gets `classify(centre)`; the rest stay unknown.
inline environment::OccupancyMap analyticMap(const Eigen::Vector3d& min, const Eigen::Vector3d& max, double resolution,
                                             const std::function<CellState(const Eigen::Vector3d&)>& classify) {
  auto tree = std::make_unique<octomap::OcTree>(resolution);
  for (double z = min.z() + resolution / 2; z < max.z(); z += resolution)
    for (double y = min.y() + resolution / 2; y < max.y(); y += resolution)
      for (double x = min.x() + resolution / 2; x < max.x(); x += resolution) {
        const CellState state = classify(Eigen::Vector3d(x, y, z));
        if (state == CellState::Unknown) continue;
        tree->setNodeValue(
            octomap::point3d(x, y, z),
            state == CellState::Occupied ? tree->getClampingThresMaxLog() : tree->getClampingThresMinLog(), true);
      }
  tree->updateInnerOccupancy();
  tree->prune();
  return environment::OccupancyMap(std::move(tree), "analytic map");
}

// A 4 x 4 m room at 0.1 m: floor top at 0.2 m, ceiling underside given by `ceiling(x, y)`,
// ceiling 0.4 m thick, free in between; unknown above the ceiling slab.
inline environment::OccupancyMap room(const std::function<double(double x, double y)>& ceiling) {
  return analyticMap({-2, -2, 0}, {2, 2, 4}, 0.1, [&](const Eigen::Vector3d& c) {
    if (c.z() < 0.2) return CellState::Occupied;
    const double underside = ceiling(c.x(), c.y());
    if (c.z() < underside) return CellState::Free;
    if (c.z() < underside + 0.4) return CellState::Occupied;
    return CellState::Unknown;
  });
}

// True if `point` lies on a face between an occupied voxel and a free one.
inline bool onOccupiedSurface(const environment::VoxelGrid& grid, const Eigen::Vector3d& point) {
  const environment::GridFrame& frame = grid.frame();
  for (int axis = 0; axis < 3; ++axis) {
    const double steps = point[axis] / frame.resolution_m();
    if (std::abs(steps - std::round(steps)) > 1e-6) continue;  // not on a face across this axis
    for (const double side : {-0.5, 0.5}) {
      Eigen::Vector3d inner = point, outer = point;
      inner[axis] += side * frame.resolution_m();
      outer[axis] -= side * frame.resolution_m();
      const auto state = [&](const Eigen::Vector3d& p) {
        return grid.at(frame.indexOf(0, p.x()), frame.indexOf(1, p.y()), frame.indexOf(2, p.z()));
      };
      if (state(inner) == CellState::Occupied && state(outer) == CellState::Free) return true;
    }
  }
  return false;
}

// The default vehicle's geometry (maps/vehicles/quad.yaml).
inline environment::VehicleGeometry quad() {
  environment::VehicleGeometry vehicle;
  vehicle.name = "quad";
  vehicle.rotor_positions_m = environment::rotorPositions(environment::RotorLayout::X, 4, 0.225);
  vehicle.rotor_radius_m = 0.127;
  vehicle.rotor_plane_height_m = 0.03;
  vehicle.top_height_m = 0.06;
  vehicle.bottom_height_m = -0.12;
  vehicle.collision_radius_m = 0.36;
  vehicle.margin_m = 0.10;
  vehicle.top_margin_m = 0.02;
  return vehicle;
}

// The specification of the cylinder test, voxel by voxel: calls `visit(i, j, k)` for every voxel
// (rows of columns, then bottom to top) that the vehicle's inflated cylinder with its body
// centre at `p` overlaps by more than a face or a side, until `visit` returns true.
template <class Visit>
bool anyVoxelInCylinder(const environment::GridFrame& frame, const environment::VehicleGeometry& vehicle,
                        const Eigen::Vector3d& p, Visit&& visit) {
  const double r = vehicle.inflatedRadius_m(), bottom = p.z() + vehicle.inflatedBottom_m(),
               top = p.z() + vehicle.inflatedTop_m();
  for (int j = frame.indexOf(1, p.y() - r); j <= frame.indexOf(1, p.y() + r); ++j)
    for (int i = frame.indexOf(0, p.x() - r); i <= frame.indexOf(0, p.x() + r); ++i) {
      const double dx = std::max({frame.faceOf(0, i) - p.x(), 0.0, p.x() - frame.faceOf(0, i + 1)});
      const double dy = std::max({frame.faceOf(1, j) - p.y(), 0.0, p.y() - frame.faceOf(1, j + 1)});
      if (dx * dx + dy * dy >= r * r) continue;
      for (int k = frame.indexOf(2, bottom); k <= frame.indexOf(2, top); ++k) {
        if (frame.faceOf(2, k) >= top || frame.faceOf(2, k + 1) <= bottom) continue;
        if (visit(i, j, k)) return true;
      }
    }
  return false;
}

// One rotor on the body axis: for coverage tests.
inline environment::VehicleGeometry singleRotor() {
  environment::VehicleGeometry vehicle = quad();
  vehicle.rotor_positions_m = {Eigen::Vector2d(0, 0)};
  return vehicle;
}

}  // namespace ceilplan::testing
