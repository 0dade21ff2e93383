#pragma once
/// @file
/// Where a free-mode tour kept less than the conventional standoff (docs/planner.md, "Free
/// mode"): free mode keeps the standoff where the space allows and the largest that fits where
/// it does not, and this says where it had to narrow, at the viewpoints and along the legs flown.

#include "ceilplan/environment/environment.hpp"
#include "ceilplan/planner/standoff.hpp"

#include <Eigen/Core>

#include <vector>

namespace ceilplan::mission {

struct TourResult;

/// A leg flown with less than the standoff somewhere.
struct NarrowedLeg {
  int sortie = 0;        ///< from 1
  int from = 0, to = 0;  ///< places: 0 home, k the target of stops[k - 1]
  /** @var from
   *  The place the leg starts at: 0 home, k the target of stops[k - 1]. */
  planner::StandoffReport report;  ///< its spans, along the leg from its start
};

/// Free mode: where a tour flew closer than the conventional standoff, leg by leg.
struct TourStandoff {
  double standoff_m = 0.0;      ///< the conventional standoff asked for
  double length_m = 0.0;        ///< flown, every leg of every sortie
  double narrowed_m = 0.0;      ///< of it, with less than the standoff
  double min_standoff_m = 0.0;  ///< the closest the airframe came to a structure, on a leg or hovering
  Eigen::Vector3d narrowest_m = Eigen::Vector3d::Zero();  ///< where
  std::vector<NarrowedLeg> legs;                          ///< the legs flown that narrowed, in the order flown
  std::vector<int> narrowed_stops;  ///< stops (indices into TourResult::stops) whose viewpoint keeps less
};

/// The standoff report of every leg the tour's plan flies and of its viewpoints, on the
/// environment it was planned in.
TourStandoff measureTourStandoff(const TourResult& tour, const environment::Environment& environment,
                                 double standoff_m);

}  // namespace ceilplan::mission
