// `ceilplan import`: an OctoMap (.bt) from a point cloud (with or without sensor origins) or a
// mesh, optionally moved from a projected CRS into a local frame (docs/import.md).

#include "command_registry.hpp"
#include "output.hpp"

#include "ceilplan/environment/map_builder.hpp"
#include "ceilplan/io/mesh_file.hpp"
#include "ceilplan/io/octomap_file.hpp"
#include "ceilplan/io/point_cloud_file.hpp"
#include "ceilplan/io/projected_frame.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>

namespace ceilplan::app {
namespace {

struct ImportOptions {
  std::string points;
  std::string origins;
  std::string mesh;
  double resolution_m = 0.0;
  std::string out;
  std::string crs;
  double max_range_m = 0.0;
  std::optional<double> free_distance_m;  // default: two voxels
  std::optional<double> margin_m;         // default: 1 m for a mesh, 0 for a cloud
  std::string interior = "auto";
  bool skip_non_finite = false;
};

constexpr double kMeshMargin_m = 1.0;

void requireFiniteOrSkip(std::vector<Eigen::Vector3d>& points, environment::SensorOrigins* origins, bool skip,
                         const std::string& file, std::size_t& skipped) {
  if (skip) {
    skipped = environment::dropNonFinitePoints(points, origins);
    if (points.empty()) throw ceilplan::InputError(file + ": no point has finite coordinates");
    return;
  }
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!points[i].allFinite())
      throw ceilplan::InputError(file + ": point " + std::to_string(i) + " (counting from 0) has a non-finite coordinate " +
                                 formatPoint(points[i]) + "; organised clouds mark missing returns this way: pass --skip-non-finite to drop them");
}

void runImport(const ImportOptions& options) {
  namespace env = environment;
  const std::filesystem::path out(options.out);
  if (out.extension() != ".bt") throw ceilplan::InputError("--out " + options.out + ": the map file must end in .bt");
  checkWritableFile(out);  // before the cloud is read
  if (!(options.resolution_m >= env::kMinImportResolution_m && options.resolution_m <= env::kMaxImportResolution_m))
    throw ceilplan::InputError("--resolution " + formatNumber(options.resolution_m) + ": use " +
                               formatNumber(env::kMinImportResolution_m) + " to " + formatNumber(env::kMaxImportResolution_m) + " m");
  if (!std::isfinite(options.max_range_m) || options.max_range_m < 0.0)
    throw ceilplan::InputError("--max-range " + formatNumber(options.max_range_m) + ": a finite number of metres >= 0 (0: none)");
  const env::MeshInterior interior = env::meshInteriorFromName(options.interior);
  if (!options.crs.empty()) io::ProjectedFrame::validate(options.crs);
  const bool from_mesh = !options.mesh.empty();
  const std::string source = from_mesh ? options.mesh : options.points;

  // Read, and the origins with the cloud.
  std::vector<Eigen::Vector3d> points;
  env::TriangleMesh mesh;
  std::optional<env::SensorOrigins> origins;
  std::size_t skipped = 0;
  if (from_mesh) {
    mesh = io::readTriangleMesh(options.mesh);
  } else {
    points = io::readPointCloud(options.points);
    if (!options.origins.empty()) origins = io::readSensorOrigins(options.origins, points.size());
    requireFiniteOrSkip(points, origins ? &*origins : nullptr, options.skip_non_finite, options.points, skipped);
  }
  std::vector<Eigen::Vector3d>& coordinates = from_mesh ? mesh.vertices_m : points;

  // Projected coordinates into the local frame, origins moved alike.
  std::unique_ptr<io::ProjectedFrame> frame;
  if (!options.crs.empty()) {
    frame = std::make_unique<io::ProjectedFrame>(options.crs, io::ProjectedFrame::originNear(coordinates));
    frame->toLocal(coordinates);
    if (origins) frame->toLocal(origins->origin_m);
  }

  Progress progress("importing " + source);
  const auto report = [&](double f) { progress.update(f); };
  env::BuiltMap built;
  if (from_mesh) {
    env::MeshVoxelisingOptions mesh_options;
    mesh_options.resolution_m = options.resolution_m;
    mesh_options.margin_m = options.margin_m.value_or(kMeshMargin_m);
    mesh_options.interior = interior;
    built = env::mapFromMesh(mesh, mesh_options, report);
  } else if (origins) {
    env::RayCarvingOptions carving;
    carving.resolution_m = options.resolution_m;
    carving.max_range_m = options.max_range_m;
    built = env::carveFromScans(points, *origins, carving, report);
  } else {
    env::PointAssumptionOptions assumption;
    assumption.resolution_m = options.resolution_m;
    assumption.free_distance_m = options.free_distance_m.value_or(2.0 * options.resolution_m);
    assumption.margin_m = options.margin_m.value_or(0.0);
    built = env::mapFromPointsAlone(points, assumption, report);
  }
  progress.finish();

  const octomap::OcTree& tree = *built.tree;
  double x0, y0, z0, x1, y1, z1;
  tree.getMetricMin(x0, y0, z0);
  tree.getMetricMax(x1, y1, z1);
  nlohmann::json figures = nlohmann::json::object();
  for (const auto& [name, value] : built.figures) figures[name] = value;
  nlohmann::json sidecar = {
      {"map", out.filename().string()},
      {"source", source},
      {"kind", from_mesh ? "mesh" : "points"},
      {"origins", options.origins.empty() ? nlohmann::json(nullptr) : nlohmann::json(options.origins)},
      {"resolution_m", options.resolution_m},
      {"free_space", built.free_space},
      {"skipped_non_finite_points", skipped},
      {"extent_m", {{"min", {x0, y0, z0}}, {"max", {x1, y1, z1}}}},
      {"figures", figures},
      {"crs", nullptr}};
  if (frame) {
    const io::GeodeticOrigin& origin = frame->origin();
    const Eigen::Vector3d& at = frame->originProjected();
    sidecar["crs"] = {{"code", frame->crs()},
                      {"name", frame->crsName()},
                      {"local_origin_in_crs", {at.x(), at.y(), at.z()}},
                      {"origin", {{"lat", origin.lat_deg}, {"lon", origin.lon_deg}, {"alt", origin.alt_m}}}};
  }

  std::filesystem::path sidecar_path = out;
  sidecar_path += ".json";
  writeAtomically(out, [&](const std::filesystem::path& temporary) {
    std::ofstream file(temporary, std::ios::binary);
    io::writeOctoMapBinary(tree, file);
    // The sidecar goes in while the map is still temporary: neither is left behind alone on failure.
    writeTextAtomically(sidecar_path, [&](std::ostream& text) { text << sidecar.dump(2) << '\n'; });
  });

  std::printf("import: %s -> %s\n", source.c_str(), out.string().c_str());
  std::printf("resolution_m: %s\n", formatNumber(options.resolution_m).c_str());
  if (skipped > 0) std::printf("skipped_non_finite_points: %zu\n", skipped);
  for (const auto& [name, value] : built.figures)
    std::printf("%s: %s\n", name.c_str(), formatNumber(value, value == std::floor(value) ? 15 : 6).c_str());
  std::printf("free_space: %s\n", built.free_space.c_str());
  std::printf("extent_m: %s to %s\n", formatPoint({x0, y0, z0}).c_str(), formatPoint({x1, y1, z1}).c_str());
  if (frame) {
    const io::GeodeticOrigin& origin = frame->origin();
    const Eigen::Vector3d& at = frame->originProjected();
    std::printf("crs: %s (%s); local origin at %s in it\n", frame->crs().c_str(), frame->crsName().c_str(),
                formatPoint(at, 3).c_str());
    std::printf("origin: {lat: %s, lon: %s, alt: %s}   # for the mission file\n", formatFixed(origin.lat_deg, 8).c_str(),
                formatFixed(origin.lon_deg, 8).c_str(), formatFixed(origin.alt_m, 3).c_str());
  }
  std::printf("wrote %s (%zu octree nodes, %ju bytes) and %s\n", out.string().c_str(), tree.size(),
              static_cast<std::uintmax_t>(std::filesystem::file_size(out)), sidecar_path.string().c_str());
}

const CommandRegistration registration(19, [](CLI::App& parent) {
  auto options = std::make_shared<ImportOptions>();
  CLI::App* command = parent.add_subcommand(
      "import", "Build an OctoMap (.bt) from a point cloud or a mesh of your structure (docs/import.md)");
  CLI::Option_group* input = command->add_option_group("input", "What to import: one of");
  CLI::Option* points = input->add_option("--points", options->points,
                                          "Point cloud: " + io::pointCloudExtensions());
  input->add_option("--mesh", options->mesh, "Triangle mesh: " + io::meshExtensions());
  input->require_option(1);
  CLI::Option* origins = command->add_option(
      "--origins", options->origins,
      "CSV of sensor positions (x,y,z per point or for all, or first_point,x,y,z per scan): free space is carved by ray casting");
  origins->needs(points);
  command->add_option("--resolution", options->resolution_m, "Voxel size in metres")->required();
  command->add_option("--out", options->out, "Output map (.bt); a summary goes beside it in <out>.json")->required();
  command->add_option("--crs", options->crs,
                      "EPSG code of the data's projected CRS (e.g. EPSG:25832): moves them into a local east-north-up frame "
                      "and prints the geodetic origin for the mission file");
  command->add_option("--max-range", options->max_range_m, "With --origins: longest ray carved, in metres (0: no limit)")
      ->capture_default_str()
      ->needs(origins);
  command->add_option("--free-distance", options->free_distance_m,
                      "Without --origins: space farther than this from every point is free (default: two voxels)")
      ->needs(points)
      ->excludes(origins);
  command->add_option("--margin", options->margin_m,
                      "Known space beyond the data's bounding box, in metres (default: 1 for a mesh, 0 for a point cloud)");
  command->add_option("--interior", options->interior,
                      "Mesh: what the surface encloses: auto (solid, or free inside a closed inward-facing mesh), solid or hollow")
      ->capture_default_str();
  command->add_flag("--skip-non-finite", options->skip_non_finite, "Drop points with NaN or infinite coordinates instead of refusing them");
  command->callback([options] { runImport(*options); });
});

}  // namespace
}  // namespace ceilplan::app
