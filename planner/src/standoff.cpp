#include "ceilplan/planner/standoff.hpp"

#include "ceilplan/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace ceilplan::planner {

double airframeRadius_m(const environment::VehicleGeometry& vehicle) {
  return std::hypot(vehicle.collision_radius_m, std::max(vehicle.top_height_m, -vehicle.bottom_height_m));
}

double standoffAt(const environment::Environment& environment, const Eigen::Vector3d& body_m) {
  return environment.clearance_m(body_m) - airframeRadius_m(environment.vehicle());
}

StandoffReport standoffReport(const environment::Environment& environment,
                              const std::vector<Eigen::Vector3d>& waypoints_m, double standoff_m) {
  if (waypoints_m.size() < 2) throw ceilplan::InputError("a standoff report needs at least 2 waypoints");
  StandoffReport report;
  report.standoff_m = standoff_m;
  report.min_standoff_m = std::numeric_limits<double>::infinity();
  const double step_m = 0.5 * environment.grid().frame().resolution_m();
  std::optional<NarrowedSpan> open_span;
  double along_m = 0.0, previous_m = 0.0;
  const auto visit = [&](const Eigen::Vector3d& p, double at_m) {
    const double standoff = standoffAt(environment, p);
    report.min_standoff_m = std::min(report.min_standoff_m, standoff);
    const bool narrowed = standoff < standoff_m - kStandoffTolerance_m;
    if (narrowed && !open_span) open_span = NarrowedSpan{previous_m, at_m, standoff, p};
    if (narrowed) {
      open_span->to_m = at_m;
      if (standoff < open_span->min_standoff_m) {
        open_span->min_standoff_m = standoff;
        open_span->narrowest_m = p;
      }
    } else if (open_span) {
      open_span->to_m = at_m;
      report.spans.push_back(*open_span);
      open_span.reset();
    }
    previous_m = at_m;
  };
  visit(waypoints_m.front(), 0.0);
  for (std::size_t s = 0; s + 1 < waypoints_m.size(); ++s) {
    const Eigen::Vector3d& a = waypoints_m[s];
    const Eigen::Vector3d& b = waypoints_m[s + 1];
    const double length_m = (b - a).norm();
    const int steps = std::max(1, static_cast<int>(std::ceil(length_m / step_m)));
    for (int k = 1; k <= steps; ++k) visit(a + (b - a) * (double(k) / steps), along_m + length_m * k / steps);
    along_m += length_m;
  }
  if (open_span) report.spans.push_back(*open_span);
  report.length_m = along_m;
  for (const NarrowedSpan& span : report.spans) report.narrowed_m += span.to_m - span.from_m;
  return report;
}

}  // namespace ceilplan::planner
