#include "ceilplan/io/point_cloud_file.hpp"

#include "file_kind.hpp"
#include "open3d_log.hpp"

#include <open3d/geometry/PointCloud.h>
#include <open3d/io/PointCloudIO.h>

#include <array>
#include <fstream>

namespace ceilplan::io {
namespace {

constexpr std::array<const char*, 6> kCloudExtensions = {".pcd", ".ply", ".xyz", ".xyzn", ".xyzrgb", ".pts"};
constexpr std::array<const char*, 6> kMeshOnlyExtensions = {".stl", ".obj", ".off", ".gltf", ".glb", ".fbx"};

}  // namespace

std::string pointCloudExtensions() { return detail::joined(kCloudExtensions); }

std::vector<Eigen::Vector3d> readPointCloud(const std::filesystem::path& file) {
  const std::string name = file.string();
  const std::string extension = detail::lowerExtension(file);
  if (detail::listed(kMeshOnlyExtensions, extension))
    throw ceilplan::InputError(name + ": " + extension + " is a mesh format, not a point cloud");
  if (!detail::listed(kCloudExtensions, extension))
    throw ceilplan::InputError(name + ": unknown point-cloud format '" + extension + "' (read: " + pointCloudExtensions() + ")");
  if (!std::filesystem::is_regular_file(file) || !std::ifstream(file))
    throw ceilplan::InputError(name + ": no such file, or it cannot be read");

  open3d::geometry::PointCloud cloud;
  open3d::io::ReadPointCloudOption option;
  option.remove_nan_points = false;
  option.remove_infinite_points = false;
  if (const auto failure = detail::failureOf([&] { return open3d::io::ReadPointCloud(name, cloud, option); }))
    throw ceilplan::InputError(name + ": not a readable point cloud" + (failure->empty() ? "" : " (Open3D: " + *failure + ")"));
  if (cloud.points_.empty()) throw ceilplan::InputError(name + ": the point cloud has no points");
  return std::move(cloud.points_);
}

}  // namespace ceilplan::io
