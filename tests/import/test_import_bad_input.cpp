// `ceilplan import` refuses bad input with one line, the documented exit code, and no output
// left behind (an earlier map of the same name stays as it was).

#include "run_command.hpp"
#include "scan_files.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <fstream>
#include <string>

namespace ceilplan {
namespace {

// `text` with `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  return text.replace(text.find(from), from.size(), to);
}

// docs/cli.md: bad input exits with 1 today (2 once bad input and usage share a code); usage
// errors (flags) with 2. Change here when the codes change.
constexpr int kBadInputExit = 2;
constexpr int kUsageExit = 2;

class ImportBadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::scratchDirectory(::testing::UnitTest::GetInstance()->current_test_info()->name());
    out_ = dir_ / "map.bt";
    std::ofstream(out_) << "an earlier map";
    testing::writePcd(dir_ / "good.pcd", testing::sampleBoxSurface({0, 0, 0}, {2, 2, 2}, 0.1), false);
    testing::writeStlBinary(dir_ / "good.stl", testing::boxMesh({0, 0, 0}, {2, 2, 2}));
  }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // Runs `import ARGUMENTS --out map.bt` (plus --resolution 0.1 unless given) and checks the refusal.
  void expectRefused(const std::string& arguments, const std::string& message, int exit_code = kBadInputExit) {
    std::string command = "import " + arguments + " --out " + out_.string();
    if (arguments.find("--resolution") == std::string::npos) command += " --resolution 0.1";
    const auto result = testing::runCeilplan(command, "timeout 60");  // a reader blocked on a FIFO fails, not hangs
    EXPECT_EQ(result.exit_code, exit_code) << command << "\n" << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_EQ(result.err.rfind("ceilplan: error: ", 0), 0u) << result.err;
    EXPECT_NE(result.err.find(message), std::string::npos) << "expected '" << message << "' in: " << result.err;
    EXPECT_EQ(result.out, "");
    EXPECT_EQ(testing::readWholeFile(out_), "an earlier map");
    EXPECT_FALSE(std::filesystem::exists(out_.string() + ".json"));
    for (const auto& entry : std::filesystem::directory_iterator(dir_))
      EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
  }

  std::filesystem::path dir_, out_;
};

TEST_F(ImportBadInput, MissingFiles) {
  expectRefused("--points " + path("nothing.pcd"), "nothing.pcd: no such point cloud file");
  expectRefused("--mesh " + path("nothing.stl"), "nothing.stl: no such mesh file");
  expectRefused("--points " + path("good.pcd") + " --origins " + path("nothing.csv"), "nothing.csv: no such CSV file");
}

TEST_F(ImportBadInput, CorruptFiles) {
  std::ofstream(dir_ / "garbage.pcd") << "this is not a point cloud\n";
  expectRefused("--points " + path("garbage.pcd"), "garbage.pcd: not a readable point cloud");
  std::ofstream(dir_ / "truncated.pcd")
      << "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1000\n"
         "HEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 1000\nDATA binary\n0123456789ab";
  expectRefused("--points " + path("truncated.pcd"), "truncated.pcd: not a readable point cloud");
  std::ofstream(dir_ / "truncated.ply")
      << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nend_header\n0 0 0\n1 0 0\n";
  expectRefused("--points " + path("truncated.ply"),
                "truncated.ply: not a readable point cloud (the PLY's vertex element announces 3 records; the file "
                "ends in record 2)");
  std::ofstream(dir_ / "truncated.stl", std::ios::binary)
      << std::string(80, ' ') << std::string("\x64\0\0\0", 4) << "short";
  expectRefused("--mesh " + path("truncated.stl"), "truncated.stl: not a readable mesh");
  std::ofstream(dir_ / "bad_index.obj") << "v 0 0 0\nv 1 0 0\nf 1 2 7\n";
  expectRefused("--mesh " + path("bad_index.obj"), "bad_index.obj: not a readable mesh");
  // Open3D would read these coordinates as zeros.
  testing::writePcd(dir_ / "doubles.pcd", {{500000.5, 5400000.5, 480.0}, {500001.5, 5400000.5, 480.0}}, true, true);
  expectRefused("--points " + path("doubles.pcd"), "doubles.pcd: binary PCD with 8-byte coordinates");
}

