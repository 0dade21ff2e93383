#pragma once
// One inspection tour in one mode, end to end: viewpoints, legs between every pair of places
// (home and the viewpoints), the visiting order, the sorties, the flown samples, the wear under
// every ageing model and the founding paper's month-long duty projection. docs/tours.md.

#include "ceilplan/battery/duty_cycle.hpp"
#include "ceilplan/core/progress.hpp"
#include "ceilplan/environment/map_index.hpp"
#include "ceilplan/mission/flight_mode.hpp"
#include "ceilplan/mission/flight_record.hpp"
#include "ceilplan/mission/mission.hpp"
#include "ceilplan/mission/planning_context.hpp"
#include "ceilplan/mission/sortie_plan.hpp"
#include "ceilplan/mission/tour_legs.hpp"
#include "ceilplan/mission/tour_order.hpp"
#include "ceilplan/mission/tour_routes.hpp"
#include "ceilplan/mission/tour_standoff.hpp"
#include "ceilplan/mission/viewpoint.hpp"
#include "ceilplan/planner/planner_factory.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::mission {

// The founding paper's 15 missions a day.
inline constexpr int kDefaultToursPerDay = 15;

struct TourOptions {
  std::uint32_t seed = 1;               // the order heuristic's; OMPL's when an OMPL planner plans the legs
  // The leg planner, by the factory's name: the roadmap (the default) searches one lattice
  // roadmap from each place, deterministic; the other planners search each pair of places.
  std::string planner = planner::defaultTourPlannerName();
  double time_limit_s = 0.5;            // pairwise planners: search time per leg, and as much again for refinement
  double lattice_spacing_m = 0.4;       // roadmap and lattice: between lattice nodes
  int lattice_stride = 0;               // when > 0, the spacing in voxels of the map instead
  bool straight_when_clear = true;      // a pair joined by a valid straight motion skips the search
  std::string ageing_model = "xu";      // the split minimises this model's wear
  double free_standoff_max_m = 3.0;     // free mode: farthest viewpoint (a conventional planner zooms)
  int workers = 2;                      // threads planning legs
  double temperature_c = 25.0;          // cell temperature for the ageing models
  // Duty projection, the founding paper's month: the whole tour is one mission.
  std::optional<int> missions_per_day;  // unset: as often as fits in a day, at most kDefaultToursPerDay
  int days = 30;
  double idle_min = 5.0;
  double charge_max_min = 60.0;  // per sortie, back to the start SOC
  ProgressCallback progress;     // stages: the roadmap, routing, refining
};

struct TourStop {
  InspectionTarget target;  // its standoff range as searched in this mode
  Viewpoint viewpoint;
  planner::PathSample hover;  // hovering at the viewpoint under the full model (the record's dwell)
};

// The founding paper's month for a tour: a report, never a reason to abort the plan.
struct DutyProjection {
  int missions_per_day = 0;
  int days = 0;
  double mission_min = 0.0;                // the tour with its recharges and idle
  std::optional<battery::DutyResult> result;  // none: not projected, `note` says why
  std::string note;
};

struct TourResult {
  FlightMode mode = FlightMode::Ceiling;
  TourOptions options;
  std::vector<std::string> names;             // places: 0 home, k the target of stops[k - 1]
  std::vector<Eigen::Vector3d> places_m;
  std::vector<TourStop> stops;
  std::vector<std::vector<TourLeg>> legs;     // legs[i][j], i != j
  TourOrder order;
  SortiePlan plan;
  FlightRecord record;                // what the plan flies, sample by sample
  std::vector<SortieRoute> routes;    // per sortie, as a vehicle flies it (autopilot files, maps)
  std::vector<Trajectory> trajectories;  // the routes time-scaled into setpoints
  std::vector<PlanWear> wear;        // fec, xu, woehler, schmalstieg
  DutyProjection duty;
  double start_soc = 0.0;
  double reserve_soc = 0.0;
  environment::UnknownSpace unknown_space;             // the map's policy, as planned
  environment::UnknownSpaceSummary unknown_summary;    // what it assumed free in the map
  double assumed_free_m = 0.0;                         // of the flown route, relying on the policy
  std::optional<TourStandoff> standoff;  // free mode: where the conventional standoff was not kept
};

// Plans the mission's tour in one mode with the context's map, vehicle and battery. Throws
// ceilplan::InputError for an invalid home or a target without a viewpoint (named),
// ceilplan::NoPathError for a leg without a path (naming both places),
// ceilplan::InfeasibleError for a target no single sortie can reach and return from,
// ceilplan::Error if a leg fails the dense re-check.
TourResult planTour(const Mission& mission, const PlanningContext& context, FlightMode mode,
                    const TourOptions& options = {});

}  // namespace ceilplan::mission
