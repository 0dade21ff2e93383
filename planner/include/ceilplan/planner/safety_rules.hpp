#pragma once
/// @file
/// Where the vehicle may be: the environment's collision check (unknown space is an obstacle,
/// the body must be inside the map) plus a minimum gap between the rotor plane and any ceiling,
/// so the rotors never touch. The same in every mode: free mode's conventional standoff is a
/// preference of its cost (CostModelOptions::standoff_m), not a rule. Everything is const and
/// safe to call from many threads.

#include "ceilplan/core/error.hpp"
#include "ceilplan/environment/environment.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace ceilplan::planner {

/// What every mode must keep: the vehicle's clearance (Environment validity) and the minimum rotor gap to a ceiling.
class SafetyRules {
 public:
  /// `environment` must outlive the rules. Throws ceilplan::InputError on a negative or
  /// non-finite gap.
  SafetyRules(const environment::Environment& environment, double min_ceiling_gap_m);

  /// The map the rules apply to.
  const environment::Environment& environment() const { return environment_; }
  /// The smallest rotor-plane gap to a ceiling allowed, m.
  double minCeilingGap_m() const { return min_ceiling_gap_m_; }

  /// Whether the vehicle may be at `body_m`.
  bool isStateValid(const Eigen::Vector3d& body_m) const;
  /// Whether the straight motion between two positions is valid, checked in steps.
  bool isMotionValid(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) const;

  /// The independent re-check of a finished path, mode-independent (the safety requirement):
  /// Environment::checkPathDensely (a tenth of a voxel, exact cylinder test) and the minimum
  /// ceiling gap at the same spacing. Returns a one-line description of the first violation.
  std::optional<std::string> checkPathDensely(const std::vector<Eigen::Vector3d>& waypoints_m) const;

 private:
  bool gapOk(const Eigen::Vector3d& body_m) const;

  const environment::Environment& environment_;
  double min_ceiling_gap_m_;
  bool gap_implied_by_cylinder_;  ///< the inflated cylinder already keeps the rotor plane that far from ceilings
  double dense_step_m_;
};

}  // namespace ceilplan::planner