// What Open3D would import wrong without a word: a PCD whose WIDTH x HEIGHT or rows disagree
// with its POINTS, a PLY whose rows or bytes disagree with its element counts, an .xyz line it
// cannot read (it skips it), and a mesh whose faces all have zero area.
TEST_F(ImportBadInput, HeaderCountsThatDisagreeWithTheDataAndLinesThatAreNotPoints) {
  const std::string pcd = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  const struct {
    std::string flag, file, text, says;
  } rows[] = {
      {"--points", "grid.pcd", pcd + "WIDTH 2\nHEIGHT 2\nPOINTS 3\nDATA ascii\n1 2 3\n2 3 4\n3 4 5\n",
       "grid.pcd: not a readable point cloud (the PCD header's POINTS 3 is not WIDTH x HEIGHT (2 x 2))"},
      {"--points", "rows.pcd", pcd + "WIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\n1 2 3\n2 3 4\n3 4 5\n",
       "rows.pcd: not a readable point cloud (the ascii PCD announces 2 points but holds more rows (line 12))"},
      {"--points", "nopoints.pcd", pcd + "WIDTH 2\nHEIGHT 1\nDATA ascii\n1 2 3\n2 3 4\n",
       "nopoints.pcd: not a readable point cloud (the PCD header lacks FIELDS, WIDTH, HEIGHT or POINTS)"},
      {"--points", "more.ply", ply + "end_header\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n",
       "more.ply: not a readable point cloud (data after the last element its header announces; do the header's "
       "element counts match the data?)"},
      {"--points", "short.ply", replaced(ply, "ascii", "binary_little_endian") + "end_header\n" + std::string(24, '\0'),
       "short.ply: not a readable point cloud (the PLY's vertex element announces 3 records of 12 bytes, more than the "
       "file's remaining 24 bytes hold)"},
      {"--points", "long.ply", replaced(ply, "ascii", "binary_little_endian") + "end_header\n" + std::string(48, '\0'),
       "long.ply: not a readable point cloud (data after the last element its header announces"},
      {"--points", "huge.ply",
       replaced(replaced(ply, "ascii", "binary_little_endian"), "vertex 3", "vertex 99999999999999") + "end_header\n" +
           std::string(24, '\0'),
       "huge.ply: not a readable point cloud (PLY header line 3: give 'element NAME COUNT', COUNT a whole number up to "
       "2147483647)"},
      {"--mesh", "faces.ply",
       ply + "element face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
       "faces.ply: not a readable mesh (the PLY's face element announces 2 records; the file ends in record 1)"},
      {"--points", "words.xyz", "0 0 0\n1 0 0\n\n0 0 one\n",
       "words.xyz: not a readable point cloud (line 4: '0 0 one' is not 3 numbers; fix or delete the line)"},
      {"--points", "two.xyz", "0 0 0\n1 0\n", "two.xyz: not a readable point cloud (line 2: '1 0' is not 3 numbers"},
      {"--points", "letters.xyz", "0 0 0\n1 0 x 0\n",
       "letters.xyz: not a readable point cloud (line 2: '1 0 x 0' is not 3 numbers"},
      {"--points", "normals.xyzn", "0 0 0 0 0 1\n1 0 0 0 0\n",
       "normals.xyzn: not a readable point cloud (line 2: '1 0 0 0 0' is not 6 numbers"},
      {"--mesh", "flat.obj", "v 0 0 0\nv 1 1 1\nv 2 2 2\nv 0 1 0\nf 1 2 3\nf 4 4 4\n",
       "flat.obj: all 2 triangles of the mesh have zero area (collinear or repeated corners); export the mesh again "
       "with its faces"},
  };
  for (const auto& row : rows) {
    std::ofstream(dir_ / row.file, std::ios::binary) << row.text;
    expectRefused(row.flag + " " + path(row.file), row.says);
  }
}

