#pragma once
// Point clouds and meshes of simple structures, sampled exactly and written in the formats
// users bring (PCD ascii and binary, PLY, STL binary, OBJ), so import tests know the geometry
// the map must reproduce. The writers follow the published format descriptions (PCL's PCD v0.7,
// Paul Bourke's PLY, the STL and Wavefront OBJ layouts); they are fixtures, not readers.

#include "ceilplan/environment/map_builder.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace ceilplan::testing {

// Points every `spacing` metres on the rectangle corner + s u + t v, s and t in [0, 1].
inline std::vector<Eigen::Vector3d> sampleRectangle(const Eigen::Vector3d& corner, const Eigen::Vector3d& u,
                                                    const Eigen::Vector3d& v, double spacing) {
  std::vector<Eigen::Vector3d> points;
  const int nu = static_cast<int>(std::ceil(u.norm() / spacing)), nv = static_cast<int>(std::ceil(v.norm() / spacing));
  for (int a = 0; a <= nu; ++a)
    for (int b = 0; b <= nv; ++b) points.push_back(corner + u * (double(a) / nu) + v * (double(b) / nv));
  return points;
}

// Points on the six faces of the box [min, max].
inline std::vector<Eigen::Vector3d> sampleBoxSurface(const Eigen::Vector3d& min, const Eigen::Vector3d& max,
                                                     double spacing) {
  const Eigen::Vector3d d = max - min;
  const Eigen::Vector3d x(d.x(), 0, 0), y(0, d.y(), 0), z(0, 0, d.z());
  std::vector<Eigen::Vector3d> points;
  for (const auto& face : {sampleRectangle(min, x, y, spacing), sampleRectangle(min + z, x, y, spacing),
                           sampleRectangle(min, x, z, spacing), sampleRectangle(min + y, x, z, spacing),
                           sampleRectangle(min, y, z, spacing), sampleRectangle(min + x, y, z, spacing)})
    points.insert(points.end(), face.begin(), face.end());
  return points;
}

// Binary files store floats, or doubles when `doubles` (projected coordinates need them).
inline void writePcd(const std::filesystem::path& file, const std::vector<Eigen::Vector3d>& points, bool binary,
                     bool doubles = false) {
  std::ofstream out(file, std::ios::binary);
  out.precision(12);
  out << "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z\nSIZE " << (doubles ? "8 8 8" : "4 4 4")
      << "\nTYPE F F F\nCOUNT 1 1 1\n"
      << "WIDTH " << points.size() << "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " << points.size() << "\nDATA "
      << (binary ? "binary" : "ascii") << "\n";
  for (const Eigen::Vector3d& p : points) {
    if (binary && doubles) {
      out.write(reinterpret_cast<const char*>(p.data()), 3 * sizeof(double));
    } else if (binary) {
      const float xyz[3] = {float(p.x()), float(p.y()), float(p.z())};
      out.write(reinterpret_cast<const char*>(xyz), sizeof xyz);
    } else {
      out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    }
  }
}

inline void writePlyPoints(const std::filesystem::path& file, const std::vector<Eigen::Vector3d>& points) {
  std::ofstream out(file);
  out << "ply\nformat ascii 1.0\nelement vertex " << points.size()
      << "\nproperty double x\nproperty double y\nproperty double z\nend_header\n";
  out.precision(10);
  for (const Eigen::Vector3d& p : points) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
}

// The closed box [min, max] as 12 triangles, facing outward (or inward: a room).
inline environment::TriangleMesh boxMesh(const Eigen::Vector3d& min, const Eigen::Vector3d& max, bool outward = true) {
  environment::TriangleMesh mesh;
  for (int corner = 0; corner < 8; ++corner)
    mesh.vertices_m.emplace_back(corner & 1 ? max.x() : min.x(), corner & 2 ? max.y() : min.y(),
                                 corner & 4 ? max.z() : min.z());
  // Counter-clockwise seen from outside.
  const std::size_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[2], q[3]});
  }
  if (!outward)
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  return mesh;
}

// A rectangle as two triangles: an open mesh.
inline environment::TriangleMesh rectangleMesh(const Eigen::Vector3d& corner, const Eigen::Vector3d& u,
                                               const Eigen::Vector3d& v) {
  environment::TriangleMesh mesh;
  mesh.vertices_m = {corner, corner + u, corner + u + v, corner + v};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

inline void writeStlBinary(const std::filesystem::path& file, const environment::TriangleMesh& mesh) {
  std::ofstream out(file, std::ios::binary);
  const std::string header(80, ' ');
  out.write(header.data(), 80);
  const std::uint32_t count = static_cast<std::uint32_t>(mesh.triangles.size());
  out.write(reinterpret_cast<const char*>(&count), 4);
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d &a = mesh.vertices_m[t[0]], &b = mesh.vertices_m[t[1]], &c = mesh.vertices_m[t[2]];
    const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    float values[12];
    for (int axis = 0; axis < 3; ++axis) {
      values[axis] = float(n[axis]);
      values[3 + axis] = float(a[axis]);
      values[6 + axis] = float(b[axis]);
      values[9 + axis] = float(c[axis]);
    }
    out.write(reinterpret_cast<const char*>(values), sizeof values);
    const std::uint16_t attributes = 0;
    out.write(reinterpret_cast<const char*>(&attributes), 2);
  }
}

inline void writeObj(const std::filesystem::path& file, const environment::TriangleMesh& mesh) {
  std::ofstream out(file);
  out.precision(10);
  for (const Eigen::Vector3d& v : mesh.vertices_m) out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const auto& t : mesh.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

inline void writePlyMesh(const std::filesystem::path& file, const environment::TriangleMesh& mesh) {
  std::ofstream out(file);
  out << "ply\nformat ascii 1.0\nelement vertex " << mesh.vertices_m.size()
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << mesh.triangles.size()
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  out.precision(10);
  for (const Eigen::Vector3d& v : mesh.vertices_m) out << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const auto& t : mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

}  // namespace ceilplan::testing
