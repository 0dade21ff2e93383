#pragma once
/// @file
/// Map views for the figure scripts (scripts/plot-compare, scripts/plot-tour).

#include "ceilplan/environment/environment.hpp"
#include "ceilplan/io/provenance.hpp"

#include <Eigen/Core>

#include <filesystem>
#include <vector>

namespace ceilplan::io {

/// DIR/map_top.csv (x_m,y_m,ceiling_m: seen from above, the height of the structure over the
/// route) and DIR/map_side.csv (x_m,z_m: from the side, occupied voxels within 1 m of the
/// route's y band), each after a provenance comment line. Atomic.
void writeMapViews(const std::filesystem::path& dir, const environment::Environment& environment,
                   const std::vector<Eigen::Vector3d>& route_m, const Provenance& provenance);

}  // namespace ceilplan::io
