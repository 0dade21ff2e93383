#include "ceilplan/io/map_import.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/io/atomic_file.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/mesh_file.hpp"
#include "ceilplan/io/octomap_file.hpp"
#include "ceilplan/io/point_cloud_file.hpp"

#include <cmath>
#include <fstream>
#include <memory>

namespace ceilplan::io {
namespace {

namespace env = environment;

void requireFiniteOrSkip(std::vector<Eigen::Vector3d>& points, env::SensorOrigins* origins, bool skip,
                         const std::string& file, std::size_t& skipped) {
  if (skip) {
    skipped = env::dropNonFinitePoints(points, origins);
    if (points.empty()) throw InputError(file + ": no point has finite coordinates");
    return;
  }
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!points[i].allFinite())
      throw InputError(file + ": point " + std::to_string(i) + " (counting from 0) has a non-finite coordinate " +
                       formatPoint(points[i]) +
                       "; organised clouds mark missing returns this way: pass --skip-non-finite to drop them");
}

env::BuiltMap build(const MapImportOptions& options, const std::vector<Eigen::Vector3d>& points,
                    const env::TriangleMesh& mesh, const std::optional<env::SensorOrigins>& origins,
                    const std::function<void(double)>& report) {
  if (!options.mesh.empty()) {
    env::MeshVoxelisingOptions mesh_options;
    mesh_options.resolution_m = options.resolution_m;
    mesh_options.margin_m = options.margin_m.value_or(kMeshMargin_m);
    mesh_options.interior = env::meshInteriorFromName(options.interior);
    mesh_options.crop_m = options.crop_m.value_or(env::CropBox());
    return env::mapFromMesh(mesh, mesh_options, report);
  }
  if (origins) {
    env::RayCarvingOptions carving;
    carving.resolution_m = options.resolution_m;
    carving.max_range_m = options.max_range_m;
    carving.crop_m = options.crop_m.value_or(env::CropBox());
    return env::carveFromScans(points, *origins, carving, report);
  }
  env::PointAssumptionOptions assumption;
  assumption.resolution_m = options.resolution_m;
  assumption.free_distance_m = options.free_distance_m.value_or(2.0 * options.resolution_m);
  assumption.region = env::assumedFreeRegionFromName(options.free_region);
  assumption.margin_m = options.margin_m.value_or(0.0);
  assumption.crop_m = options.crop_m.value_or(env::CropBox());
  return env::mapFromPointsAlone(points, assumption, report);
}

nlohmann::json pointJson(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

}  // namespace

void MapImportOptions::validate() const {
  if (points.empty() == mesh.empty()) throw InputError("give a point cloud or a mesh to import, one of the two");
  if (!origins.empty() && points.empty()) throw InputError("sensor origins go with a point cloud, not a mesh");
  if (!(resolution_m >= env::kMinImportResolution_m && resolution_m <= env::kMaxImportResolution_m))
    throw InputError("an import resolution of " + formatNumber(resolution_m) + " m is outside " +
                     formatNumber(env::kMinImportResolution_m) + " to " + formatNumber(env::kMaxImportResolution_m) +
                     " m");
  if (!std::isfinite(max_range_m) || max_range_m < 0.0)
    throw InputError("a maximum range of " + formatNumber(max_range_m) + " m: give a finite number >= 0 (0: none)");
  env::meshInteriorFromName(interior);
  env::assumedFreeRegionFromName(free_region);
  if (crop_m) {
    if (crop_m->min() == env::CropBox().min() && crop_m->max() == env::CropBox().max())
      throw InputError("a crop box must have corners; leave it out for no crop");
    env::validateCrop(*crop_m);
  }
  if (!crs.empty()) ProjectedFrame::validate(crs);
}

MapImport importMap(const MapImportOptions& options, const ProgressCallback& progress) {
  options.validate();
  MapImport imported;
  imported.from_mesh = !options.mesh.empty();
  imported.source = imported.from_mesh ? options.mesh : options.points;

  // Read, and the origins with the cloud.
  std::vector<Eigen::Vector3d> points;
  env::TriangleMesh mesh;
  std::optional<env::SensorOrigins> origins;
  if (imported.from_mesh) {
    mesh = readTriangleMesh(options.mesh);
  } else {
    points = readPointCloud(options.points);
    if (!options.origins.empty()) origins = readSensorOrigins(options.origins, points.size());
    requireFiniteOrSkip(points, origins ? &*origins : nullptr, options.skip_non_finite, options.points.string(),
                        imported.skipped_non_finite_points);
  }

  // Projected coordinates into the local frame, origins moved alike.
  if (!options.crs.empty()) {
    std::vector<Eigen::Vector3d>& coordinates = imported.from_mesh ? mesh.vertices_m : points;
    const ProjectedFrame frame(options.crs, ProjectedFrame::originNear(coordinates));
    frame.toLocal(coordinates);
    if (origins) frame.toLocal(origins->origin_m);
    imported.frame = ImportedFrame{frame.crs(), frame.crsName(), frame.originProjected(), frame.origin()};
  }

  const std::string stage = "importing " + imported.source.string();
  imported.built = build(options, points, mesh, origins, [&](double fraction) {
    if (progress) progress(stage, fraction);
  });
  // The const overloads: they walk the leaves, where the others round cached key bounds.
  const octomap::OcTree& tree = *imported.built.tree;
  double x0, y0, z0, x1, y1, z1;
  tree.getMetricMin(x0, y0, z0);
  tree.getMetricMax(x1, y1, z1);
  imported.extent_m = Eigen::AlignedBox3d(Eigen::Vector3d(x0, y0, z0), Eigen::Vector3d(x1, y1, z1));
  return imported;
}

nlohmann::json mapImportJson(const MapImport& imported, const MapImportOptions& options,
                             const std::filesystem::path& map_file) {
  nlohmann::json figures = nlohmann::json::object();
  for (const auto& [name, value] : imported.built.figures) figures[name] = value;
  nlohmann::json summary = {
      {"map", map_file.filename().string()},
      {"source", imported.source.string()},
      {"kind", imported.from_mesh ? "mesh" : "points"},
      {"origins", options.origins.empty() ? nlohmann::json(nullptr) : nlohmann::json(options.origins.string())},
      {"resolution_m", options.resolution_m},
      {"free_space", imported.built.free_space},
      {"crop_m", options.crop_m ? nlohmann::json{{"min", pointJson(options.crop_m->min())},
                                                 {"max", pointJson(options.crop_m->max())}}
                                : nlohmann::json(nullptr)},
      {"skipped_non_finite_points", imported.skipped_non_finite_points},
      {"extent_m", {{"min", pointJson(imported.extent_m.min())}, {"max", pointJson(imported.extent_m.max())}}},
      {"figures", figures},
      {"crs", nullptr}};
  if (imported.frame) {
    const ImportedFrame& frame = *imported.frame;
    summary["crs"] = {
        {"code", frame.crs},
        {"name", frame.crs_name},
        {"local_origin_in_crs", pointJson(frame.origin_projected)},
        {"origin",
         {{"lat", frame.origin.latitude_deg}, {"lon", frame.origin.longitude_deg}, {"alt", frame.origin.altitude_m}}}};
  }
  return summary;
}

void writeImportedMap(const std::filesystem::path& map_file, const MapImport& imported, const MapImportOptions& options,
                      const Provenance& provenance, std::filesystem::path summary_file) {
  if (map_file.extension() != ".bt")
    throw InputError(printableText(map_file.string(), 256) + ": an imported map is written as .bt");
  const nlohmann::json summary = withProvenance(mapImportJson(imported, options, map_file), provenance);
  if (summary_file.empty()) (summary_file = map_file) += ".json";
  writeAtomically(map_file, [&](const std::filesystem::path& temporary) {
    std::ofstream file(temporary, std::ios::binary);
    writeOctoMapBinary(*imported.built.tree, file, map_file);
    // The summary goes in while the map is still temporary: neither is left behind alone on failure.
    writeJsonFile(summary_file, summary);
  });
}

}  // namespace ceilplan::io
