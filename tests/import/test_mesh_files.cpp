// io::readTriangleMesh on the files CAD and photogrammetry tools write: polygon faces of any
// size, glTF, GLB and COLLADA scenes with their node transforms and axes, and coordinates
// beyond single precision.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "ceilplan/environment/map_builder.hpp"
#include "ceilplan/io/mesh_file.hpp"
#include "input_error.hpp"
#include "run_command.hpp"

namespace ceilplan::io {
namespace {

using environment::TriangleMesh;

// Into this test's own directory (ctest runs tests side by side).
std::filesystem::path writeFile(const std::string& name, const std::string& content) {
  const std::filesystem::path dir = std::filesystem::path(CEILPLAN_TEST_TMP) / "mesh_files" /
                                    ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << content;
  return dir / name;
}

double areaOf(const TriangleMesh& mesh) {
  double area = 0.0;
  for (const auto& t : mesh.triangles)
    area += 0.5 *
            (mesh.vertices_m[t[1]] - mesh.vertices_m[t[0]]).cross(mesh.vertices_m[t[2]] - mesh.vertices_m[t[0]]).norm();
  return area;
}

Eigen::AlignedBox3d boundsOf(const TriangleMesh& mesh) {
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& v : mesh.vertices_m) box.extend(v);
  return box;
}

// The unit cube's corners and its six faces as quads, counter-clockwise seen from outside.
const char* const kCubeCorners = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n";
const int kCubeQuads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

std::string cubeObj() {
  std::string text;
  std::istringstream corners(kCubeCorners);
  for (std::string line; std::getline(corners, line);) text += "v " + line + "\n";
  for (const auto& q : kCubeQuads)
    text += "f " + std::to_string(q[0] + 1) + " " + std::to_string(q[1] + 1) + " " + std::to_string(q[2] + 1) + " " +
            std::to_string(q[3] + 1) + "\n";
  return text;
}

std::string plyHeader(int vertices, int faces, const char* type = "float") {
  const std::string t(type);
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertices) + "\nproperty " + t + " x\nproperty " + t +
         " y\nproperty " + t + " z\nelement face " + std::to_string(faces) +
         "\nproperty list uchar int vertex_indices\nend_header\n";
}

TEST(MeshFiles, PolygonFacesOfAnySizeAreTriangulated) {
  // A cube of six quads, as OBJ (Open3D read it as an empty mesh) and as PLY.
  std::string ply = plyHeader(8, 6) + kCubeCorners;
  for (const auto& q : kCubeQuads)
    ply += "4 " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) + " " +
           std::to_string(q[3]) + "\n";
  for (const auto& file : {writeFile("cube.obj", cubeObj()), writeFile("cube.ply", ply)}) {
    const TriangleMesh mesh = readTriangleMesh(file);
    EXPECT_EQ(mesh.triangles.size(), 12u) << file;
    EXPECT_NEAR(areaOf(mesh), 6.0, 1e-9) << file;
    const environment::MeshTopology topology = environment::meshTopology(mesh);
    EXPECT_TRUE(topology.closed()) << file;
    EXPECT_TRUE(topology.consistently_oriented) << file;
    EXPECT_NEAR(topology.signed_volume_m3, 1.0, 1e-9) << file;
  }
  // An L-shaped hexagon, concave: its 3 m2 and no more (assimp's own triangulation covers the
  // notch too: 4 m2).
  const auto l_shape = writeFile("l.obj", "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nf 1 2 3 4 5 6\n");
  const TriangleMesh l_mesh = readTriangleMesh(l_shape);
  EXPECT_EQ(l_mesh.triangles.size(), 4u);
  EXPECT_NEAR(areaOf(l_mesh), 3.0, 1e-9);
  // Quads with a repeated corner (a triangle stored as a quad) and crossed quads, which Open3D
  // refused as "could not be decomposed into triangles", are read.
  const auto repeated =
      writeFile("repeated.ply", plyHeader(4, 2) + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 1 2\n4 0 2 1 3\n");
  const TriangleMesh repeated_mesh = readTriangleMesh(repeated);
  EXPECT_EQ(repeated_mesh.triangles.size(), 3u);
  EXPECT_NEAR(areaOf(repeated_mesh), 0.5 + 1.0, 1e-9);
  // A vertical face of 8 corners: the girder web of a CAD export.
  const auto web = writeFile(
      "web.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nv 3 0 1\nv 2 0 1\nv 1 0 1\nv 0 0 1\nf 1 2 3 4 5 6 7 8\n");
  EXPECT_NEAR(areaOf(readTriangleMesh(web)), 3.0, 1e-9);
}

