#pragma once
// A lower bound of the cost of any path between two points that knows climbing costs more than
// descending: what the roadmap's searches price an edge at before they cost it. c_min x length
// (FlightObjective::heuristic) prices every metre as the cheapest direction, a descent at contact
// with a ceiling; this bound prices the rise and the horizontal distance apart.

#include "ceilplan/planner/flight_objective.hpp"

#include <Eigen/Core>

#include <vector>

namespace ceilplan::planner::detail {

class ElevationBound {
 public:
  explicit ElevationBound(const FlightObjective& objective);

  // At most the cost of any path from `from_m` to `to_m`, and consistent: bound(a, c) <=
  // bound(a, b) + bound(b, c).
  double operator()(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) const {
    const Eigen::Vector3d delta = to_m - from_m;
    const double horizontal = delta.head<2>().norm();
    double best = 0.0;
    for (const Eigen::Vector2d& plane : planes_) best = std::max(best, plane.x() * horizontal + plane.y() * delta.z());
    return best;
  }

 private:
  // Pairs (a per horizontal metre, b per metre of rise), a >= 0, with a cos(e) + b sin(e) at most
  // the cheapest cost per metre at every elevation e: a path costs at least a x its horizontal
  // distance + b x its rise (the horizontal lengths of its pieces add up to at least the
  // distance, their rises to the rise).
  std::vector<Eigen::Vector2d> planes_;
};

}  // namespace ceilplan::planner::detail
