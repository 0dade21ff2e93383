#include "ceilplan/io/mesh_file.hpp"

#include "file_kind.hpp"
#include "open3d_input_checks.hpp"
#include "open3d_log.hpp"

#include <open3d/geometry/TriangleMesh.h>
#include <open3d/io/TriangleMeshIO.h>

#include <algorithm>
#include <array>

namespace ceilplan::io {
namespace {

constexpr std::array<const char*, 4> kMeshExtensions = {".stl", ".obj", ".ply", ".off"};
constexpr std::array<const char*, 5> kCloudOnlyExtensions = {".pcd", ".xyz", ".xyzn", ".xyzrgb", ".pts"};

}  // namespace

std::string meshExtensions() { return detail::joined(kMeshExtensions); }

environment::TriangleMesh readTriangleMesh(const std::filesystem::path& file) {
  const std::string name = file.string();
  const std::string extension =
      detail::requireReadableFileOfKind(file, kMeshExtensions, kCloudOnlyExtensions, "mesh", "point-cloud");
  // The header counts first (their messages name the mismatch), then the whole file as Open3D
  // would walk it (faces it would crash on).
  if (extension == ".ply") detail::checkPlyFile(file, "mesh");

  open3d::geometry::TriangleMesh mesh;
  if (const auto failure = detail::failureOf([&] { return open3d::io::ReadTriangleMesh(name, mesh, open3d::io::ReadTriangleMeshOptions{}); }))
    throw ceilplan::InputError(name + ": not a readable mesh" + (failure->empty() ? "" : " (Open3D: " + *failure + ")"));
  if (mesh.triangles_.empty())
    throw ceilplan::InputError(name + ": the mesh has no triangles" +
                               (mesh.vertices_.empty() ? std::string() : " (only vertices: a point cloud?)"));

  environment::TriangleMesh result;
  result.vertices_m = std::move(mesh.vertices_);
  result.triangles.reserve(mesh.triangles_.size());
  for (std::size_t t = 0; t < mesh.triangles_.size(); ++t) {
    const Eigen::Vector3i& triangle = mesh.triangles_[t];
    if ((triangle.array() < 0).any() || (triangle.array() >= static_cast<int>(result.vertices_m.size())).any())
      throw ceilplan::InputError(name + ": triangle " + std::to_string(t) + " names a vertex that does not exist");
    result.triangles.push_back({static_cast<std::size_t>(triangle[0]), static_cast<std::size_t>(triangle[1]),
                                static_cast<std::size_t>(triangle[2])});
  }
  // A mesh of zero-area faces (collinear or repeated corners) has no surface to voxelise: the
  // map would come out empty or wrong, so say what the file holds.
  const auto hasArea = [&](const std::array<std::size_t, 3>& t) {
    const Eigen::Vector3d& a = result.vertices_m[t[0]];
    const Eigen::Vector3d edge1 = result.vertices_m[t[1]] - a, edge2 = result.vertices_m[t[2]] - a;
    const double scale = std::max(edge1.squaredNorm(), edge2.squaredNorm());
    return edge1.cross(edge2).norm() > 1e-12 * scale;
  };
  if (std::none_of(result.triangles.begin(), result.triangles.end(), hasArea))
    throw ceilplan::InputError(name + ": all " + std::to_string(result.triangles.size()) +
                               " triangles of the mesh have zero area (collinear or repeated corners); export the "
                               "mesh again with its faces");
  return result;
}

}  // namespace ceilplan::io