// Little-endian bytes of floats and 16-bit indices, for glTF buffers.
template <typename T>
std::string bytesOf(const std::vector<T>& values) {
  return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

// A glTF 2.0 scene: the unit cube (y up, as glTF states) placed by its node at (10, 0, 0) and
// turned by it a quarter turn about y.
std::string cubeGltf(const std::string& buffer_uri, std::size_t buffer_bytes) {
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
         R"("nodes":[{"mesh":0,"translation":[10,0,0],"rotation":[0,0.7071067811865476,0,0.7071067811865476]}],)"
         R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"mode":4}]}],"buffers":[{)" +
         (buffer_uri.empty() ? std::string() : "\"uri\":\"" + buffer_uri + "\",") +
         "\"byteLength\":" + std::to_string(buffer_bytes) +
         R"(}],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":96},{"buffer":0,"byteOffset":96,"byteLength":72}],)"
         R"("accessors":[{"bufferView":0,"componentType":5126,"count":8,"type":"VEC3","min":[0,0,0],"max":[1,1,1]},)"
         R"({"bufferView":1,"componentType":5123,"count":36,"type":"SCALAR"}]})";
}

std::string cubeBuffer() {
  std::vector<float> corners;
  std::istringstream text(kCubeCorners);
  for (float value; text >> value;) corners.push_back(value);
  std::vector<std::uint16_t> indices;
  for (const auto& q : kCubeQuads)
    for (int corner : {q[0], q[1], q[2], q[0], q[2], q[3]}) indices.push_back(static_cast<std::uint16_t>(corner));
  return bytesOf(corners) + bytesOf(indices);
}

std::string glb(std::string json, std::string buffer) {
  json.append((4 - json.size() % 4) % 4, ' ');
  buffer.append((4 - buffer.size() % 4) % 4, '\0');
  const auto word = [](std::uint32_t value) { return bytesOf(std::vector<std::uint32_t>{value}); };
  const std::string body = word(std::uint32_t(json.size())) + "JSON" + json + word(std::uint32_t(buffer.size())) +
                           "BIN" + std::string(1, '\0') + buffer;
  return "glTF" + word(2) + word(std::uint32_t(12 + body.size())) + body;
}

std::string cubeCollada(const std::string& unit, double metres_per_unit, const std::string& up_axis) {
  std::string indices;
  for (const auto& q : kCubeQuads)
    for (int corner : q) indices += std::to_string(corner) + " ";
  std::string corners(kCubeCorners);
  std::replace(corners.begin(), corners.end(), '\n', ' ');
  return R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
<asset><unit name=")" +
         unit + "\" meter=\"" + std::to_string(metres_per_unit) + "\"/><up_axis>" + up_axis +
         R"(</up_axis></asset>
<library_geometries><geometry id="cube"><mesh>
<source id="p"><float_array id="pa" count="24">)" +
         corners + R"(</float_array>
<technique_common><accessor source="#pa" count="8" stride="3"><param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>
<vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
<polylist count="6"><input semantic="VERTEX" source="#v" offset="0"/><vcount>4 4 4 4 4 4</vcount><p>)" +
         indices +
         R"(</p></polylist></mesh></geometry></library_geometries>
<library_visual_scenes><visual_scene id="s"><node id="n"><translate>0 0 5</translate><instance_geometry url="#cube"/></node></visual_scene></library_visual_scenes>
<scene><instance_visual_scene url="#s"/></scene></COLLADA>
)";
}

void expectBox(const TriangleMesh& mesh, const Eigen::Vector3d& min, const Eigen::Vector3d& max,
               const std::string& file) {
  const Eigen::AlignedBox3d box = boundsOf(mesh);
  EXPECT_LT((box.min() - min).norm(), 1e-6) << file << ": " << box.min().transpose();
  EXPECT_LT((box.max() - max).norm(), 1e-6) << file << ": " << box.max().transpose();
  EXPECT_EQ(mesh.triangles.size(), 12u) << file;
  EXPECT_TRUE(environment::meshTopology(mesh).closed()) << file;
}

TEST(MeshFiles, GltfGlbAndColladaScenesArePlacedByTheirNodesWithZUp) {
  // glTF: the node turns the cube a quarter turn about y (x -> -z) and moves it 10 m along x;
  // glTF's y up becomes z, its z becomes -y.
  const std::string buffer = cubeBuffer();
  writeFile("cube.bin", buffer);
  for (const auto& file : {writeFile("cube.gltf", cubeGltf("cube.bin", buffer.size())),
                           writeFile("cube.glb", glb(cubeGltf("", buffer.size()), buffer))})
    expectBox(readTriangleMesh(file), {10, 0, 0}, {11, 1, 1}, file.string());
  // COLLADA states its up axis and unit: the same cube, z up, 5 units up, in metres and in centimetres.
  const auto metres = writeFile("cube.dae", cubeCollada("meter", 1.0, "Z_UP"));
  expectBox(readTriangleMesh(metres), {0, 0, 5}, {1, 1, 6}, metres.string());
  const auto centimetres = writeFile("cube_cm.dae", cubeCollada("centimeter", 0.01, "Z_UP"));
  expectBox(readTriangleMesh(centimetres), {0, 0, 0.05}, {0.01, 0.01, 0.06}, centimetres.string());
  const auto y_up = writeFile("cube_y.dae", cubeCollada("meter", 1.0, "Y_UP"));
  expectBox(readTriangleMesh(y_up), {0, -6, 0}, {1, -5, 1}, y_up.string());
}

