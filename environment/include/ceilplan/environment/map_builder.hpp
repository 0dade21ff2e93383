#pragma once
/// @file
/// Builds an OctoMap occupancy tree from what users have of a structure: a point cloud with the
/// sensor positions it was seen from (free space carved by ray casting), a point cloud alone
/// (free space by a stated assumption), or a triangle mesh (surfaces voxelised, closed solids
/// filled). Every builder says, in one line, how it decided what is free: commands print it and
/// write it beside the map (docs/import.md).

#include "ceilplan/core/error.hpp"

#include <octomap/OcTree.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ceilplan::environment {

/// Accepted voxel sizes, in metres.
inline constexpr double kMinImportResolution_m = 0.01;
inline constexpr double kMaxImportResolution_m = 1.0;  ///< largest voxel size an import accepts

/// Where the sensor stood for each point: scan s covers points [first_point[s], first_point[s + 1])
/// (the last scan runs to the end of the cloud) and was taken from origin_m[s]. One scan per
/// point is the per-point form.
struct SensorOrigins {
  std::vector<std::size_t> first_point;   ///< index of each scan's first point, increasing from 0
  std::vector<Eigen::Vector3d> origin_m;  ///< each scan's sensor origin, map coordinates

  /// Checks the scans against a cloud of `point_count` points: first_point starts at 0, strictly
  /// increases and stays below point_count, origins are finite. Throws ceilplan::InputError
  /// naming the first bad scan.
  void validate(std::size_t point_count) const;
  /// The origin of every point, in cloud order.
  std::vector<Eigen::Vector3d> perPoint(std::size_t point_count) const;
};

/// Drops the points with a NaN or infinite coordinate (organised clouds mark missing returns
/// this way) together with their scans' bookkeeping; returns how many were dropped.
std::size_t dropNonFinitePoints(std::vector<Eigen::Vector3d>& points_m, SensorOrigins* origins);

/// What an import keeps: an empty box (the default) keeps everything; otherwise the map covers
/// no more than this box, in map coordinates, and data outside it is dropped before voxelising.
using CropBox = Eigen::AlignedBox3d;

/// Throws ceilplan::InputError unless `crop_m` is empty or finite with min < max on every axis.
void validateCrop(const CropBox& crop_m);

/// How buildFromScans carves free space along the rays from the sensor origins.
struct RayCarvingOptions {
  double resolution_m = 0.1;  ///< voxel size of the map built
  /// Returns farther than this from their origin are dropped: not occupied, and the map's box is
  /// not grown for them; their rays still carve free space up to this range inside the box of
  /// what is kept. <= 0 keeps every return.
  double max_range_m = 0.0;
  /// Returns outside it are dropped; rays carve only inside it.
  CropBox crop_m = CropBox();
};

/// Where a cloud without sensor origins vouches for free space: the region its assumption covers.
enum class AssumedFreeRegion {
  /// Between scanned surfaces: only voxels with a point-holding voxel above and one below them in
  /// their column. Outside a room's walls, beside a bridge, beyond the last scanned ceiling, the
  /// cloud says nothing, so that space stays unknown (the map knows where its data ends).
  BetweenSurfaces,
  WholeBox,  ///< every voxel of the box: behind walls and beside the structure too
};

/// "between", "box"; throws ceilplan::InputError for any other name.
AssumedFreeRegion assumedFreeRegionFromName(const std::string& name);

/// How buildFromPoints decides free space for a cloud without sensor origins.
struct PointAssumptionOptions {
  double resolution_m = 0.1;  ///< voxel size of the map built
  /// A voxel of the region is free when its centre lies farther than this from every voxel that
  /// holds a point (measured to that voxel's faces); nearer ones stay unknown.
  double free_distance_m = 0.2;
  AssumedFreeRegion region = AssumedFreeRegion::BetweenSurfaces;  ///< where the free-space assumption holds
  /// The box is the points' bounding box grown by this on every side.
  double margin_m = 0.0;
  /// Points outside it are dropped; the box goes no farther.
  CropBox crop_m = CropBox();
};

