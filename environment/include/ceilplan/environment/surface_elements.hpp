#pragma once
/// @file
/// The inspectable surface of a map: every face of an occupied voxel whose neighbour across the
/// face is known free space. Unknown space is never inspectable, so a face onto unknown space is
/// no surface element. Each element carries the normal of the local surface (not only of its
/// voxel face: a wall at 30 degrees to the grid axes is a staircase of faces) and its share of
/// that surface's area. docs/coverage.md, "Surface elements".

#include "ceilplan/environment/voxel_grid.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace ceilplan::environment {

/// One exposed voxel face of a structure: a patch of surface to inspect.
struct SurfaceElement {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();  ///< centre of the voxel face
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   ///< unit, out of the structure into free space
  double area_m2 = 0.0;  ///< r^2 |normal . faceNormal()|: the face's share of the local surface
  Index3 voxel{};        ///< the occupied voxel
  int face = 0;          ///< which of its faces: 0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z

  /// The face's own axis normal, e.g. (0, 0, -1) for face 5 (the underside of a voxel).
  Eigen::Vector3d faceNormal() const;
};

/// Every exposed face whose centre lies in `box_m` (faces on its boundary included), ordered by
/// voxel (z, then y, then x) and face. Each takes its face's axis normal, unless the exposed faces
/// around it (within 2 voxels, facing its half-space) are a staircase: their centres all lie within
/// about a third of a voxel (RMS) of one inclined plane. Then the normal is the normalised sum of
/// those faces' axis normals, which is that plane's normal. Flat surfaces and the edges and corners
/// of boxes (an L of faces, far from any single plane) keep exact axis normals.
std::vector<SurfaceElement> exposedSurface(const VoxelGrid& grid, const Eigen::AlignedBox3d& box_m);

/// The axis normal of face `face` (0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z).
Eigen::Vector3d faceAxisNormal(int face);

}  // namespace ceilplan::environment
