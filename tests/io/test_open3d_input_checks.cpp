// Files that crash or mislead Open3D 0.16's PCD and PLY readers (io/src/open3d_input_checks.hpp):
// the fuzzers' reproducers (tests/io/fuzz_regressions/, docs/fuzzing.md) and their minimal forms
// are refused in words naming the file, and well-formed files still read.

#include "ceilplan/io/mesh_file.hpp"
#include "ceilplan/io/point_cloud_file.hpp"

#include "input_error.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <utility>

namespace ceilplan::io {
namespace {

const std::filesystem::path kSource(CEILPLAN_SOURCE_DIR);

std::filesystem::path writeFile(const std::string& name, const std::string& content) {
  const std::filesystem::path dir = std::filesystem::path(CEILPLAN_TEST_TMP) / "open3d_input_checks";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << content;
  return dir / name;
}

std::string cloudRefusal(const std::filesystem::path& file) {
  return testing::inputErrorOf([&] { readPointCloud(file); });
}

std::string meshRefusal(const std::filesystem::path& file) {
  return testing::inputErrorOf([&] { readTriangleMesh(file); });
}

const std::string kPlyTriangleHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";

TEST(Open3dInputChecks, TheFuzzersReproducersAreRefusedInWords) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kSource / "tests/io/fuzz_regressions")) {
    const std::filesystem::path& file = entry.path();
    const std::string name = file.string() + ": ";
    if (file.extension() != ".stl" && file.extension() != ".obj") {
      EXPECT_EQ(cloudRefusal(file).rfind(name, 0), 0u) << cloudRefusal(file);
    }
    if (file.extension() != ".pcd" && file.extension() != ".xyz") {
      EXPECT_EQ(meshRefusal(file).rfind(name, 0), 0u) << meshRefusal(file);
    }
    ++files;
  }
  EXPECT_GE(files, 2);
}

TEST(Open3dInputChecks, RefusesPcdHeadersOpen3dWouldMisread) {
  const std::string fields = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n";
  // A count of 0 made Open3D index past a row's values (the fuzzer's crash).
  const auto zero_count =
      writeFile("zero_count.pcd", "FIELDS x y z\nCOUNT 1 0 0\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1\n");
  EXPECT_EQ(cloudRefusal(zero_count),
            zero_count.string() + ": not a readable point cloud (PCD header line 2: a field count of '0' (1 or more))");
  // Fewer rows than points: Open3D returned the rest uninitialised. A short row it skipped.
  const auto few_rows = writeFile("few.pcd", fields + "WIDTH 3\nHEIGHT 1\nPOINTS 3\nDATA ascii\n1 2 3\n\n4 5 6\n");
  EXPECT_EQ(cloudRefusal(few_rows),
            few_rows.string() + ": not a readable point cloud (the ascii PCD announces 3 points but holds 2 rows)");
  const auto short_row =
      writeFile("short.pcd", fields + "WIDTH 3\nHEIGHT 1\nPOINTS 3\nDATA ascii\n1 2 3\n4 5\n7 8 9\n");
  EXPECT_EQ(cloudRefusal(short_row), short_row.string() +
                                         ": not a readable point cloud (PCD line 9: '4 5' holds 2 values "
                                         "where a point has 3; fix or delete the line)");
  // Two billion points announced in a file of a few bytes: Open3D allocated them first.
  const auto huge = writeFile("huge.pcd", fields + "WIDTH 100000000\nHEIGHT 20\nPOINTS 2000000000\nDATA binary\n");
  EXPECT_EQ(cloudRefusal(huge), huge.string() +
                                    ": not a readable point cloud (the binary PCD announces 2000000000 "
                                    "points of 12 bytes but holds 0 bytes of data)");
  const auto sizes = writeFile("sizes.pcd", fields + "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA binary_compressed\n" +
                                                std::string("\x08\x00\x00\x00\x0c\x00\x00\x01", 8));
  EXPECT_NE(cloudRefusal(sizes).find("the compressed PCD's data sizes (8 compressed, 16777228 uncompressed)"),
            std::string::npos);
  const auto half =
      writeFile("half.pcd", "FIELDS x y z\nSIZE 2 2 2\nTYPE F F F\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA binary\n123456");
  EXPECT_EQ(cloudRefusal(half), half.string() +
                                    ": binary PCD with 2-byte coordinates of type F, which the PCD reader "
                                    "(Open3D 0.16) reads as zeros; save it as ascii PCD or as PLY");
  for (const auto& [header, message] : std::initializer_list<std::pair<std::string, std::string>>{
           {fields + "COUNT 1 1 1\nSIZE 4 4 4\n", "PCD header line 5: a second SIZE line"},
           {"FIELDS x y z\nCOUNT 1 1 1\nSIZE 4 4 4\n", "PCD header line 3: SIZE after COUNT"},
           {"SIZE 4 4 4\n", "PCD header line 1: SIZE gives 3 values for 0 fields (FIELDS must come first)"},
           {fields + "HEIGHT 1\nWIDTH 1\n", "PCD header line 4: HEIGHT before WIDTH"},
           {fields + "WIDTH -1\n", "PCD header line 4: WIDTH '-1' is not a whole number from 1 to 2147483647"},
           {fields + "WIDTHS 1\n", "PCD header line 4: 'WIDTHS' is no PCD v0.7 entry"},
           {fields + "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA binaryx\n", "PCD header line 7: DATA 'binaryx'"},
           {fields + "WIDTH 1\n", "the PCD header ends before its DATA line"},
           {"FIELDS " + std::string(5000, 'x'), "PCD header line 1: longer than 1000 bytes, or a control byte"},
           {"FIELDS x y\x1bz\n", "PCD header line 1: longer than 1000 bytes, or a control byte"}}) {
    const auto file = writeFile("header.pcd", header);
    EXPECT_NE(cloudRefusal(file).find(file.string() + ": not a readable point cloud (" + message), std::string::npos)
        << cloudRefusal(file);
  }
  const auto grid = writeFile("grid.pcd", fields + "WIDTH 2\nHEIGHT 1\nPOINTS 3\nDATA ascii\n");
  EXPECT_EQ(cloudRefusal(grid),
            grid.string() + ": not a readable point cloud (the PCD header's POINTS 3 is not WIDTH x HEIGHT (2 x 1))");
}

