#pragma once
/// @file
/// Where the vehicle can fly to from one place: the lattice nodes (the lattice planners' grid,
/// LatticeSettings::spacing_m apart, 26-connected) that a flood from the origin reaches by valid
/// straight motions under the safety rules. A tour asks it before it settles a viewpoint or a
/// photo pose, so that a stop never lies in a pocket no route enters (a recess between ceiling
/// lamps that a fine scan resolves, a room behind a door narrower than the vehicle).
///
/// reaches(p) is sound: true only where a route exists (p joins a flooded node by a valid
/// straight motion, and the flood's motions lead back to the origin). It is not complete: a
/// passage narrower than the lattice lets through, which the roadmap's refinement finds, is not
/// seen; callers prefer reachable places and fall back to the others (docs/planner.md,
/// "Reachable space"). Const and safe to call from many threads.

#include "ceilplan/planner/safety_rules.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace ceilplan::planner {

/// Where routes from one origin reach under the safety rules: a lattice flooded from it.
class ReachableSpace {
 public:
  /// Floods from `origin_m` at `spacing_m` on `workers` threads; `rules` must outlive this.
  /// Throws ceilplan::InputError for an origin that is not a valid state or a bad spacing.
  ReachableSpace(const SafetyRules& rules, const Eigen::Vector3d& origin_m, double spacing_m, int workers = 1);

  /// Whether a route from the origin to `body_m` exists through the flooded lattice (or straight).
  bool reaches(const Eigen::Vector3d& body_m) const;

  /// Where the flood started.
  const Eigen::Vector3d& origin_m() const { return origin_m_; }
  double spacing_m() const { return spacing_m_; }  ///< as the lattice rounds it to whole voxels
  /// The spacing asked for, m.
  double requestedSpacing_m() const { return requested_spacing_m_; }
  /// Lattice nodes the flood reached.
  std::size_t reachedNodeCount() const { return reached_count_; }

 private:
  const SafetyRules& rules_;
  Eigen::Vector3d origin_m_;
  double requested_spacing_m_;
  double spacing_m_;
  std::vector<std::uint8_t> reached_;  ///< per lattice node
  std::size_t reached_count_ = 0;
};

/// A predicate over body positions (empty: every valid position counts as reachable).
using ReachablePredicate = std::function<bool(const Eigen::Vector3d&)>;

}  // namespace ceilplan::planner
