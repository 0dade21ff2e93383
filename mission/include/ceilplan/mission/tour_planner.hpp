#pragma once
// One inspection tour in one mode, end to end: viewpoints, legs between every pair of places
// (home and the viewpoints), the visiting order, the sorties, the flown samples, the wear under
// every ageing model and the founding paper's month-long duty projection. docs/tours.md.

#include "ceilplan/battery/duty_cycle.hpp"
#include "ceilplan/core/progress.hpp"
#include "ceilplan/mission/flight_mode.hpp"
#include "ceilplan/mission/mission.hpp"
#include "ceilplan/mission/planning_context.hpp"
#include "ceilplan/mission/sortie_plan.hpp"
#include "ceilplan/mission/tour_legs.hpp"
#include "ceilplan/mission/tour_order.hpp"
#include "ceilplan/mission/viewpoint.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace ceilplan::mission {

struct TourOptions {
  std::uint32_t seed = 1;               // the order heuristic's; OMPL's when an OMPL planner plans the legs
  // The leg planner: "roadmap" (the default) searches one lattice roadmap from each place,
  // deterministic; OMPL's planners and "lattice" (A*) search each pair of places.
  std::string planner = "roadmap";
  double time_limit_s = 0.5;            // pairwise planners: search time per leg, and as much again for refinement
  int lattice_stride = 4;               // roadmap and lattice: voxels between lattice nodes
  bool straight_when_clear = true;      // a pair joined by a valid straight motion skips the search
  std::string ageing_model = "xu";      // the split minimises this model's wear
  double free_standoff_max_m = 3.0;     // free mode: farthest viewpoint (a conventional planner zooms)
  int workers = 2;                      // threads planning legs
  double temperature_c = 25.0;          // cell temperature for the ageing models
  // Duty projection, the founding paper's month: the whole tour is one mission.
  int missions_per_day = 15;
  int days = 30;
  double idle_min = 5.0;
  double charge_max_min = 60.0;  // per sortie, back to the start SOC
  ProgressCallback progress;     // stages: the roadmap, routing, refining
};

struct TourStop {
  InspectionTarget target;  // its standoff range as searched in this mode
  Viewpoint viewpoint;
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
  // Per sortie, the flown samples from take-off (dwells included, as hovering samples), the
  // SOC counted from the start SOC over the sortie's own samples.
  std::vector<std::vector<planner::PathSample>> sortie_samples;
  std::vector<PlanWear> wear;        // fec, xu, woehler, schmalstieg
  battery::DutyResult duty;
  double start_soc = 0.0;
  double reserve_soc = 0.0;
};

// Plans the mission's tour in one mode with the context's map, vehicle and battery. Throws
// ceilplan::InputError for an invalid home or a target without a viewpoint (named),
// ceilplan::NoPathError for a leg without a path (naming both places), ceilplan::InputError
// from planSorties for a target no single sortie can reach and return from, ceilplan::Error if a
// leg fails the dense re-check.
TourResult planTour(const Mission& mission, const PlanningContext& context, FlightMode mode,
                    const TourOptions& options = {});

}  // namespace ceilplan::mission
