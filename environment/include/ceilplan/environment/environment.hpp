#pragma once
/// @file
/// What the energy model and the planner ask of a map, for one vehicle: the gap from each
/// rotor disc to the ceiling above and the ground below, the clearance around the body, and
/// whether a state, a motion or a whole path is collision-free. The map's index (MapIndex) is
/// built once and shared; an Environment adds only what depends on the vehicle's geometry and
/// margins (docs/environment.md). Every query is const and safe to call from many threads.

#include "ceilplan/core/error.hpp"
#include "ceilplan/environment/column_index.hpp"
#include "ceilplan/environment/distance_field.hpp"
#include "ceilplan/environment/footprint_masks.hpp"
#include "ceilplan/environment/map_index.hpp"
#include "ceilplan/environment/occupancy_map.hpp"
#include "ceilplan/environment/unknown_space.hpp"
#include "ceilplan/environment/vehicle_geometry.hpp"
#include "ceilplan/environment/voxel_grid.hpp"

#include <Eigen/Core>

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::environment {

/// What depends on the vehicle; the unknown-space policy belongs to the map's index
/// (MapIndexOptions).
struct EnvironmentOptions {
  /// Gaps: unknown space that the policy keeps, met before any occupied voxel, means "no
  /// surface" (the default: never claim an energy benefit the map cannot support); true makes
  /// it a surface. Unknown space the policy assumed free is free air, never a surface.
  bool unknown_is_surface = false;
  /// Coverage counts disc area with a surface within this many rotor radii of the rotor plane.
  /// Ceiling: the modelled effect is gone by 2.5 R (docs/models.md, "Ceiling effect"), 4 R leaves
  /// room. Ground: significant up to about 5 R (Sanchez-Cuevas et al. 2017).
  double ceiling_reach_radii = 4.0;
  double ground_reach_radii = 5.0;  ///< ground: coverage counts disc area with a surface within this many rotor radii
  /// Motions are checked at this fraction of the map resolution.
  double motion_step_voxels = 0.25;
  int workers = 2;  ///< threads building what depends on the vehicle (and the index, when built here)
};

/// One rotor disc against the surface above (or below) it.
struct RotorGap {
  double nearest_gap_m;  ///< from the rotor plane to the nearest surface over any part of the disc; +inf if none
  double coverage;       ///< share of the disc's area with a surface within reach, in [0, 1]
  double mean_gap_m;     ///< area-weighted mean gap over the covered part; +inf if coverage is 0
};

/// The rotor discs of a vehicle against the surface above (or below) them, and their summary.
struct SurfaceGaps {
  std::vector<RotorGap> rotors;  ///< in the vehicle file's rotor order
  double nearest_gap_m;          ///< smallest over the rotors
  double coverage;               ///< mean over the rotors
  double mean_gap_m;             ///< area-weighted mean gap over all covered disc area
};

/// Why a state is not valid: it lies outside the map, touches occupied space, or touches unknown space the policy
/// keeps.
enum class ViolationKind {
  OutsideMap,  ///< the body centre lies outside the map
  Occupied,    ///< the vehicle with its margins touches occupied space
  Unknown      ///< it touches unknown space the policy keeps
};

/// A stretch of a path, by distance along it from its first waypoint.
struct PathInterval {
  double from_m;                 ///< start, m along the path
  double to_m;                   ///< end, m along the path
  Eigen::Vector3d from_point_m;  ///< where it starts
  Eigen::Vector3d to_point_m;    ///< where it ends
};

/// Where a path relies on the unknown-space policy.
struct AssumedFreeStretches {
  double length_m = 0.0;                ///< total length of the intervals
  std::vector<PathInterval> intervals;  ///< in order along the path, disjoint
};

/// The first place a state, motion or path breaks the collision constraint.
struct Violation {
  std::size_t segment = 0;       ///< index of the path segment (0 for a single state or motion)
  Eigen::Vector3d position_m;    ///< body centre of the first invalid state found
  ViolationKind kind;            ///< what the vehicle touches there
  std::string describe() const;  ///< one line, e.g. "segment 3 at (1.20, 0.00, 5.95): touches occupied space"
};

/// A map indexed for one vehicle: gaps above and below each rotor, clearance, and the validity of states, motions and
/// paths. Read only; safe to share between threads.
class Environment {
 public:
  /// `vehicle` (validated here) on a map indexed once for every vehicle: builds only the
  /// footprint masks (a bit per voxel, one pass over the grid); `progress` receives fractions in [0, 1].
  Environment(std::shared_ptr<const MapIndex> index, VehicleGeometry vehicle, EnvironmentOptions options = {},
              const std::function<void(double)>& progress = {});
  /// Indexes `map` itself, with unknown space occupied: the same as the constructor above on
  /// MapIndex::build(map). About 7 bytes per voxel of the map's bounding box.
  Environment(const OccupancyMap& map, VehicleGeometry vehicle, EnvironmentOptions options = {},
              const std::function<void(double)>& progress = {});
  /// The same with the index's options (the unknown-space policy) given.
  Environment(const OccupancyMap& map, VehicleGeometry vehicle, EnvironmentOptions options,
              const MapIndexOptions& index_options, const std::function<void(double)>& progress = {});

  /// The shared index: pass it to the next Environment on this map.
  const std::shared_ptr<const MapIndex>& index() const { return index_; }
  /// The map's own voxel states.
  const VoxelGrid& grid() const { return index_->grid(); }
  /// The runs of what blocks under the policy.
  const ColumnIndex& columns() const { return index_->columns(); }
  /// The vehicle, as validated.
  const VehicleGeometry& vehicle() const { return vehicle_; }
  /// The options it was built with.
  const EnvironmentOptions& options() const { return options_; }
  /// The unknown-space policy of the index.
  const UnknownSpace& unknownSpace() const { return index_->unknownSpace(); }
  /// The map's name (its file) for messages.
  const std::string& mapName() const { return index_->mapName(); }
  /// The footprint masks and the index's share; the index is counted once however many share it.
  std::size_t memoryBytes() const { return footprint_.memoryBytes(); }

  /// Whether a point lies in the bounding box of the map's known voxels.
  bool contains(const Eigen::Vector3d& point_m) const { return grid().frame().contains(point_m); }

  /// Single-point queries: vertical distance from `point_m` to the nearest occupied voxel face
  /// above (below), +infinity if none (or unknown comes first, by policy). Throws
  /// ceilplan::InputError for a point outside the map.
  double ceilingGapAt(const Eigen::Vector3d& point_m) const;
  /// Vertical distance from `point_m` down to the nearest occupied voxel face (as ceilingGapAt, below).
  double groundGapAt(const Eigen::Vector3d& point_m) const;

  /// Every rotor disc of the vehicle with its body centre at `body_m`. Throws ceilplan::InputError
  /// if the body centre lies outside the map.
  SurfaceGaps ceiling(const Eigen::Vector3d& body_m) const;
  /// The same below every rotor disc (ground effect).
  SurfaceGaps ground(const Eigen::Vector3d& body_m) const;
  /// Both, each column under a disc looked up once for the two (what the cost model asks at
  /// every sample): the same as ceiling() and ground().
  struct CeilingAndGround {
    SurfaceGaps ceiling;  ///< as ceiling()
    SurfaceGaps ground;   ///< as ground()
  };
  /// The ceiling and the ground at `body_m`. Throws as ceiling() does.
  CeilingAndGround ceilingAndGround(const Eigen::Vector3d& body_m) const;
  /// ceilingAndGround() at each of `bodies_m`, the same to the bit, passed to `visit(k, gaps)` in
  /// order. For points close together (a motion's samples, whose discs share most columns) each
  /// column is searched once for all of them: its free span holding the first height asked
  /// answers every later height inside it. Throws as ceiling() does, before any work.
  void ceilingAndGroundAlong(const std::vector<Eigen::Vector3d>& bodies_m,
                             const std::function<void(std::size_t, const CeilingAndGround&)>& visit) const;
  /// Whether ceiling(body_m).nearest_gap_m >= gap_m: the same columns' gaps, without weighing the
  /// discs, stopping at the first nearer one. Throws as ceiling() does.
  bool ceilingGapAtLeast(const Eigen::Vector3d& body_m, double gap_m) const;
  /// ceiling(body_m).nearest_gap_m, the same to the bit: the same columns' gaps, without weighing
  /// the discs (what the safety rules, free mode's cost and the viewpoints need). Throws as
  /// ceiling() does.
  double nearestCeilingGap_m(const Eigen::Vector3d& body_m) const;

  /// Distance from the body centre to the nearest occupied (or, by policy, unknown) voxel
  /// surface; 0 inside one, +inf if there is none. Throws ceilplan::InputError outside the map.
  double clearance_m(const Eigen::Vector3d& body_m) const;
  /// A cheap lower bound on clearance_m (from the voxel holding the point alone, a few ns): lets
  /// callers skip gap queries far from any structure. Throws ceilplan::InputError outside the map.
  double clearanceLowerBound_m(const Eigen::Vector3d& body_m) const;

  /// How far the body may move from `body_m`, in any direction, and stay valid: the distance
  /// field's lower bound beyond the sphere holding the inflated cylinder, and no further than the
  /// map's box (0 when the bound is not beyond the sphere, or outside the map). Every state
  /// within it is valid by isStateValid and by checkPathDensely's exact test, under every
  /// unknown-space policy.
  double validReach_m(const Eigen::Vector3d& body_m) const;

  /// Whether every body position in grid column (i, j) (inside the grid) with its centre between
  /// heights low_z_m and high_z_m is valid by isStateValid, as the footprint masks alone show it
  /// (nothing blocking at the cylinder's heights within its reach): one test for the many states
  /// a motion has in one column. False says only that the masks cannot tell.
  bool columnSurelyValid(int i, int j, double low_z_m, double high_z_m) const {
    return !footprint_.mayBlock(i, j, low_z_m + vehicle_.inflatedBottom_m(), high_z_m + vehicle_.inflatedTop_m());
  }

  /// A state is valid when the collision cylinder inflated by the margins touches no occupied
  /// (or, by policy, unknown) voxel and the body centre lies in the map.
  bool isStateValid(const Eigen::Vector3d& body_m) const { return !stateViolation(body_m); }
  /// The first violation at `body_m`, or none when it is valid.
  std::optional<Violation> stateViolation(const Eigen::Vector3d& body_m) const;

  /// Checks states along the segment every options().motion_step_voxels voxels, both ends included.
  bool isMotionValid(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) const {
    return !motionViolation(from_m, to_m);
  }
  /// The first violation along the segment, or none when it is valid.
  std::optional<Violation> motionViolation(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) const;

  /// Independent re-check of a whole path (waypoints joined by straight segments), at a tenth
  /// of a voxel with the exact cylinder test everywhere: the first violation, or none.
  std::optional<Violation> checkPathDensely(const std::vector<Eigen::Vector3d>& waypoints_m) const;
  /// The spacing of checkPathDensely's states along a segment of length L: L / ceil(L / step),
  /// from the segment's start; a planner that checks the same states with isStateValid is
  /// guaranteed to pass the re-check.
  double denseStep_m() const;

  /// Whether the vehicle at `body_m` relies on the unknown-space policy: its inflated collision
  /// cylinder overlaps unknown space the policy assumed free, so under the occupied policy the
  /// state would be invalid. Always false under the occupied policy and outside the map.
  bool assumesFree(const Eigen::Vector3d& body_m) const;
  /// Where along a path (waypoints joined by straight segments) the vehicle relies on the
  /// policy, checked at the dense re-check's states; each such state stands for half a step on
  /// either side. What plan.json, tour.json and path.csv report as assumed_free_m.
  AssumedFreeStretches assumedFreeAlong(const std::vector<Eigen::Vector3d>& waypoints_m) const;

 private:
  enum class Direction { Up, Down };
  /// The gaps above into `up` and below into `down`, where given; when both are,
  /// `column_gaps(i, j, z_m)` gives column (i, j)'s gaps above and below height z_m, and
  /// `uniform_gaps(r, z_m)` those of every column under rotor r's disc when it knows they agree.
  template <class ColumnGaps, class UniformGaps>
  void gaps(const Eigen::Vector3d& body_m, SurfaceGaps* up, SurfaceGaps* down, ColumnGaps&& column_gaps,
            UniformGaps&& uniform_gaps) const;
  /// gaps() with every column searched afresh.
  void gaps(const Eigen::Vector3d& body_m, SurfaceGaps* up, SurfaceGaps* down) const;
  double columnGap(int i, int j, double z_m, Direction direction) const;
  bool isSurface(const ColumnIndex::Boundary& boundary) const;
  double surfaceGap(const ColumnIndex::Boundary& boundary, double z_m) const;
  /// Column (i, j)'s gaps above and below height z_m, from one search of the column.
  std::array<double, 2> searchedColumnGaps(int i, int j, double z_m) const;
  void requireInside(const Eigen::Vector3d& point_m, const char* query) const;
  std::optional<Violation> exactCylinderViolation(const Eigen::Vector3d& body_m) const;
  /// Calls `visit(i, j)` for every column the inflated cylinder at `body_m` overlaps by more
  /// than its side, until one returns true; returns whether one did.
  template <class Visit>
  bool anyColumnUnderCylinder(const Eigen::Vector3d& body_m, Visit&& visit) const;
  std::optional<Violation> segmentViolation(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m, double step_m,
                                            bool fast_path) const;

  std::shared_ptr<const MapIndex> index_;
  const ColumnIndex* columns_;  ///< the index's, reached without two indirections on every query
  const DistanceField* distance_;
  VehicleGeometry vehicle_;
  EnvironmentOptions options_;
  FootprintMasks footprint_;
  double bounding_sphere_m_;  ///< around the body centre, holding the inflated cylinder
};

}  // namespace ceilplan::environment
