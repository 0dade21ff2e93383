#include "ceilplan/io/point_cloud_file.hpp"

#include "file_kind.hpp"
#include "open3d_log.hpp"

#include <open3d/geometry/PointCloud.h>
#include <open3d/io/PointCloudIO.h>

#include <array>
#include <fstream>
#include <sstream>

namespace ceilplan::io {
namespace {

constexpr std::array<const char*, 6> kCloudExtensions = {".pcd", ".ply", ".xyz", ".xyzn", ".xyzrgb", ".pts"};
constexpr std::array<const char*, 6> kMeshOnlyExtensions = {".stl", ".obj", ".off", ".gltf", ".glb", ".fbx"};

// Open3D 0.16 (Debian bookworm) reads binary PCD fields of 8-byte floats as zeros, silently.
// Its header lines tell; such files are refused rather than imported as a heap of zeros.
void refuseBinaryDoublePcd(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string line, fields, sizes;
  for (int lines = 0; lines < 64 && std::getline(in, line); ++lines) {
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "FIELDS") fields = line;
    if (key == "SIZE") sizes = line;
    if (key != "DATA") continue;
    std::string storage;
    words >> storage;
    if (storage == "ascii") return;
    std::istringstream names(fields), bytes(sizes);
    std::string name, size;
    names >> name;  // "FIELDS"
    bytes >> size;  // "SIZE"
    while (names >> name && bytes >> size)
      if ((name == "x" || name == "y" || name == "z") && size == "8")
        throw ceilplan::InputError(file.string() + ": " + storage + " PCD with 8-byte coordinates, which the PCD reader (Open3D 0.16) "
                                   "reads as zeros; save it as ascii PCD or as PLY");
    return;
  }
}

}  // namespace

std::string pointCloudExtensions() { return detail::joined(kCloudExtensions); }

std::vector<Eigen::Vector3d> readPointCloud(const std::filesystem::path& file) {
  const std::string name = file.string();
  const std::string extension =
      detail::requireReadableFileOfKind(file, kCloudExtensions, kMeshOnlyExtensions, "point cloud", "mesh");

  if (extension == ".pcd") refuseBinaryDoublePcd(file);

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
