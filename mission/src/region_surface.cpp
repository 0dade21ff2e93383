#include "ceilplan/mission/region_surface.hpp"

#include "ceilplan/core/format.hpp"

namespace ceilplan::mission {

RegionSurface extractRegionSurface(const environment::VoxelGrid& grid, const RegionShape& shape, const FaceSet& faces,
                                   const std::string& what) {
  RegionSurface surface;
  for (environment::SurfaceElement& element : environment::exposedSurface(grid, shape.bounds())) {
    if (!shape.contains(element.centre_m) || !faces.has(faceKindOf(element.normal))) continue;
    surface.area_m2 += element.area_m2;
    surface.elements.push_back(element);
  }
  if (surface.elements.empty())
    throw ceilplan::InputError(what + ": no occupied voxel face facing " + faces.describe() +
                               " onto known free space inside its " +
                               (shape.kind == RegionShape::Kind::Box
                                    ? "'box' " + formatPoint(shape.box.min()) + " to " + formatPoint(shape.box.max())
                                    : std::string("'prism'")) +
                               ": check it against the map (ceilplan mapinfo, probe) and its 'faces'");
  return surface;
}

}  // namespace ceilplan::mission
