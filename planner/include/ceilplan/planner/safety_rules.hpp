#pragma once
// Where the vehicle may be: the environment's collision check (unknown space is an obstacle,
// the body must be inside the map) plus a minimum gap between the rotor plane and any ceiling,
// so the rotors never touch. In "free" mode a second environment with a conventional standoff
// applies everywhere except near the start and goal, which lie on the structure by definition.
// Everything is const and safe to call from many threads.

#include "ceilplan/environment/environment.hpp"
#include "ceilplan/core/error.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace ceilplan::planner {

struct StandoffZone {
  const environment::Environment* standoff = nullptr;  // the map with margins grown by the standoff
  std::vector<Eigen::Vector3d> exempt_centres_m;       // start and goal
  double exempt_radius_m = 0.0;                         // within it, the plain environment applies
};

// Free mode: the vehicle with its margins (sideways, below and above) grown to `standoff_m`.
environment::VehicleGeometry withStandoff(environment::VehicleGeometry vehicle, double standoff_m);

// Free mode: the standoff applies except within reach of start and goal (the approach zone:
// standoff + the body's largest inflated extent + 1 m), far enough to back away from the
// structure they sit on and past the structure around it to the standoff distance.
StandoffZone standoffZone(const environment::Environment& standoff, const environment::Environment& plain,
                          double standoff_m, const Eigen::Vector3d& start_m, const Eigen::Vector3d& goal_m);

class SafetyRules {
 public:
  // `environment` (and the standoff's) must outlive the rules. Throws ceilplan::InputError on
  // a negative or non-finite gap.
  SafetyRules(const environment::Environment& environment, double min_ceiling_gap_m,
              std::optional<StandoffZone> standoff = std::nullopt);

  const environment::Environment& environment() const { return environment_; }
  double minCeilingGap_m() const { return min_ceiling_gap_m_; }

  // The same rules with the standoff's exemption around other centres (free mode: the rules of
  // a query between other places). Without a standoff, a copy.
  SafetyRules withExemptions(std::vector<Eigen::Vector3d> centres_m) const;
  // Radius of the exemption around each centre; 0 without a standoff.
  double exemptRadius_m() const { return standoff_ ? standoff_->exempt_radius_m : 0.0; }
  bool hasStandoff() const { return standoff_.has_value(); }

  bool isStateValid(const Eigen::Vector3d& body_m) const;
  bool isMotionValid(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) const;

  // The independent re-check of a finished path, mode-independent (the safety requirement):
  // Environment::checkPathDensely (a tenth of a voxel, exact cylinder test) and the minimum
  // ceiling gap at the same spacing. Returns a one-line description of the first violation.
  std::optional<std::string> checkPathDensely(const std::vector<Eigen::Vector3d>& waypoints_m) const;

 private:
  bool gapOk(const Eigen::Vector3d& body_m) const;
  bool baseStateValid(const Eigen::Vector3d& body_m) const;
  bool exempt(const Eigen::Vector3d& body_m) const;

  const environment::Environment& environment_;
  double min_ceiling_gap_m_;
  bool gap_implied_by_cylinder_;  // the inflated cylinder already keeps the rotor plane that far from ceilings
  std::optional<StandoffZone> standoff_;
  double dense_step_m_;
};

}  // namespace ceilplan::planner
