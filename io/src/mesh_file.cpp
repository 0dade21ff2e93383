#include "ceilplan/io/mesh_file.hpp"

#include <assimp/DefaultIOSystem.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <open3d/geometry/TriangleMesh.h>
#include <open3d/io/TriangleMeshIO.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <assimp/Importer.hpp>
#include <cmath>
#include <numeric>
#include <system_error>

#include "ceilplan/core/format.hpp"
#include "ceilplan/core/printable_text.hpp"
#include "file_kind.hpp"
#include "open3d_input_checks.hpp"
#include "open3d_log.hpp"

namespace ceilplan::io {
namespace {

constexpr std::array<const char*, 8> kMeshExtensions = {".stl",  ".obj", ".ply", ".off",
                                                        ".gltf", ".glb", ".dae", ".fbx"};
constexpr std::array<const char*, 5> kCloudOnlyExtensions = {".pcd", ".xyz", ".xyzn", ".xyzrgb", ".pts"};

// assimp keeps coordinates in single precision (Debian's build): beyond this distance from the
// origin its steps exceed 1 mm, a tenth of the finest import resolution.
constexpr double kSinglePrecisionReach_m = 8192.0;

// A scene may place one mesh many times: bounded before the vertices are copied (24 bytes each).
constexpr std::size_t kMaxVertices = 200'000'000;

// assimp opens the files a scene names (a glTF's buffers) itself: each gets the check every
// reader makes first, so that a FIFO or a device named there is refused, not read for ever.
class CheckedIOSystem : public Assimp::DefaultIOSystem {
 public:
  bool Exists(const char* file) const override {
    std::error_code error;
    return std::filesystem::exists(file, error);  // without opening it: a FIFO would block
  }
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    try {
      requireInputFile(file, "mesh file");
    } catch (const ceilplan::Error& e) {
      refusal = e.what();
      return nullptr;
    }
    return DefaultIOSystem::Open(file, mode);
  }
  std::string refusal;  // why the last refused file was refused
};

// Appends the triangles of one polygon face (corner indices into `vertices`): ear clipping in the
// plane of its Newell normal, so that concave faces keep their shape (assimp 5.2's triangulation
// overlaps the triangles of an L-shaped face); repeated corners are dropped, and what no ear can
// be cut from (a self-intersecting or degenerate face) becomes a fan.
void appendTriangles(const std::vector<Eigen::Vector3d>& vertices, std::vector<std::size_t> corners,
                     std::vector<std::array<std::size_t, 3>>& triangles) {
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  while (corners.size() > 1 && corners.front() == corners.back()) corners.pop_back();
  if (corners.size() < 3) return;
  if (corners.size() == 3) {
    triangles.push_back({corners[0], corners[1], corners[2]});
    return;
  }
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < corners.size(); ++i)
    normal += vertices[corners[i]].cross(vertices[corners[(i + 1) % corners.size()]]);
  std::vector<Eigen::Vector2d> flat;
  if (normal.norm() > 0.0) {
    const Eigen::Vector3d n = normal.normalized();
    const Eigen::Vector3d u = n.unitOrthogonal(), w = n.cross(u);
    for (std::size_t c : corners) {
      const Eigen::Vector3d d = vertices[c] - vertices[corners[0]];
      flat.emplace_back(d.dot(u), d.dot(w));  // counter-clockwise: u x w is the normal
    }
  }
  const auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); };
  std::vector<std::size_t> left(corners.size());
  std::iota(left.begin(), left.end(), 0);
  while (left.size() > 3 && !flat.empty()) {
    bool cut = false;
    for (std::size_t i = 0; i < left.size() && !cut; ++i) {
      const std::size_t a = left[(i + left.size() - 1) % left.size()], b = left[i], c = left[(i + 1) % left.size()];
      if (cross(flat[b] - flat[a], flat[c] - flat[b]) <= 0.0) continue;  // reflex or straight
      const bool empty = std::none_of(left.begin(), left.end(), [&](std::size_t p) {
        if (p == a || p == b || p == c || flat[p] == flat[a] || flat[p] == flat[b] || flat[p] == flat[c]) return false;
        return cross(flat[b] - flat[a], flat[p] - flat[a]) >= 0.0 &&
               cross(flat[c] - flat[b], flat[p] - flat[b]) >= 0.0 && cross(flat[a] - flat[c], flat[p] - flat[c]) >= 0.0;
      });
      if (!empty) continue;
      triangles.push_back({corners[a], corners[b], corners[c]});
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(i));
      cut = true;
    }
    if (!cut) break;
  }
  for (std::size_t i = 1; i + 1 < left.size(); ++i)
    triangles.push_back({corners[left[0]], corners[left[i]], corners[left[i + 1]]});
}