// A FIFO would block the reader that opens it, a device never end: each is refused before it is
// opened (the timeout makes a reader that blocks fail the test rather than hang it).
TEST_F(ImportBadInput, FifosDevicesAndDirectoriesAreNotInputFiles) {
  for (const char* name : {"pipe.xyz", "pipe.pcd", "pipe.stl", "pipe.csv", "pipe.bin"})
    ASSERT_EQ(::mkfifo((dir_ / name).c_str(), 0600), 0) << name;
  std::filesystem::create_directories(dir_ / "folder.ply");
  // A glTF scene names its buffer files; assimp opens them itself.
  std::ofstream(dir_ / "buffer.gltf")
      << R"({"asset":{"version":"2.0"},"buffers":[{"uri":"pipe.bin","byteLength":12}],)"
         R"("bufferViews":[{"buffer":0,"byteLength":12}],"accessors":[{"bufferView":0,)"
         R"("componentType":5126,"count":1,"type":"VEC3"}],"meshes":[{"primitives":)"
         R"([{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]})";
  const struct {
    std::string arguments, says;
  } rows[] = {
      {"--points " + path("pipe.xyz"), "pipe.xyz: is a FIFO (named pipe), not a point cloud file; give a regular file"},
      {"--points " + path("pipe.pcd"), "pipe.pcd: is a FIFO (named pipe), not a point cloud file"},
      {"--mesh " + path("pipe.stl"), "pipe.stl: is a FIFO (named pipe), not a mesh file"},
      {"--mesh " + path("buffer.gltf"),
       "buffer.gltf: not a readable mesh (" + path("pipe.bin") + ": is a FIFO (named pipe)"},
      {"--points " + path("good.pcd") + " --origins " + path("pipe.csv"),
       "pipe.csv: is a FIFO (named pipe), not a CSV file"},
      {"--points " + path("folder.ply"), "folder.ply: is a directory, not a point cloud file"},
      {"--mesh " + path("folder.ply"), "folder.ply: is a directory, not a mesh file"},
  };
  for (const auto& row : rows) expectRefused(row.arguments, row.says);
}

TEST_F(ImportBadInput, WrongKindOfFile) {
  expectRefused("--points " + path("good.stl"), "good.stl: .stl is a mesh format, not a point cloud");
  expectRefused("--mesh " + path("good.pcd"), "good.pcd: .pcd is a point-cloud format, not a mesh");
  std::ofstream(dir_ / "scan.las") << "LASF";
  expectRefused("--points " + path("scan.las"), "unknown point cloud format '.las'");
  testing::writePlyPoints(dir_ / "cloud.ply", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  expectRefused("--mesh " + path("cloud.ply"), "the mesh has no triangles (only vertices: a point cloud?)");
  expectRefused("--points " + path("good.pcd") + " --out-of-nowhere 3", "out-of-nowhere", kUsageExit);
  expectRefused("--points " + path("good.pcd") + " --mesh " + path("good.stl"), "Exactly 1 option", kUsageExit);
  expectRefused("--mesh " + path("good.stl") + " --origins " + path("good.csv"), "--origins requires --points",
                kUsageExit);
}

TEST_F(ImportBadInput, EmptyClouds) {
  testing::writePlyPoints(dir_ / "empty.ply", {});
  expectRefused("--points " + path("empty.ply"),
                "empty.ply: not a readable point cloud");  // Open3D: "number of vertex <= 0"
  testing::writePcd(dir_ / "empty.pcd", {}, false);
  expectRefused("--points " + path("empty.pcd"), "empty.pcd: not a readable point cloud");
}

TEST_F(ImportBadInput, NonFiniteCoordinates) {
  std::ofstream(dir_ / "nan.pcd")
      << "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 3\nHEIGHT 1\n"
         "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 3\nDATA ascii\n1 2 3\nnan nan nan\n2 3 4\n";
  expectRefused("--points " + path("nan.pcd"), "nan.pcd: point 1 (counting from 0) has a non-finite coordinate");
  const auto result = testing::runCeilplan("import --points " + path("nan.pcd") +
                                           " --skip-non-finite --resolution 0.1 --out " + path("skipped.bt"));
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("skipped_non_finite_points: 1"), std::string::npos) << result.out;
  std::ofstream(dir_ / "nan_origin.csv") << "x,y,z\n1,nan,1\n";
  expectRefused("--points " + path("good.pcd") + " --origins " + path("nan_origin.csv"), "nan_origin.csv");
}

