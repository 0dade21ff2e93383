#pragma once
// What the energy model and the planner ask of a map, for one vehicle: the gap from each
// rotor disc to the ceiling above and the ground below, the clearance around the body, and
// whether a state, a motion or a whole path is collision-free. Built once per map (indexes
// described in docs/environment.md); every query is const and safe to call from many threads.

#include "ceilplan/environment/column_index.hpp"
#include "ceilplan/environment/distance_field.hpp"
#include "ceilplan/environment/footprint_masks.hpp"
#include "ceilplan/environment/occupancy_map.hpp"
#include "ceilplan/environment/vehicle_geometry.hpp"
#include "ceilplan/environment/voxel_grid.hpp"
#include "ceilplan/core/error.hpp"

#include <Eigen/Core>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::environment {

struct EnvironmentOptions {
  // Validity and clearance: unknown space is an obstacle (the safe default).
  bool unknown_is_occupied = true;
  // Gaps: unknown space met before any occupied voxel means "no surface" (the default: never
  // claim an energy benefit the map cannot support); true makes it a surface.
  bool unknown_is_surface = false;
  // Coverage counts disc area with a surface within this many rotor radii of the rotor plane.
  // Ceiling: the modelled effect is gone by 2.5 R (docs/models.md, "Ceiling effect"), 4 R leaves
  // room. Ground: significant up to about 5 R (Sanchez-Cuevas et al. 2017).
  double ceiling_reach_radii = 4.0;
  double ground_reach_radii = 5.0;
  // Motions are checked at this fraction of the map resolution.
  double motion_step_voxels = 0.25;
};

// One rotor disc against the surface above (or below) it.
struct RotorGap {
  double nearest_gap_m;  // from the rotor plane to the nearest surface over any part of the disc; +inf if none
  double coverage;       // share of the disc's area with a surface within reach, in [0, 1]
  double mean_gap_m;     // area-weighted mean gap over the covered part; +inf if coverage is 0
};

struct SurfaceGaps {
  std::vector<RotorGap> rotors;  // in the vehicle file's rotor order
  double nearest_gap_m;          // smallest over the rotors
  double coverage;               // mean over the rotors
  double mean_gap_m;             // area-weighted mean gap over all covered disc area
};

enum class ViolationKind { OutsideMap, Occupied, Unknown };

// The first place a state, motion or path breaks the collision constraint.
struct Violation {
  std::size_t segment = 0;  // index of the path segment (0 for a single state or motion)
  Eigen::Vector3d position_m;  // body centre of the first invalid state found
  ViolationKind kind;
  std::string describe() const;  // one line, e.g. "segment 3 at (1.20, 0.00, 5.95): touches occupied space"
};

class Environment {
 public:
  // Indexes `map` for `vehicle` (validated here). Takes about a second and about 5 bytes per
  // voxel of the map's bounding box; `progress` receives fractions in [0, 1].
  Environment(const OccupancyMap& map, VehicleGeometry vehicle, EnvironmentOptions options = {},
              const std::function<void(double)>& progress = {});

  const VoxelGrid& grid() const { return grid_; }
  const ColumnIndex& columns() const { return columns_; }
  const VehicleGeometry& vehicle() const { return vehicle_; }
  const EnvironmentOptions& options() const { return options_; }
  const std::string& mapName() const { return map_name_; }

  // Whether a point lies in the bounding box of the map's known voxels.
  bool contains(const Eigen::Vector3d& point_m) const { return grid_.frame().contains(point_m); }

  // Single-point queries: vertical distance from `point_m` to the nearest occupied voxel face
  // above (below), +infinity if none (or unknown comes first, by policy). Throws
  // ceilplan::InputError for a point outside the map.
  double ceilingGapAt(const Eigen::Vector3d& point_m) const;
  double groundGapAt(const Eigen::Vector3d& point_m) const;

  // Every rotor disc of the vehicle with its body centre at `body_m`. Throws ceilplan::InputError
  // if the body centre lies outside the map.
  SurfaceGaps ceiling(const Eigen::Vector3d& body_m) const;
  SurfaceGaps ground(const Eigen::Vector3d& body_m) const;

  // Distance from the body centre to the nearest occupied (or, by policy, unknown) voxel
  // surface; 0 inside one, +inf if there is none. Throws ceilplan::InputError outside the map.
  double clearance_m(const Eigen::Vector3d& body_m) const;
  // A cheap lower bound on clearance_m (from the voxel holding the point alone, a few ns): lets
  // callers skip gap queries far from any structure. Throws ceilplan::InputError outside the map.
  double clearanceLowerBound_m(const Eigen::Vector3d& body_m) const;

  // A state is valid when the collision cylinder inflated by the margins touches no occupied
  // (or, by policy, unknown) voxel and the body centre lies in the map.
  bool isStateValid(const Eigen::Vector3d& body_m) const { return !stateViolation(body_m); }
  std::optional<Violation> stateViolation(const Eigen::Vector3d& body_m) const;

  // Checks states along the segment every options().motion_step_voxels voxels, both ends included.
  bool isMotionValid(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) const {
    return !motionViolation(from_m, to_m);
  }
  std::optional<Violation> motionViolation(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) const;

  // Independent re-check of a whole path (waypoints joined by straight segments), at a tenth
  // of a voxel with the exact cylinder test everywhere: the first violation, or none.
  std::optional<Violation> checkPathDensely(const std::vector<Eigen::Vector3d>& waypoints_m) const;
  // The spacing of checkPathDensely's states along a segment of length L: L / ceil(L / step),
  // from the segment's start; a planner that checks the same states with isStateValid is
  // guaranteed to pass the re-check.
  double denseStep_m() const;

 private:
  enum class Direction { Up, Down };
  SurfaceGaps gaps(const Eigen::Vector3d& body_m, Direction direction) const;
  double columnGap(int i, int j, double z_m, Direction direction) const;
  void requireInside(const Eigen::Vector3d& point_m, const char* query) const;
  std::optional<Violation> exactCylinderViolation(const Eigen::Vector3d& body_m) const;
  std::optional<Violation> segmentViolation(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m,
                                            double step_m, bool fast_path) const;

  std::string map_name_;
  VehicleGeometry vehicle_;
  EnvironmentOptions options_;
  VoxelGrid grid_;
  ColumnIndex columns_;
  DistanceField distance_;
  FootprintMasks footprint_;
  double bounding_sphere_m_;  // around the body centre, holding the inflated cylinder
};

}  // namespace ceilplan::environment
