#pragma once
/// @file
/// Where the vehicle hovers to inspect a target: a valid body position within the target's
/// standoff range that sees the target point. In ceiling mode it draws the least charge over
/// the dwell: hugging the surface above (contact-style inspection under a deck). In free mode
/// proximity effects are ignored when choosing, as a conventional planner would: the nearest
/// position that keeps the conventional standoff from every structure where one fits, else the
/// position with the largest standoff that fits (planner/standoff.hpp). Both modes keep the same
/// clearance rules, and either way the dwell is scored with the full model.

#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/environment/environment.hpp"
#include "ceilplan/mission/flight_mode.hpp"
#include "ceilplan/planner/reachable_space.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>

namespace ceilplan::mission {

/// A point target of a mission (`targets:` entry, docs/missions.md): a point to inspect from within a standoff range.
struct InspectionTarget {
  /// The farthest standoff: beyond, a viewpoint search spans more than any inspected structure.
  static constexpr double kMaxStandoff_m = 50.0;

  std::string name;                                   ///< unique in the mission
  Eigen::Vector3d point_m = Eigen::Vector3d::Zero();  ///< on the structure's surface
  double standoff_min_m = 0.3;                        ///< body centre to point
  double standoff_max_m = 1.5;                        ///< farthest body centre to point
  double dwell_s = 0.0;                               ///< hover time for the inspection

  /// Throws ceilplan::InputError naming the target and the bad field.
  void validate() const;
};

/// How a viewpoint is chosen for a target.
struct ViewpointOptions {
  FlightMode mode = FlightMode::Ceiling;  ///< the mode the viewpoint is for
  /// Rotors never come closer than this to the surface above (the planner's minimum ceiling gap).
  double min_ceiling_gap_m = 0.03;
  double soc = 0.65;        ///< SOC at which the dwell current is evaluated (energy model's reference)
  double standoff_m = 1.0;  ///< free mode: the conventional standoff from every structure
  /// Whether a route from home reaches a position (a tour's planner::ReachableSpace); empty:
  /// every valid position. The best reachable position wins; only where none is reachable is
  /// the best of the others kept (a passage finer than the reachability lattice may still lead
  /// there, and the tour's planner then says where the way is blocked).
  planner::ReachablePredicate reachable;
};

/// Where a target is inspected from, and what hovering there costs.
struct Viewpoint {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  ///< body centre
  double distance_m = 0.0;                               ///< to the target point
  double ceiling_gap_m = 0.0;                            ///< nearest rotor-plane gap above; +inf if none
  double standoff_m = 0.0;                               ///< airframe to the nearest structure (planner::standoffAt)
  double dwell_current_a = 0.0;                          ///< full model, hovering here
  double dwell_charge_ah = 0.0;                          ///< dwell current x dwell time
  bool reachable = true;                                 ///< ViewpointOptions::reachable held (or was not given)
};

/// A target lies on structure: some occupied voxel within its standoff range (standoff_max_m)
/// of its point. Throws ceilplan::InputError naming the target when none is, a target in free
/// air (a point outside the map is left to chooseViewpoint, which names the map's extent).
void requireOnStructure(const InspectionTarget& target, const environment::Environment& environment);

/// Where a target given on or inside a structure (its point in an occupied voxel, as a scanned
/// point is) lies on the structure's surface: the nearest point of a face between an occupied and
/// a free voxel, at most the target's standoff_max_m away. The point itself when its voxel is not
/// occupied; none when no such face is that near (chooseViewpoint then names the target).
std::optional<Eigen::Vector3d> surfacePoint(const InspectionTarget& target,
                                            const environment::Environment& environment);

/// Pack current hovering at `body_m` under the full model: each rotor's mean gap and coverage
/// above, the mean gap below.
double hoverCurrentA(const environment::Environment& environment, const energy::EnergyModel& model,
                     const Eigen::Vector3d& body_m, double soc);

/// Searches a lattice over the standoff shell (whole voxels at most 0.1 m apart, then a quarter
/// of the step at a time around the best, down to a quarter voxel) for states valid in
/// `environment` with a clear line of sight to the point through free voxels, preferring those
/// ViewpointOptions::reachable accepts, choosing under `options.mode` (ceiling: the least dwell
/// charge; free: the smallest standoff shortfall, to the millimetre), ties by distance to the point.
/// Throws ceilplan::InputError naming the target when it is invalid or no viewpoint exists.
/// Reads the environment and the model only: safe to run for several targets at once.
Viewpoint chooseViewpoint(const InspectionTarget& target, const environment::Environment& environment,
                          const energy::EnergyModel& model, const ViewpointOptions& options = {});

}  // namespace ceilplan::mission
