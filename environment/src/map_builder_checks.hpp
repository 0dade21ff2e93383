#pragma once
// Checks and box arithmetic shared by the map builders (private to the environment module).

#include "ceilplan/environment/map_builder.hpp"
#include "ceilplan/environment/voxel_grid.hpp"

#include <octomap/OcTree.h>

#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace ceilplan::environment::detail {

// Throws ceilplan::InputError unless the resolution lies in the accepted range.
void checkImportResolution(double resolution_m);

// Throws ceilplan::InputError naming the first non-finite point; `what` is "point" or "vertex".
void requireFinitePoints(const std::vector<Eigen::Vector3d>& points_m, const char* what);

// The grid of voxels covering `data_m` grown by `margin_m` and limited to `crop_m` (croppedBox,
// `what` naming the data), refused (ceilplan::InputError) before anything is allocated if
// OctoMap's 16-bit key space or ceilplan's voxel limit cannot hold it.
GridFrame importFrame(const Eigen::AlignedBox3d& data_m, double margin_m, double resolution_m,
                      const CropBox& crop_m = CropBox(), const char* what = "data");

// `box_m` limited to `crop_m` (an empty crop keeps it whole). Throws ceilplan::InputError when
// nothing of `what` ("return", "point", "triangle") lies in the crop.
Eigen::AlignedBox3d croppedBox(const Eigen::AlignedBox3d& box_m, const CropBox& crop_m, const char* what);

// " (cropped to BOX)" when `crop_m` is not empty, for the free-space lines.
std::string cropText(const CropBox& crop_m);

// Appends the occupied and free volume of the built tree's leaves (occupied_m3, free_m3).
void addVolumeFigures(BuiltMap& built);

}  // namespace ceilplan::environment::detail
