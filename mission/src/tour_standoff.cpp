#include "ceilplan/mission/tour_standoff.hpp"

#include "ceilplan/mission/tour_planner.hpp"

#include <limits>

namespace ceilplan::mission {
TourStandoff measureTourStandoff(const TourResult& tour, const environment::Environment& environment,
                                 double standoff_m) {
  TourStandoff result;
  result.standoff_m = standoff_m;
  result.min_standoff_m = std::numeric_limits<double>::infinity();
  const auto closest = [&](double standoff, const Eigen::Vector3d& where_m) {
    if (standoff < result.min_standoff_m) {
      result.min_standoff_m = standoff;
      result.narrowest_m = where_m;
    }
  };
  for (std::size_t k = 0; k < tour.stops.size(); ++k) {
    const Viewpoint& viewpoint = tour.stops[k].viewpoint;
    closest(viewpoint.standoff_m, viewpoint.position_m);
    if (viewpoint.standoff_m < standoff_m - planner::kStandoffTolerance_m)
      result.narrowed_stops.push_back(static_cast<int>(k));
  }
  for (std::size_t s = 0; s < tour.plan.sorties.size(); ++s)
    for (const SortieLeg& leg : tour.plan.sorties[s].legs) {
      const planner::StandoffReport report =
          planner::standoffReport(environment, tour.legs[leg.from][leg.to].waypoints, standoff_m);
      result.length_m += report.length_m;
      result.narrowed_m += report.narrowed_m;
      for (const planner::NarrowedSpan& span : report.spans) closest(span.min_standoff_m, span.narrowest_m);
      if (!report.spans.empty()) result.legs.push_back({static_cast<int>(s) + 1, leg.from, leg.to, report});
    }
  return result;
}

}  // namespace ceilplan::mission
