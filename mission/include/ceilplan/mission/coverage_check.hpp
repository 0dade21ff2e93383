#pragma once
/// @file
/// The independent coverage re-check: what a set of photos really covers. It takes the photo
/// poses alone (not which region or element a planner meant them for), tests every photo against
/// every surface element with the camera model (skipping only the photos whose frustum cannot reach
/// an element's 1 m cube), and casts each line of sight through the OctoMap tree itself
/// (OcTree::computeRayKeys, the keys looked up among the tree's known-free leaves, read once), not
/// through the planner's voxel grid or any of its visibility bookkeeping. A line of sight is cast
/// for every photo that sees an element within the required GSD and incidence; the others can only
/// lower the element's best GSD, so they are cast finest first until one is clear (the same
/// figures as casting them all). docs/coverage.md, "Re-check".

#include "ceilplan/core/error.hpp"
#include "ceilplan/mission/camera.hpp"
#include "ceilplan/mission/coverage_region.hpp"
#include "ceilplan/mission/region_surface.hpp"

#include <octomap/OcTree.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace ceilplan::mission {

/// The independent re-check of one region: what the photos flown cover, at what GSD.
struct RegionCoverageCheck {
  std::string name;                  ///< the region's name
  double area_m2 = 0.0;              ///< the region's surface area
  double reachable_area_m2 = 0.0;    ///< the planner's claim of what any valid pose could cover
  double unreachable_area_m2 = 0.0;  ///< the rest of the area
  /// Covered: in the central (1 - side) x (1 - front) part of some photo, at or below the
  /// required GSD and incidence, beyond the minimum focus, with a free line of sight.
  double covered_area_m2 = 0.0;
  double covered_reachable_area_m2 = 0.0;  ///< covered and reachable
  double mean_gsd_mm_px = 0.0;             ///< area-weighted best GSD over covered elements

  /// Histogram of each element's best GSD over the photos that see it anywhere in the frame
  /// (free line of sight, facing the camera, beyond the minimum focus): area per bin, bins
  /// [edges[i], edges[i + 1]) and a last bin [edges.back(), inf); unseen_area_m2 holds the rest.
  std::vector<double> gsd_bin_edges_mm_px;
  std::vector<double> gsd_bin_area_m2;  ///< area per GSD bin, m^2
  double unseen_area_m2 = 0.0;          ///< area no photo sees

  /// Per element (RegionSurface order).
  std::vector<std::uint8_t> covered;
  std::vector<float> best_gsd_mm_px;      ///< +inf if no photo sees it
  std::vector<std::uint16_t> view_count;  ///< photos seeing it at or below the required GSD and incidence

  /// Covered share of the region's area, 0..1.
  double coveredShare() const { return area_m2 > 0.0 ? covered_area_m2 / area_m2 : 0.0; }
  /// Covered share of its reachable area, 0..1 (1 when nothing is reachable).
  double coveredReachableShare() const {
    return reachable_area_m2 > 0.0 ? covered_reachable_area_m2 / reachable_area_m2 : 1.0;
  }
};

/// The independent re-check of a coverage tour's photos (checkCoverage; coverage.json).
struct CoverageCheck {
  std::vector<RegionCoverageCheck> regions;  ///< one per region, in the mission's order
  std::size_t rays = 0;                      ///< lines of sight cast
};

/// `surfaces[r]` and `reachable[r]` (per element, from the planner, for the reachable share only)
/// belong to `regions[r]`; `photos` are the poses flown. Runs on `workers` threads.
CoverageCheck checkCoverage(const octomap::OcTree& tree, const Camera& camera,
                            const std::vector<CoverageRegion>& regions, const std::vector<RegionSurface>& surfaces,
                            const std::vector<std::vector<std::uint8_t>>& reachable,
                            const std::vector<CameraPose>& photos, int workers = 2);

/// The elements of a region the check found uncovered: their centres.
std::vector<Eigen::Vector3d> uncoveredCentres(const RegionSurface& surface, const RegionCoverageCheck& check);

}  // namespace ceilplan::mission
