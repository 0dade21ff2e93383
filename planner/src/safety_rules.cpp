#include "ceilplan/planner/safety_rules.hpp"
#include "ceilplan/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace ceilplan::planner {

SafetyRules::SafetyRules(const environment::Environment& environment, double min_ceiling_gap_m)
    : environment_(environment), min_ceiling_gap_m_(min_ceiling_gap_m) {
  if (!(std::isfinite(min_ceiling_gap_m) && min_ceiling_gap_m >= 0.0))
    throw ceilplan::InputError("minimum ceiling gap must be a finite number >= 0 m");
  const environment::VehicleGeometry& vehicle = environment_.vehicle();
  // Every rotor disc lies inside the cylinder's footprint, and the cylinder's top (with its
  // margin) is at least the minimum gap above the rotor plane: then no valid state can have a
  // ceiling closer than the minimum gap to any rotor, and the gap query can be skipped.
  double disc_reach = 0.0;
  for (const Eigen::Vector2d& rotor : vehicle.rotor_positions_m)
    disc_reach = std::max(disc_reach, rotor.norm() + vehicle.rotor_radius_m);
  gap_implied_by_cylinder_ = disc_reach <= vehicle.inflatedRadius_m() &&
                             vehicle.inflatedTop_m() - vehicle.rotor_plane_height_m >= min_ceiling_gap_m_;
  dense_step_m_ = environment_.denseStep_m();
}

bool SafetyRules::gapOk(const Eigen::Vector3d& body_m) const {
  return gap_implied_by_cylinder_ || environment_.nearestCeilingGap_m(body_m) >= min_ceiling_gap_m_;
}

bool SafetyRules::isStateValid(const Eigen::Vector3d& body_m) const {
  return environment_.isStateValid(body_m) && gapOk(body_m);
}

bool SafetyRules::isMotionValid(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) const {
  // Exactly the states the dense re-check visits (Environment::denseStep_m), so an accepted
  // motion always passes it; isStateValid's distance-field fast path keeps this cheap away
  // from structure. A coarser step can clip a voxel corner between two checked states.
  const double length = (to_m - from_m).norm();
  if (!std::isfinite(length)) return false;
  const long steps = std::max(1L, static_cast<long>(std::ceil(length / dense_step_m_)));
  const double step_m = length / static_cast<double>(steps);
  const auto stateAt = [&](long s) {
    return Eigen::Vector3d(from_m + (to_m - from_m) * (static_cast<double>(s) / steps));
  };
  const environment::GridFrame& frame = environment_.grid().frame();
  for (long s = 0; s <= steps;) {
    const Eigen::Vector3d state = stateAt(s);
    // Sphere tracing: far from structure every state within the distance field's reach is
    // valid (Environment::validReach_m; the cylinder then keeps the ceiling gap too), so the
    // states of this motion within it are skipped.
    const double reach_m = gap_implied_by_cylinder_ ? environment_.validReach_m(state) : 0.0;
    if (reach_m > 0.0) {
      const double skipped = step_m > 0.0 ? std::floor(reach_m / step_m) : static_cast<double>(steps);
      s += std::max(1L, static_cast<long>(std::min(skipped, static_cast<double>(steps))));
      continue;
    }
    if (gap_implied_by_cylinder_ && environment_.contains(state)) {
      // Near structure the states come a tenth of a voxel apart, about ten to a grid column:
      // the footprint masks clear the column's run of them at once, as they clear each alone
      // in isStateValid (the same test over the union of their heights).
      const int i = frame.indexOf(0, state.x()), j = frame.indexOf(1, state.y());
      double low_z = state.z(), high_z = state.z();
      long end = s + 1;
      for (; end <= steps; ++end) {
        const Eigen::Vector3d next = stateAt(end);
        if (!environment_.contains(next) || frame.indexOf(0, next.x()) != i || frame.indexOf(1, next.y()) != j) break;
        low_z = std::min(low_z, next.z());
        high_z = std::max(high_z, next.z());
      }
      if (!environment_.columnSurelyValid(i, j, low_z, high_z))
        for (long k = s; k < end; ++k)
          if (!isStateValid(stateAt(k))) return false;
      s = end;
      continue;
    }
    if (!isStateValid(state)) return false;
    ++s;
  }
  return true;
}

std::optional<std::string> SafetyRules::checkPathDensely(const std::vector<Eigen::Vector3d>& waypoints_m) const {
  if (waypoints_m.empty()) return std::string("the path has no waypoint");
  if (const auto violation = environment_.checkPathDensely(waypoints_m)) return violation->describe();
  for (std::size_t s = 0; s + 1 < waypoints_m.size(); ++s) {
    const Eigen::Vector3d& a = waypoints_m[s];
    const Eigen::Vector3d& b = waypoints_m[s + 1];
    const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() / dense_step_m_)));
    for (int k = 0; k <= steps; ++k) {
      const Eigen::Vector3d p = a + (b - a) * (double(k) / steps);
      const double gap = environment_.nearestCeilingGap_m(p);
      if (gap < min_ceiling_gap_m_) {
        char line[200];
        std::snprintf(
            line, sizeof line,
            "segment %zu at (%.2f, %.2f, %.2f): rotor plane %.3f m from the ceiling, under the minimum %.3f m", s,
            p.x(), p.y(), p.z(), gap, min_ceiling_gap_m_);
        return std::string(line);
      }
    }
  }
  return std::nullopt;
}

}  // namespace ceilplan::planner
