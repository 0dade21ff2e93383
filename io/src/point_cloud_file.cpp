#include "ceilplan/io/point_cloud_file.hpp"

#include "ceilplan/core/format.hpp"
#include "ceilplan/io/csv_columns.hpp"

#include "file_kind.hpp"
#include "open3d_input_checks.hpp"
#include "open3d_log.hpp"

#include <open3d/geometry/PointCloud.h>
#include <open3d/io/PointCloudIO.h>

#include <array>
#include <cmath>

namespace ceilplan::io {
namespace {

constexpr std::array<const char*, 6> kCloudExtensions = {".pcd", ".ply", ".xyz", ".xyzn", ".xyzrgb", ".pts"};
constexpr std::array<const char*, 6> kMeshOnlyExtensions = {".stl", ".obj", ".off", ".gltf", ".glb", ".fbx"};

}  // namespace

std::string pointCloudExtensions() { return detail::joined(kCloudExtensions); }

std::vector<Eigen::Vector3d> readPointCloud(const std::filesystem::path& file) {
  const std::string name = file.string();
  const std::string extension =
      detail::requireReadableFileOfKind(file, kCloudExtensions, kMeshOnlyExtensions, "point cloud", "mesh");

  if (extension == ".pcd") detail::checkPcdFile(file);
  if (extension == ".xyz") detail::checkXyzFile(file, 3);
  if (extension == ".xyzn" || extension == ".xyzrgb") detail::checkXyzFile(file, 6);
  if (extension == ".ply") detail::checkPlyFile(file, "point cloud");

  open3d::geometry::PointCloud cloud;
  open3d::io::ReadPointCloudOption option;
  option.remove_nan_points = false;
  option.remove_infinite_points = false;
  if (const auto failure = detail::failureOf([&] { return open3d::io::ReadPointCloud(name, cloud, option); }))
    throw ceilplan::InputError(name + ": not a readable point cloud" +
                               (failure->empty() ? "" : " (Open3D: " + *failure + ")"));
  if (cloud.points_.empty()) throw ceilplan::InputError(name + ": the point cloud has no points");
  return std::move(cloud.points_);
}

environment::SensorOrigins readSensorOrigins(const std::filesystem::path& path, std::size_t point_count) {
  const std::string file = path.string();
  const CsvColumns table = CsvColumns::read(path, {}, {"x", "y", "z", "first_point"});
  for (const char* column : {"x", "y", "z"})
    if (!table.hasColumn(column))
      throw ceilplan::InputError("--origins " + file + ": no column '" + column +
                                 "' (expected x,y,z or first_point,x,y,z)");
  const std::size_t rows = table.rowCount();
  if (rows == 0) throw ceilplan::InputError("--origins " + file + ": no origin rows");
  environment::SensorOrigins origins;
  for (std::size_t row = 0; row < rows; ++row)
    origins.origin_m.emplace_back(table.column("x")[row], table.column("y")[row], table.column("z")[row]);
  if (table.hasColumn("first_point")) {
    for (std::size_t row = 0; row < rows; ++row) {
      const double first = table.column("first_point")[row];
      if (!(first >= 0.0) || first != std::floor(first))
        throw ceilplan::InputError("--origins " + file + " line " + std::to_string(table.lineOfRow(row)) +
                                   ": first_point must be a whole number >= 0, got " + formatNumber(first));
      origins.first_point.push_back(static_cast<std::size_t>(first));
    }
  } else if (rows == 1) {
    origins.first_point = {0};
  } else if (rows == point_count) {
    for (std::size_t row = 0; row < rows; ++row) origins.first_point.push_back(row);
  } else {
    throw ceilplan::InputError(
        "--origins " + file + ": " + std::to_string(rows) + " rows of x,y,z for " + std::to_string(point_count) +
        " points; give one row per point, a single row, or a first_point column for one row per scan");
  }
  try {
    origins.validate(point_count);
  } catch (const ceilplan::InputError& e) {
    throw ceilplan::InputError("--origins " + file + ": " + e.what());
  }
  return origins;
}

}  // namespace ceilplan::io
