#pragma once
/// @file
/// Where a search found the way blocked, and by which rule: what a "no path" error names, so a
/// user can see the gap that is too narrow (or the unknown space, or the map's edge) and decide
/// what to change.

#include <Eigen/Core>

#include <optional>
#include <string>

namespace ceilplan::planner {

/// The rule that blocks the way where no path is found.
enum class BlockingRule {
  Clearance,   ///< the vehicle with its margins touches occupied space
  Unknown,     ///< unknown space, which the map's policy counts as occupied
  MapEdge,     ///< the body would leave the map
  CeilingGap,  ///< the rotors would come closer to a ceiling than the minimum gap
};

/// "the vehicle's clearance", "unknown space", "the map's edge", "the minimum rotor gap to a ceiling".
std::string describe(BlockingRule rule);

/// Where and why no path gets through, for a NoPathError's message.
struct Blockage {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  ///< the most open blocked body position of the gap
  BlockingRule rule = BlockingRule::Clearance;           ///< what blocks
  /// The free opening across the way there through voxels the map's policy counts as free:
  /// sideways, and square to the way and the sideways (vertically for a level way); 0: solid,
  /// +inf: open beyond 3 m; NaN when both are wide enough and something askew blocks the way.
  double width_m = 0.0;
  double height_m = 0.0;  ///< the opening square to the way and the sideways, m (as width_m)
  /// What the vehicle with its margins needs along the same two directions (for a level way:
  /// the inflated cylinder's diameter and height).
  double needed_width_m = 0.0;
  double needed_height_m = 0.0;  ///< what the vehicle needs square to the way, m
  /// Set when no opening at all joins the two sides: the end ("start" or "goal") walled in on
  /// every side, where it is, and the box of the space the vehicle reaches from it. Then
  /// position_m and the opening say nothing.
  std::string enclosed_end;
  /// where the walled-in end is
  Eigen::Vector3d enclosed_at_m = Eigen::Vector3d::Zero();
  /// lower corner of the space reached from it
  Eigen::Vector3d enclosure_min_m = Eigen::Vector3d::Zero();
  /// upper corner of the space reached from it
  Eigen::Vector3d enclosure_max_m = Eigen::Vector3d::Zero();

  /// One line, e.g. "blocked at (4.05, 1.20, 1.00) by the vehicle's clearance: the opening there
  /// is 0.88 m wide and 2.00 m high, the vehicle needs 0.92 x 0.30 m with its margins", or "the
  /// goal at (1.10, 0.80, 1.20) is enclosed: ..." .
  std::string describe() const;
};

/// A planner that can say where its search was blocked (the lattice planners).
class BlockageReporter {
 public:
  virtual ~BlockageReporter() = default;
  /// After a search that found that no path exists: where the way is blocked; else nothing.
  virtual std::optional<Blockage> lastBlockage() const = 0;
};

}  // namespace ceilplan::planner
