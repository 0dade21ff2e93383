#pragma once
/// @file
/// The surface elements of one region: the exposed voxel faces (environment/surface_elements.hpp)
/// inside its shape whose normal faces one of its face kinds.

#include "ceilplan/core/error.hpp"
#include "ceilplan/environment/surface_elements.hpp"
#include "ceilplan/environment/voxel_grid.hpp"
#include "ceilplan/mission/coverage_region.hpp"

#include <vector>

namespace ceilplan::mission {

/// A region's surface as the voxel faces of its structure (regionSurface).
struct RegionSurface {
  std::vector<environment::SurfaceElement> elements;  ///< the exposed faces, in surfaceElements' order
  double area_m2 = 0.0;                               ///< sum of the elements' areas
};

/// Throws ceilplan::InputError naming `what` (e.g. "surface region 'soffit'") when the shape
/// holds no such element: a region with no surface in it is a mistake in the mission, not
/// something to cover trivially.
RegionSurface extractRegionSurface(const environment::VoxelGrid& grid, const RegionShape& shape, const FaceSet& faces,
                                   const std::string& what);

}  // namespace ceilplan::mission
