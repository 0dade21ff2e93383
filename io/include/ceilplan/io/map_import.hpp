#pragma once
/// @file
/// An OctoMap from what users have of their structure (docs/import.md): a point cloud with or
/// without the sensor origins it was seen from, or a triangle mesh, optionally in a projected
/// CRS moved into a local east-north-up frame; and the map written with its summary beside it.
/// What `ceilplan import` runs.

#include "ceilplan/core/progress.hpp"
#include "ceilplan/environment/map_builder.hpp"
#include "ceilplan/io/projected_frame.hpp"
#include "ceilplan/io/provenance.hpp"

#include <Eigen/Geometry>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>

namespace ceilplan::io {

inline constexpr double kMeshMargin_m = 1.0;  ///< known space around a mesh by default

/// What `ceilplan import` reads and how it builds the map (docs/import.md).
struct MapImportOptions {
  std::filesystem::path points;           ///< a point cloud (pointCloudExtensions()), or
  std::filesystem::path mesh;             ///< a triangle mesh (meshExtensions()): exactly one of the two
  std::filesystem::path origins;          ///< optional, with points: free space carved by ray casting
  double resolution_m = 0.1;              ///< voxel size of the map built
  std::string crs;                        ///< "EPSG:<code>" of the data's projected CRS; empty: local already
  double max_range_m = 0.0;               ///< with origins: the longest ray carved (0: no limit)
  std::optional<double> free_distance_m;  ///< without origins: default two voxels
  /// Without origins, where the assumption holds: environment::assumedFreeRegionFromName.
  std::string free_region = "between";
  std::optional<double> margin_m;  ///< default kMeshMargin_m for a mesh, 0 for a cloud
  std::string interior = "auto";   ///< a mesh's inside: environment::meshInteriorFromName
  bool skip_non_finite = false;    ///< drop points with NaN or infinite coordinates
  /// A box in map coordinates (after --crs): data outside it is dropped before voxelising, and the
  /// map goes no farther (environment::CropBox).
  std::optional<Eigen::AlignedBox3d> crop_m;

  /// Throws ceilplan::InputError, before any file is read, for no or two inputs, origins without
  /// a cloud, a resolution outside environment::kMin/kMaxImportResolution_m, a negative or
  /// non-finite maximum range, an unknown interior or free region, a bad CRS, or a crop box with a non-finite
  /// corner or a minimum not below its maximum.
  void validate() const;
};

/// The local frame a projected CRS was moved into.
struct ImportedFrame {
  std::string crs;                   ///< "EPSG:<code>" of the projected CRS
  std::string crs_name;              ///< the CRS's name, as PROJ gives it
  Eigen::Vector3d origin_projected;  ///< the local origin in the CRS's coordinates
  GeodeticOrigin origin;             ///< the same, geodetic: a mission file's `origin`
};

/// A map imported from a cloud or a mesh, with where it lies.
struct MapImport {
  std::filesystem::path source;               ///< the cloud or mesh read
  bool from_mesh = false;                     ///< the source was a mesh, not a cloud
  environment::BuiltMap built;                ///< the map built and how its free space was decided
  std::size_t skipped_non_finite_points = 0;  ///< points dropped for a NaN or infinite coordinate
  std::optional<ImportedFrame> frame;         ///< the local frame, when the data came in a projected CRS
  Eigen::AlignedBox3d extent_m;               ///< the map's metric bounds
};

/// Reads, moves into the local frame and builds the map; `progress` (optional) gets the stage
/// "importing <source>". Throws ceilplan::InputError for bad options or files (naming them), a
/// non-finite point unless skipped, and what the builders refuse.
MapImport importMap(const MapImportOptions& options, const ProgressCallback& progress = {});

/// The summary written beside the map: map (its file name), source, kind (points or mesh),
/// origins, resolution_m, free_space, skipped_non_finite_points, extent_m {min, max}, figures
/// and crs (null, or code, name, local_origin_in_crs and origin {lat, lon, alt}).
nlohmann::json mapImportJson(const MapImport& imported, const MapImportOptions& options,
                             const std::filesystem::path& map_file);

/// Writes `map_file` (.bt) and its summary (mapImportJson with `provenance`) to `summary_file`,
/// by default `<map_file>.json`, together: on any failure neither is left behind. Throws
/// ceilplan::InputError for a name not ending in .bt.
void writeImportedMap(const std::filesystem::path& map_file, const MapImport& imported, const MapImportOptions& options,
                      const Provenance& provenance, std::filesystem::path summary_file = {});

}  // namespace ceilplan::io