TEST_F(ImportBadInput, ResolutionsOutOfRangeAndBoxesTooLarge) {
  for (const std::string resolution : {"0", "-0.1", "0.001", "5", "nan"})
    expectRefused("--points " + path("good.pcd") + " --resolution " + resolution, "--resolution");
  testing::writePlyPoints(dir_ / "far.ply", {{0, 0, 0}, {1500, 1500, 100}});
  expectRefused("--points " + path("far.ply") + " --resolution 0.05", "more than ceilplan indexes");
  expectRefused("--points " + path("far.ply") + " --resolution 0.01", "beyond what OctoMap holds");
  std::ofstream(dir_ / "one.csv") << "x,y,z\n1,1,1\n";
  expectRefused("--points " + path("good.pcd") + " --max-range -1 --origins " + path("one.csv"), "--max-range -1");
  expectRefused("--mesh " + path("good.stl") + " --margin -1", "margin -1 m");
  expectRefused("--mesh " + path("good.stl") + " --interior porous", "unknown mesh interior 'porous'");
  expectRefused("--points " + path("good.pcd") + " --free-region hull",
                "unknown free region 'hull': use between or box");
}

TEST_F(ImportBadInput, OriginsThatDoNotFitTheCloud) {
  std::ofstream(dir_ / "three.csv") << "x,y,z\n1,1,1\n1,1,1\n1,1,1\n";
  expectRefused("--points " + path("good.pcd") + " --origins " + path("three.csv"), "3 rows of x,y,z for");
  std::ofstream(dir_ / "late.csv") << "first_point,x,y,z\n5,1,1,1\n";
  expectRefused("--points " + path("good.pcd") + " --origins " + path("late.csv"),
                "the first scan must start at point 0");
  std::ofstream(dir_ / "columns.csv") << "a,b,c\n1,1,1\n";
  expectRefused("--points " + path("good.pcd") + " --origins " + path("columns.csv"), "no column 'x'");
  std::ofstream(dir_ / "words.csv") << "x,y,z\none,1,1\n";
  expectRefused("--points " + path("good.pcd") + " --origins " + path("words.csv"), "words.csv");
}

TEST_F(ImportBadInput, CoordinateReferenceSystems) {
  expectRefused("--points " + path("good.pcd") + " --crs EPSG:999999",
                "unknown coordinate reference system EPSG:999999");
  expectRefused("--points " + path("good.pcd") + " --crs EPSG:4326", "is not a projected coordinate reference system");
  expectRefused("--points " + path("good.pcd") + " --crs utm32", "expected EPSG:<code>");
  expectRefused("--points " + path("nothing.pcd") + " --crs EPSG:999999", "EPSG:999999");  // the CRS is checked first
}

TEST_F(ImportBadInput, OutputThatIsNotABtFile) {
  const auto result =
      testing::runCeilplan("import --points " + path("good.pcd") + " --resolution 0.1 --out " + path("map.ot"));
  EXPECT_EQ(result.exit_code, kBadInputExit);
  EXPECT_NE(result.err.find("must end in .bt"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "map.ot"));
}

}  // namespace
}  // namespace ceilplan
