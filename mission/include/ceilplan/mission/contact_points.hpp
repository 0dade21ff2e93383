#pragma once
/// @file
/// Contact grids as tour targets: points on the surface at the grid's spacing, each an
/// InspectionTarget the tour's viewpoint search (chooseViewpoint) places a hugging pose at, so
/// the ceiling effect pays during every reading. docs/coverage.md, "Contact grids".

#include "ceilplan/core/error.hpp"
#include "ceilplan/environment/voxel_grid.hpp"
#include "ceilplan/mission/coverage_region.hpp"
#include "ceilplan/mission/region_surface.hpp"
#include "ceilplan/mission/viewpoint.hpp"

#include <vector>

namespace ceilplan::mission {

/// The grid's points: for each face direction of its surface, a lattice at spacing_m in the
/// surface's plane, centred on the surface's extent, each node moved to the nearest element
/// centre within half a spacing (in the plane), or dropped if none. Targets are named
/// "<grid>_<k>" (k from 1, in lattice order), with standoff [0, reach_m] and the grid's dwell.
/// Throws ceilplan::InputError for a bad grid or one with no surface in it.
std::vector<InspectionTarget> contactTargets(const environment::VoxelGrid& grid, const ContactGrid& contact);

/// Same, from its surface already extracted.
std::vector<InspectionTarget> contactTargets(const ContactGrid& contact, const RegionSurface& surface);

}  // namespace ceilplan::mission