TEST(Open3dInputChecks, RefusesPlyFacesAndCountsOpen3dWouldMisread) {
  // A face of no corners crashed Open3D's ear clipping (the fuzzer's crash); two corners read past
  // the list, a missing vertex past the vertices.
  for (const auto& [face, message] : std::initializer_list<std::pair<std::string, std::string>>{
           {"0\n", "the PLY's face element, record 0: a face of 0 corners (3 to 255)"},
           {"2 0 1\n", "the PLY's face element, record 0: a face of 2 corners (3 to 255)"},
           {"4 0 1 2 900000\n", "the PLY's face element, record 0: a face names vertex 900000 of 3"},
           {"3 0 1 -1\n", "the PLY's face element, record 0: a face names vertex -1 of 3"},
           {"3 0 1\n", "the PLY's face element announces 1 record; the file ends in record 0"},
           {"3 0 1 x\n", "the PLY's face element, record 0: a vertex index that is no whole number"},
           {"3 0 1 2\n0 0 0\n",
            "data after the last element its header announces; do the header's element counts match the data?"}}) {
    const auto file = writeFile("face.ply", kPlyTriangleHeader + face);
    EXPECT_EQ(meshRefusal(file), file.string() + ": not a readable mesh (" + message + ")");
    EXPECT_EQ(cloudRefusal(file), file.string() + ": not a readable point cloud (" + message + ")");
  }
  const auto huge = writeFile("huge.ply",
                              "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\n"
                              "property float x\nproperty float y\nproperty float z\nend_header\n");
  EXPECT_EQ(cloudRefusal(huge), huge.string() +
                                    ": not a readable point cloud (the PLY's vertex element announces "
                                    "2000000000 records of 12 bytes, more than the file's remaining 0 bytes hold)");
  const auto tail = writeFile("tail.ply",
                              "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
                              "property float y\nproperty float z\nend_header\n" +
                                  std::string(13, '\0'));
  EXPECT_EQ(cloudRefusal(tail), tail.string() +
                                    ": not a readable point cloud (data after the last element its header "
                                    "announces; do the header's element counts match the data?)");
  const auto scalar =
      writeFile("scalar.ply",
                "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                "property float z\nelement face 1\nproperty int vertex_indices\nend_header\n0 0 0\n0\n");
  EXPECT_EQ(
      meshRefusal(scalar),
      scalar.string() + ": not a readable mesh (the PLY's face element, record 0: vertex_indices must be a list)");
  const auto crlf =
      writeFile("crlf.ply", "ply\r\nformat binary_little_endian 1.0\r\nelement vertex 0\r\nend_header\r\n");
  EXPECT_EQ(meshRefusal(crlf), crlf.string() + ": not a readable mesh (PLY header line 4: give 'end_header' alone)");
  // Its one row present, so that the header's list type is the file's only fault.
  const auto list_type =
      writeFile("list.ply",
                "ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\nend_header\n3 0 1 2\n");
  EXPECT_NE(meshRefusal(list_type).find("PLY header line 4: give 'property TYPE NAME'"), std::string::npos);
}

TEST(Open3dInputChecks, APropertyLineWithoutTypeOrNameIsRefused) {
  // "property" with nothing after it was read past the line's words (a crash, found by mutating
  // the PLY seed).
  for (const std::string line : {"property", "property ", "property float"}) {
    const auto file = writeFile("property.ply", "ply\nformat ascii 1.0\nelement vertex 8\n" + line);
    EXPECT_EQ(meshRefusal(file), file.string() +
                                     ": not a readable mesh (PLY header line 4: give 'property TYPE NAME' "
                                     "or 'property list COUNT_TYPE TYPE NAME' with PLY's types, an integer "
                                     "count)")
        << line;
  }
}

TEST(Open3dInputChecks, WellFormedFilesStillRead) {
  for (const auto& [seed, points] :
       std::initializer_list<std::pair<const char*, std::size_t>>{{"pcd/ascii.pcd", 8},
                                                                  {"pcd/binary.pcd", 8},
                                                                  {"pcd/compressed.pcd", 8},
                                                                  {"pcd/organised.pcd", 4},
                                                                  {"ply/points.ply", 8}})
    EXPECT_EQ(readPointCloud(kSource / "tests/io/fuzz_seeds" / seed).size(), points) << seed;
  for (const char* seed : {"ply/box.ply", "ply/box_binary.ply"})
    EXPECT_EQ(readTriangleMesh(kSource / "tests/io/fuzz_seeds" / seed).triangles.size(), 12u) << seed;  // quads split
  const auto triangle = writeFile("triangle.ply", kPlyTriangleHeader + "3 0 1 2\n");
  EXPECT_EQ(readTriangleMesh(triangle).triangles.size(), 1u);
}

}  // namespace
}  // namespace ceilplan::io
