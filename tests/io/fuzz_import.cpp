// libFuzzer target for one import format, CEILPLAN_FUZZ_EXTENSION (".pcd", ".ply", ".xyz", ".stl" or
// ".obj"; the build makes one target per format): any bytes in such a file give points or a mesh, or a
// ceilplan::Error; never a crash, a hang, a leak or another exception. A .ply goes through both
// readers, as `ceilplan import` takes it as a cloud or a mesh. What the mesh reader accepts, the
// map builder must take or refuse in words; it runs on small meshes only (a coarse map of at most
// 8 m a side), so each input stays quick. Clouds are read only: the cloud builder's distance field
// waits at least 100 ms per pass (parallelFor's progress loop), which would leave a few inputs a
// second. Build and run: scripts/fuzz-import-pcd and the like.

#include "fuzz_support.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/environment/map_builder.hpp"
#include "ceilplan/io/mesh_file.hpp"
#include "ceilplan/io/point_cloud_file.hpp"

#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace {

namespace env = ceilplan::environment;

// Larger meshes are read only: building their maps would take most of the run.
constexpr double kMaxBuildExtent_m = 8.0;
constexpr std::size_t kMaxBuildTriangles = 4096;
constexpr double kBuildResolution_m = 0.5;

bool smallEnough(const std::vector<Eigen::Vector3d>& vertices_m) {
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& v : vertices_m) box.extend(v);
  return box.sizes().maxCoeff() <= kMaxBuildExtent_m;
}

void readCloud(const std::filesystem::path& file) {
  try {
    std::vector<Eigen::Vector3d> points = ceilplan::io::readPointCloud(file);
    env::dropNonFinitePoints(points, nullptr);  // as `import --skip-non-finite`
  } catch (const ceilplan::Error&) {
  }
}

void readMesh(const std::filesystem::path& file) {
  try {
    const env::TriangleMesh mesh = ceilplan::io::readTriangleMesh(file);
    if (mesh.triangles.size() > kMaxBuildTriangles || !smallEnough(mesh.vertices_m)) return;
    env::MeshVoxelisingOptions options;
    options.resolution_m = kBuildResolution_m;
    env::mapFromMesh(mesh, options);
  } catch (const ceilplan::Error&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string extension = CEILPLAN_FUZZ_EXTENSION;
  const std::filesystem::path file = ceilplan::fuzzing::inputFile(data, size, ("input" + extension).c_str());
  if (extension != ".stl" && extension != ".obj") readCloud(file);
  if (extension != ".pcd" && extension != ".xyz") readMesh(file);
  return 0;
}
