#include "elevation_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ceilplan::planner::detail {
namespace {

// What the fan of elevations can miss between its directions (the cost per metre is smooth
// between them, and the corners where the speed limits switch are in the fan), and the edges'
// costs rounded to float.
constexpr double kMargin = 0.99;
// Directions the bound's planes are chosen for: each keeps the plane that bounds it best.
constexpr int kTargetDirections = 36;

}  // namespace

ElevationBound::ElevationBound(const FlightObjective& objective) {
  const FlightCostModel& model = objective.model();
  std::vector<double> elevations = model.costFanElevations_rad();
  std::sort(elevations.begin(), elevations.end());
  std::vector<double> cheapest;
  std::vector<Eigen::Vector2d> units;  // (cos, sin) of each elevation
  cheapest.reserve(elevations.size());
  units.reserve(elevations.size());
  for (const double elevation : elevations) {
    cheapest.push_back(model.minCostPerMetreAt(objective.weights(), elevation));
    units.emplace_back(std::cos(elevation), std::sin(elevation));
  }
  // The directions' unit-cost points (how far a unit of cost flies at each elevation, in the
  // plane of horizontal distance and rise) and the outer chain of their convex hull, from straight
  // down to straight up: a path of any mix of directions costs at least the hull's gauge.
  std::vector<Eigen::Vector2d> hull;
  const auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
  };
  for (std::size_t k = 0; k < units.size(); ++k) {
    const Eigen::Vector2d point = units[k] / cheapest[k];
    while (hull.size() >= 2 && cross(hull[hull.size() - 2], hull.back(), point) <= 0.0) hull.pop_back();
    hull.push_back(point);
  }
  // Each hull edge gives a plane w with w . p = 1 at both its ends, scaled down until it meets
  // every direction's constraint (what the hull's rounding may leave).
  std::vector<Eigen::Vector2d> candidates;
  for (std::size_t k = 0; k + 1 < hull.size(); ++k) {
    Eigen::Matrix2d ends;
    ends.row(0) = hull[k].transpose();
    ends.row(1) = hull[k + 1].transpose();
    if (std::abs(ends.determinant()) < 1e-300) continue;
    Eigen::Vector2d plane = ends.inverse() * Eigen::Vector2d::Ones();
    plane.x() = std::max(0.0, plane.x());
    double scale = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < units.size(); ++j) {
      const double along = plane.dot(units[j]);
      if (along > 0.0) scale = std::min(scale, cheapest[j] / along);
    }
    if (std::isfinite(scale)) candidates.push_back(kMargin * std::min(1.0, scale) * plane);
  }
  for (int t = 0; t <= kTargetDirections; ++t) {
    const double elevation = -M_PI / 2 + M_PI * t / kTargetDirections;
    const Eigen::Vector2d direction(std::cos(elevation), std::sin(elevation));
    const Eigen::Vector2d* best = nullptr;
    for (const Eigen::Vector2d& candidate : candidates)
      if (!best || candidate.dot(direction) > best->dot(direction)) best = &candidate;
    if (best && std::find(planes_.begin(), planes_.end(), *best) == planes_.end()) planes_.push_back(*best);
  }
}

}  // namespace ceilplan::planner::detail
