#pragma once
/// @file
/// A coverage mission proposed from the map alone (`ceilplan propose`, docs/import.md): the
/// overhead surfaces a scan or model holds, grouped into regions, and a home to take off from.
/// The regions are the map's down-facing occupied faces with known free space below them
/// (environment/surface_elements.hpp) with room below them for the vehicle to photograph them,
/// joined where they touch (26-connected voxels); the home is a valid body position in known free
/// space low above the lowest floor or ground, with room to climb 1.5 m straight up, near the
/// regions.

#include "ceilplan/core/progress.hpp"
#include "ceilplan/environment/environment.hpp"
#include "ceilplan/mission/camera.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::mission {

/// How proposeMission finds overhead regions and a home (`ceilplan propose`, docs/import.md).
struct ProposalOptions {
  /// Only overhead surfaces inside this box (map frame); none: the whole map.
  std::optional<Eigen::AlignedBox3d> crop_m;
  /// The home, checked rather than proposed.
  std::optional<Eigen::Vector3d> home_m;
  /// Regions of less overhead area are dropped (a bracket, a lamp, a scan's stray return).
  double min_region_area_m2 = 1.0;
  /// At most this many regions, the largest first: each is a coverage surface of the tour.
  int max_regions = 8;
  /// The proposed home's height above the floor under it (the lowest one that is a valid state).
  double min_home_height_m = 0.5;
  double max_home_height_m = 3.0;  ///< the proposed home's highest height above the floor
  /// Camera to surface: a down-facing face is overhead only with this much known free space below
  /// it besides the vehicle's inflated height (proposalStandoff_m; io sets it from the camera).
  double standoff_m = 1.0;

  /// Throws ceilplan::InputError naming the option: non-finite or empty crop, area < 0,
  /// max_regions outside [1, 100], heights or standoff outside (0, 100] or min above max.
  void validate() const;
};

/// One proposed coverage region.
struct ProposedRegion {
  std::string name;           ///< "overhead_1", ... by area, largest first
  Eigen::AlignedBox3d box_m;  ///< the region's faces, each with its half voxel around it
  double area_m2 = 0.0;       ///< the surface's area (environment::SurfaceElement::area_m2)
  std::size_t elements = 0;   ///< voxel faces
  /// All the overhead area inside the box: more than area_m2 where smaller surfaces (a closet's
  /// ceiling, a lamp) lie within its bounds. The mission's region covers them too.
  double box_area_m2 = 0.0;
};

/// What proposeMission returns: regions, a home and what was left out.
struct MissionProposal {
  std::vector<ProposedRegion> regions;  ///< largest first
  /// the home, map frame
  Eigen::Vector3d home_m = Eigen::Vector3d::Zero();
  bool home_given = false;          ///< the home was given (ProposalOptions::home_m), not proposed
  double home_height_m = 0.0;       ///< above the floor under the home (NaN when no floor lies below)
  std::size_t dropped_regions = 0;  ///< below the area or beyond the count
  double dropped_area_m2 = 0.0;     ///< their overhead area
  double overhead_area_m2 = 0.0;    ///< of every down-facing face onto known free space (in the crop)
  /// Of that, the regions with less free space below most of their area than the vehicle needs
  /// to photograph them (min_room_below_m), and the faces less high than that above the ground: a
  /// table's underside, the ground seen from a hole under it (a scan's) or from below (an open mesh's).
  double too_low_area_m2 = 0.0;
  double min_room_below_m = 0.0;  ///< ProposalOptions::standoff_m + the vehicle's inflated height
  /// The lowest floor a home can stand on (inside the crop), a proposed home within 0.5 m of it;
  /// NaN when there is none.
  double ground_m = std::numeric_limits<double>::quiet_NaN();
};

/// The standoff a proposed region leaves room for below it: free mode's distance kept from every
/// structure (ViewGenerationOptions::free_standoff_m, 1 m), nearer where the GSD asks for it (the
/// camera's distance for `gsd_mm_px` straight on), never nearer than the camera's minimum focus.
double proposalStandoff_m(const Camera& camera, double gsd_mm_px);

/// Throws ceilplan::InputError: no overhead surface with known free space below (in the crop),
/// none with room below it to photograph it, none large enough, a given home that is outside the
/// map, not a valid state or in unknown space, or no valid home in known free space above any floor.
MissionProposal proposeMission(const environment::Environment& environment, const ProposalOptions& options,
                               const ProgressCallback& progress = {});

}  // namespace ceilplan::mission
