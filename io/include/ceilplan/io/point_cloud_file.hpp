#pragma once
/// @file
/// Point-cloud files, read with Open3D (docs/import.md says why that library).

#include "ceilplan/core/error.hpp"
#include "ceilplan/environment/map_builder.hpp"

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <vector>

namespace ceilplan::io {

/// The extensions readPointCloud accepts, e.g. ".pcd, .ply, ...", for messages and help.
std::string pointCloudExtensions();

/// Every point of a .pcd (ascii, binary or binary_compressed), .ply, .xyz, .xyzn, .xyzrgb or .pts
/// file, in file order, non-finite ones included (organised clouds mark missing returns with
/// NaN; the caller decides). Throws ceilplan::InputError naming the file: missing, a mesh or
/// other wrong-kind extension, unreadable or corrupt, or no point.
std::vector<Eigen::Vector3d> readPointCloud(const std::filesystem::path& file);

/// The sensor origins of a cloud of `point_count` points (docs/import.md): a CSV with columns
/// x,y,z (one row for the whole cloud, or one per point) or first_point,x,y,z (one row per scan),
/// in the cloud's coordinates. Throws ceilplan::InputError naming the file, line and column.
environment::SensorOrigins readSensorOrigins(const std::filesystem::path& file, std::size_t point_count);

}  // namespace ceilplan::io