/// A triangle mesh: vertex positions and, per triangle, three vertex indices.
struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices_m;            ///< vertex positions, map coordinates
  std::vector<std::array<std::size_t, 3>> triangles;  ///< per triangle, three indices into vertices_m
};

/// What fills the space a mesh's surface encloses.
enum class MeshInterior {
  Automatic,  ///< Shell for an open mesh; for a closed one Solid, or Hollow when its triangles face inward (a room)
  Solid,      ///< enclosed space is occupied; space around the mesh is free
  Hollow,     ///< enclosed space is free; space outside the mesh stays unknown
  Shell,      ///< only the surface is occupied: both of its sides are free, whatever it encloses
};

/// "auto", "solid", "hollow", "shell"; throws ceilplan::InputError for any other name.
MeshInterior meshInteriorFromName(const std::string& name);

/// How buildFromMesh voxelises a mesh.
struct MeshVoxelisingOptions {
  double resolution_m = 0.1;  ///< voxel size of the map built
  /// The map's box is the mesh's bounding box grown by this on every side.
  double margin_m = 1.0;
  MeshInterior interior = MeshInterior::Automatic;  ///< what fills the space the mesh encloses
  /// Triangles are clipped at its faces (only voxels inside it are voxelised); whether the mesh
  /// is closed is decided on the whole mesh, and a closed mesh the box cuts is filled inside the
  /// box as it would be whole.
  CropBox crop_m = CropBox();
};

/// Closedness and orientation of a mesh, with vertices welded at identical positions.
struct MeshTopology {
  std::size_t boundary_edges = 0;      ///< edges of one triangle only
  std::size_t non_manifold_edges = 0;  ///< edges of three or more triangles
  bool consistently_oriented = false;  ///< every interior edge is walked once each way
  double signed_volume_m3 = 0.0;       ///< > 0 when a closed mesh's triangles face outward
  /// No boundary and no non-manifold edge: the mesh encloses space.
  bool closed() const { return boundary_edges == 0 && non_manifold_edges == 0; }
};
/// The closedness and orientation of `mesh`.
MeshTopology meshTopology(const TriangleMesh& mesh);

/// A map built from a scan or a mesh, with how its free space was decided.
struct BuiltMap {
  std::unique_ptr<octomap::OcTree> tree;  ///< the OctoMap built
  /// How free space was decided, one line (printed and written beside the map).
  std::string free_space;
  /// Named figures for the summary: points used, voxels filled, and so on, in a fixed order.
  std::vector<std::pair<std::string, double>> figures;
};

/// Ray casting with OctoMap's insertPointCloud from each scan's origin; scans whose origins
/// fall in the same voxel are inserted together from their mean origin. A voxel holding a
/// return within range ends occupied, however many rays later pass through it (thin walls stay
/// closed). Throws ceilplan::InputError for a bad resolution, a non-finite point or origin, an
/// empty cloud, or points and origins spanning more than OctoMap or ceilplan can index, before
/// any map is allocated.
BuiltMap carveFromScans(const std::vector<Eigen::Vector3d>& points_m, const SensorOrigins& origins,
                        const RayCarvingOptions& options, const std::function<void(double)>& progress = {});

/// No sensor positions: voxels holding a point are occupied, voxels of options.region farther
/// than free_distance_m from any of them are free, the rest stay unknown. Same checks as above.
BuiltMap mapFromPointsAlone(const std::vector<Eigen::Vector3d>& points_m, const PointAssumptionOptions& options,
                            const std::function<void(double)>& progress = {});

/// Voxels a triangle touches are occupied (exact triangle-box overlap, so thin walls close);
/// space the surface encloses at that resolution is filled according to options.interior (an
/// open mesh is a thin shell under Automatic); the rest of the box is free (or unknown outside a
/// hollow mesh). Throws ceilplan::InputError for a
/// bad resolution, no triangle, a non-finite vertex, a vertex index out of range, or a box too
/// large, before any map is allocated.
BuiltMap mapFromMesh(const TriangleMesh& mesh, const MeshVoxelisingOptions& options,
                     const std::function<void(double)>& progress = {});

}  // namespace ceilplan::environment
