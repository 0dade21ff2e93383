#pragma once
/// @file
/// Choosing the views: a weighted set cover of the reachable surface, each candidate view priced
/// by the charge it costs the battery (hover current at its pose under the mode's cost model,
/// times the time it takes: the stop to shoot, and the transit to the next photo, estimated as
/// the square root of the area it covers at the transit speed). Greedy by cost per newly covered
/// area with lazy evaluation, then local improvement: drop redundant views, and exchange (add
/// one view where the views it makes redundant cost more). docs/coverage.md, "Choice of views".

#include "ceilplan/core/error.hpp"
#include "ceilplan/mission/camera.hpp"
#include "ceilplan/mission/coverage_views.hpp"
#include "ceilplan/mission/region_surface.hpp"
#include "ceilplan/planner/flight_cost_model.hpp"

#include <cstdint>
#include <vector>

namespace ceilplan::mission {

/// What one candidate view costs the tour.
struct ViewCost {
  double hover_current_a = 0.0;  ///< at the pose, under the mode's cost model
  double stop_s = 0.0;           ///< stopped to shoot (Camera::stopPerPhoto_s)
  double transit_s = 0.0;        ///< estimated flight to the next photo
  double speed_m_s = 0.0;        ///< the speed that transit assumes (blur and photo interval included)
  double charge_ah = 0.0;        ///< hover current x (stop + transit)
};

/// How viewCosts prices the candidates.
struct ViewCostOptions {
  double transit_speed_m_s = 0.5;  ///< between neighbouring photos (the mission's inspection speed)
  int workers = 2;                 ///< threads pricing views
};

/// The cost of every candidate. The ageing models are monotone in charge for a given sortie, and
/// every view's charge feeds the same tour, so ranking by charge is ranking by wear to first order
/// (docs/coverage.md); the tour then prices the real wear.
std::vector<ViewCost> viewCosts(const planner::FlightCostModel& model, const Camera& camera,
                                const CandidateViews& views, const ViewCostOptions& options = {});

/// How the set cover improves on its greedy choice.
struct SetCoverOptions {
  int improvement_rounds = 4;  ///< rounds of redundancy removal and exchanges
};

/// The views chosen to cover a region, and how the choice went.
struct SetCoverResult {
  std::vector<std::uint32_t> chosen;  ///< candidate indices, ascending
  double cost = 0.0;                  ///< sum of the chosen views' costs
  double greedy_cost = 0.0;           ///< before local improvement
  std::size_t greedy_views = 0;       ///< views the greedy choice took
  std::size_t evaluations = 0;        ///< gains computed by the lazy greedy (plain greedy: views x rounds)
  std::size_t removed = 0;            ///< views dropped as redundant
  std::size_t exchanges = 0;          ///< views added where the views they made redundant cost more
  std::size_t tiling_views = 0;  ///< views of whole lawnmower tilings the greedy started from (0: it started empty)
};

/// Covers every element some candidate covers (elements no candidate covers are ignored), at
/// least cost. `area` is each element's weight, `cost` each candidate's (both positive). Where
/// `views` has tilings, the greedy also runs from the cheapest tiling of each flat patch (cost per
/// area its views cover), and that cover is kept when it takes fewer views for less cost (or
/// covers more). Deterministic: ties go to the lower candidate index.
SetCoverResult chooseViews(const CandidateViews& views, const std::vector<double>& area,
                           const std::vector<double>& cost, const SetCoverOptions& options = {});

}  // namespace ceilplan::mission
