#pragma once
/// @file
/// What a coverage mission inspects: surface regions to photograph at a required GSD, overlap
/// and incidence (`surfaces:`), and regions to probe by contact on a grid (`contact_grid:`).
/// A region is a box or a vertical polygon prism in the map frame, and a choice of which way
/// its surfaces may face. docs/coverage.md, "Regions".

#include "ceilplan/core/error.hpp"
#include "ceilplan/mission/camera.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace ceilplan::mission {

/// Which way a surface faces, from its normal: Down (soffits, ceilings, a tunnel crown) when the
/// normal points more than 45 deg below level, Up more than 45 deg above, Side otherwise (walls,
/// girder webs, piers).
enum class FaceKind {
  Down,  ///< normal more than 45 deg below level: soffits, ceilings
  Side,  ///< walls, girder webs, piers
  Up     ///< normal more than 45 deg above level
};
/// The kind of face `normal` belongs to.
FaceKind faceKindOf(const Eigen::Vector3d& normal);
const char* faceKindName(FaceKind kind);  ///< "down", "side", "up"

/// Which kinds of face a region inspects (key `faces:`).
struct FaceSet {
  bool down = false;  ///< faces pointing down (soffits, ceilings)
  bool side = false;  ///< faces to the side (walls, webs, piers)
  bool up = false;    ///< faces pointing up

  /// Whether faces of `kind` are inspected.
  bool has(FaceKind kind) const;
  /// Whether no kind is inspected.
  bool empty() const { return !down && !side && !up; }
  std::string describe() const;  ///< "[down, side]"
};

/// A box, or a prism: a simple polygon in the horizontal plane extruded between two heights.
struct RegionShape {
  /// Box or Prism.
  enum class Kind {
    Box,   ///< an axis-aligned box
    Prism  ///< a horizontal polygon extruded between two heights
  };
  Kind kind = Kind::Box;                   ///< which shape
  Eigen::AlignedBox3d box;                 ///< Box: the box; Prism: its bounds (set by makePrism)
  std::vector<Eigen::Vector2d> polygon_m;  ///< Prism: vertices in order, not repeated at the end

  /// A box between two corners.
  static RegionShape makeBox(const Eigen::Vector3d& min_m, const Eigen::Vector3d& max_m);
  /// A prism: `polygon_m` extruded from z_min_m to z_max_m.
  static RegionShape makePrism(std::vector<Eigen::Vector2d> polygon_m, double z_min_m, double z_max_m);

  /// Whether `point_m` lies inside (boundary included).
  bool contains(const Eigen::Vector3d& point_m) const;
  /// The shape's bounding box.
  const Eigen::AlignedBox3d& bounds() const { return box; }
  /// Throws ceilplan::InputError naming `what` (e.g. "region 'soffit'"): non-finite or empty
  /// box, polygon of fewer than 3 vertices, zero area or self-intersecting.
  void validate(const std::string& what) const;
};

/// A surface to photograph (`surfaces:` entry).
struct CoverageRegion {
  std::string name;                 ///< unique in the mission
  RegionShape shape;                ///< where the region lies
  FaceSet faces;                    ///< which faces in it are photographed
  double gsd_mm_px = 1.0;           ///< required ground sample distance: every element at or below it
  double overlap_front_pct = 70.0;  ///< along the direction of flight (the image height)
  double overlap_side_pct = 60.0;   ///< across it (the image width)
  double max_incidence_deg = 45.0;  ///< largest angle between a line of sight and the surface normal

  /// Throws ceilplan::InputError naming the region and the field: no name, no faces, GSD <= 0
  /// or beyond 1000 mm/px, overlap outside [0, 100) %, incidence outside (0, 89] deg.
  void validate() const;
  /// Share of each image's width and height that must not be needed by a neighbour: a region
  /// element counts as covered only in the central (1 - side) x (1 - front) part of an image.
  double widthShare() const { return 1.0 - overlap_side_pct / 100.0; }
  /// Share of each image's height a neighbour must not need: 1 - front overlap.
  double heightShare() const { return 1.0 - overlap_front_pct / 100.0; }
};

/// Contact points on a surface (`contact_grid:` entry): the vehicle hugs the surface at each
/// point for `dwell_s` while its probe (ultrasonic thickness, hammer) touches it.
struct ContactGrid {
  std::string name;        ///< unique in the mission
  RegionShape shape;       ///< where the grid lies
  FaceSet faces;           ///< which faces in it are probed
  double spacing_m = 1.0;  ///< between neighbouring points, in the surface's plane
  double dwell_s = 10.0;   ///< per point
  double reach_m = 0.5;    ///< farthest the body centre may be from a point (the probe's reach)

  /// Throws ceilplan::InputError naming the grid and the field.
  void validate() const;
};

/// Checks, before any map work, that `camera` can inspect `region`, else throws
/// ceilplan::InputError naming both keys: the distance giving the required GSD must lie beyond
/// the minimum focus distance, and for every face kind of the region the gimbal must be able
/// to point the optical axis within the incidence limit of that kind's normal (down faces need
/// pitch >= 90 - max_incidence_deg, up faces pitch <= -(90 - max_incidence_deg), side faces a
/// pitch within +-max_incidence_deg).
void checkCameraReaches(const Camera& camera, const CoverageRegion& region);

}  // namespace ceilplan::mission