// An ASCII FBX 7.4 scene: the unit cube as six quads, its model moved 10 units along x, with the
// axes (up, front and its sign; x to the right) and unit (centimetres per unit) it states.
std::string cubeFbx(int up, int front, int front_sign, double centimetres_per_unit) {
  const auto setting = [](const std::string& name, const std::string& type, const auto& value) {
    return "P: \"" + name + "\", \"" + type + "\", \"\", \"\"," + std::to_string(value) + "\n";
  };
  std::string corners, quads;
  for (char c : std::string(kCubeCorners)) corners += c == ' ' || c == '\n' ? ',' : c;
  corners.pop_back();
  for (const auto& q : kCubeQuads)  // the last corner of a polygon is stored as -(index + 1)
    quads += std::to_string(q[0]) + "," + std::to_string(q[1]) + "," + std::to_string(q[2]) + "," +
             std::to_string(-q[3] - 1) + ",";
  quads.pop_back();
  return "; FBX 7.4.0 project file\nFBXHeaderExtension: {\nFBXHeaderVersion: 1003\nFBXVersion: 7400\n}\n"
         "GlobalSettings: {\nVersion: 1000\nProperties70: {\n" +
         setting("UpAxis", "int", up) + setting("UpAxisSign", "int", 1) + setting("FrontAxis", "int", front) +
         setting("FrontAxisSign", "int", front_sign) + setting("CoordAxis", "int", 0) +
         setting("CoordAxisSign", "int", 1) + setting("UnitScaleFactor", "double", centimetres_per_unit) +
         "}\n}\nObjects: {\nGeometry: 1000, \"Geometry::cube\", \"Mesh\" {\nVertices: *24 {\na: " + corners +
         "\n}\nPolygonVertexIndex: *24 {\na: " + quads +
         "\n}\nGeometryVersion: 124\n}\nModel: 2000, \"Model::cube\", \"Mesh\" {\nVersion: 232\nProperties70: {\n"
         "P: \"Lcl Translation\", \"Lcl Translation\", \"\", \"A\",10,0,0\n}\n}\n}\n"
         "Connections: {\nC: \"OO\",2000,0\nC: \"OO\",1000,2000\n}\n";
}

TEST(MeshFiles, FbxScenesAreTurnedZUpAndScaledToMetresByTheirGlobalSettings) {
  // Maya's axes (y up, z towards the viewer) in metres (100 cm per unit): y becomes z, z becomes -y.
  const auto maya = writeFile("maya.fbx", cubeFbx(1, 2, 1, 100.0));
  expectBox(readTriangleMesh(maya), {10, -1, 0}, {11, 0, 1}, maya.string());
  // Blender's (z up, -y forward) in centimetres, FBX's default unit.
  const auto blender = writeFile("blender.fbx", cubeFbx(2, 1, -1, 1.0));
  expectBox(readTriangleMesh(blender), {0.1, 0, 0}, {0.11, 0.01, 0.01}, blender.string());
}

TEST(MeshFiles, CoordinatesBeyondSinglePrecisionAreReadInDoubleOrRefused) {
  // A triangle in UTM coordinates: PLY keeps its doubles (read with Open3D); OBJ, read in single
  // precision, would move it by up to 0.5 m and is refused.
  const auto ply = writeFile("utm.ply", plyHeader(3, 1, "double") +
                                            "500123.456 5400000.123 480.1\n500124.456 5400000.123 480.1\n"
                                            "500124.456 5400001.123 480.1\n3 0 1 2\n");
  const TriangleMesh mesh = readTriangleMesh(ply);
  ASSERT_EQ(mesh.vertices_m.size(), 3u);
  EXPECT_NEAR(mesh.vertices_m[0].x(), 500123.456, 1e-6);
  EXPECT_NEAR(mesh.vertices_m[0].y(), 5400000.123, 1e-6);
  const auto obj = writeFile("utm.obj",
                             "v 500123.456 5400000.123 480.1\nv 500124.456 5400000.123 480.1\n"
                             "v 500124.456 5400001.123 480.1\nf 1 2 3\n");
  EXPECT_EQ(testing::inputErrorOf([&] { readTriangleMesh(obj); }),
            obj.string() +
                ": vertices lie up to 5400001 m from the origin, where this format is read in single "
                "precision (steps of 0.5 m); export the mesh near the origin, or as .ply (read in double "
                "precision)");
}

}  // namespace
}  // namespace ceilplan::io