// The map from a file's axes and unit into ceilplan's (metres, z up). glTF is y up in metres by
// its specification and assimp turns a COLLADA file's <up_axis> into y up and its <unit> into
// metres; FBX states its axes and unit (centimetres per unit) in its global settings, which
// assimp 5.2 passes on as metadata without applying them. Other formats carry neither: they are
// taken as z up in metres.
Eigen::Matrix3d axesOf(const aiScene& scene, const std::string& extension) {
  Eigen::Matrix3d yUp;
  yUp << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  if (extension == ".gltf" || extension == ".glb" || extension == ".dae") return yUp;
  if (extension != ".fbx" || !scene.mMetaData) return Eigen::Matrix3d::Identity();
  std::int32_t up = 1, up_sign = 1, front = 2, front_sign = 1, coord = 0, coord_sign = 1;
  const aiMetadata& metadata = *scene.mMetaData;
  if (!metadata.Get("UpAxis", up) || !metadata.Get("UpAxisSign", up_sign) || !metadata.Get("FrontAxis", front) ||
      !metadata.Get("FrontAxisSign", front_sign) || !metadata.Get("CoordAxis", coord) ||
      !metadata.Get("CoordAxisSign", coord_sign))
    return yUp;  // FBX's default axes
  const auto axis = [](std::int32_t index, std::int32_t sign) {
    return index >= 0 && index < 3 ? Eigen::Vector3d(Eigen::Vector3d::Unit(index) * (sign < 0 ? -1.0 : 1.0))
                                   : Eigen::Vector3d(Eigen::Vector3d::Zero());
  };
  // Rows: ceilplan's x is the file's right (coord) axis, z its up axis, y the opposite of its
  // front axis (FBX's front points at the viewer): Maya's y up gives (x, -z, y), Blender's z up
  // with -y forward the identity.
  Eigen::Matrix3d rotation;
  rotation.row(0) = axis(coord, coord_sign).transpose();
  rotation.row(1) = -axis(front, front_sign).transpose();
  rotation.row(2) = axis(up, up_sign).transpose();
  if (std::abs(rotation.determinant() - 1.0) > 1e-9) rotation = yUp;  // not a proper rotation: metadata we cannot use
  float centimetres_per_unit = 1.0f;                                  // FBX's default unit
  double stated = 1.0;
  if (!metadata.Get("UnitScaleFactor", centimetres_per_unit) && metadata.Get("UnitScaleFactor", stated))
    centimetres_per_unit = static_cast<float>(stated);
  if (std::isfinite(centimetres_per_unit) && centimetres_per_unit > 0.0f) rotation *= 0.01 * centimetres_per_unit;
  return rotation;
}

// A .ply or .off whose coordinates need double precision (a mesh in projected coordinates):
// Open3D reads these formats in double, but refuses polygon faces it cannot ear-clip.
environment::TriangleMesh readWithOpen3d(const std::string& name) {
  open3d::geometry::TriangleMesh mesh;
  if (const auto failure = detail::failureOf(
          [&] { return open3d::io::ReadTriangleMesh(name, mesh, open3d::io::ReadTriangleMeshOptions{}); }))
    throw ceilplan::InputError(name + ": not a readable mesh" +
                               (failure->empty() ? "" : " (Open3D: " + *failure + ")"));
  environment::TriangleMesh result;
  result.vertices_m = std::move(mesh.vertices_);
  for (const Eigen::Vector3i& triangle : mesh.triangles_) {
    if ((triangle.array() < 0).any() || (triangle.array() >= static_cast<int>(result.vertices_m.size())).any())
      throw ceilplan::InputError(name + ": a triangle names a vertex that does not exist");
    result.triangles.push_back({static_cast<std::size_t>(triangle[0]), static_cast<std::size_t>(triangle[1]),
                                static_cast<std::size_t>(triangle[2])});
  }
  return result;
}

}  // namespace

std::string meshExtensions() { return detail::joined(kMeshExtensions); }

environment::TriangleMesh readTriangleMesh(const std::filesystem::path& file) {
  const std::string name = file.string();
  const std::string extension =
      detail::requireReadableFileOfKind(file, kMeshExtensions, kCloudOnlyExtensions, "mesh", "point-cloud");
  // The header counts first (their messages name the mismatch), then the whole file as a reader
  // would walk it (faces that crashed Open3D's reader).
  if (extension == ".ply") detail::checkPlyFile(file, "mesh");

  Assimp::Importer importer;
  auto* io_system = new CheckedIOSystem;  // the importer owns it
  importer.SetIOHandler(io_system);
  // No post-processing: faces are triangulated, their corners checked and node transforms applied
  // below (aiProcess_ValidateDataStructure and aiProcess_PreTransformVertices refuse a point
  // cloud's vertices without saying what they are).
  const aiScene* scene = importer.ReadFile(name, 0);
  if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
    const std::string why = !io_system->refusal.empty() ? io_system->refusal : importer.GetErrorString();
    throw ceilplan::InputError(name + ": not a readable mesh" +
                               (why.empty() ? "" : " (" + printableText(why, 300) + ")"));
  }

  // Every mesh where the node tree places it (a glTF or COLLADA scene instances meshes).
  const Eigen::Matrix3d axes = axesOf(*scene, extension);
  environment::TriangleMesh result;
  double reach_m = 0.0;
  std::vector<std::pair<const aiNode*, aiMatrix4x4>> nodes;
  if (scene->mRootNode) nodes.emplace_back(scene->mRootNode, scene->mRootNode->mTransformation);
  std::vector<std::size_t> corners;
  while (!nodes.empty()) {
    const auto [node, transform] = nodes.back();
    nodes.pop_back();
    for (unsigned c = 0; c < node->mNumChildren; ++c)
      nodes.emplace_back(node->mChildren[c], transform * node->mChildren[c]->mTransformation);
    for (unsigned n = 0; n < node->mNumMeshes; ++n) {
      if (node->mMeshes[n] >= scene->mNumMeshes)
        throw ceilplan::InputError(name + ": not a readable mesh (a node names a mesh that does not exist)");
      const aiMesh& mesh = *scene->mMeshes[node->mMeshes[n]];
      if (!mesh.mVertices && mesh.mNumVertices > 0)
        throw ceilplan::InputError(name + ": not a readable mesh (no vertex positions)");
      if (result.vertices_m.size() + mesh.mNumVertices > kMaxVertices)
        throw ceilplan::InputError(name + ": the scene places more than " + std::to_string(kMaxVertices) +
                                   " vertices; import its parts separately");
      const std::size_t first = result.vertices_m.size();
      for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
        const aiVector3D p = transform * mesh.mVertices[v];
        result.vertices_m.push_back(axes * Eigen::Vector3d(p.x, p.y, p.z));
        reach_m = std::max(reach_m, result.vertices_m.back().cwiseAbs().maxCoeff());
      }
      for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace& face = mesh.mFaces[f];
        if (face.mNumIndices < 3) continue;  // points and lines have no surface
        corners.assign(face.mIndices, face.mIndices + face.mNumIndices);
        for (std::size_t& corner : corners) {
          if (corner >= mesh.mNumVertices)
            throw ceilplan::InputError(name + ": not a readable mesh (face " + std::to_string(f) + " names vertex " +
                                       std::to_string(corner) + " of " + std::to_string(mesh.mNumVertices) + ")");
          corner += first;
        }
        appendTriangles(result.vertices_m, corners, result.triangles);
      }
    }
  }
  if (reach_m > kSinglePrecisionReach_m) {
    if (extension == ".ply" || extension == ".off") {
      result = readWithOpen3d(name);
    } else {
      const double step_m = std::ldexp(1.0, std::ilogb(reach_m) - 23);
      throw ceilplan::InputError(name + ": vertices lie up to " + formatFixed(reach_m, 0) +
                                 " m from the origin, where this format is read in single precision (steps of " +
                                 formatNumber(step_m) +
                                 " m); export the mesh near the origin, or as .ply (read in "
                                 "double precision)");
    }
  }
  if (result.triangles.empty()) {
    const bool vertices = std::any_of(scene->mMeshes, scene->mMeshes + scene->mNumMeshes,
                                      [](const aiMesh* mesh) { return mesh->mNumVertices > 0; });
    throw ceilplan::InputError(name + ": the mesh has no triangles" +
                               (vertices ? " (only vertices: a point cloud?)" : std::string()));
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
