#pragma once
// One inspection tour in one mode, end to end: viewpoints, legs between every pair of places
// (home and the viewpoints), the visiting order, the sorties, the flown samples, the wear under
// every ageing model and the founding paper's month-long duty projection. docs/tours.md.

#include "mission_file.hpp"
#include "planning_setup.hpp"
#include "tour_legs.hpp"

#include "ceilplan/battery/duty_cycle.hpp"
#include "ceilplan/mission/sortie_plan.hpp"
#include "ceilplan/mission/tour_order.hpp"
#include "ceilplan/mission/viewpoint.hpp"
#include "ceilplan/planner/planner_factory.hpp"
#include "ceilplan/core/error.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace ceilplan::app {

struct TourOptions {
  std::uint64_t seed = 1;               // the order heuristic's; OMPL's when an OMPL planner plans the legs
  // The leg planner: the roadmap (the default) searches one lattice roadmap from each place,
  // deterministic; the other planners search each pair of places.
  std::string planner = planner::defaultTourPlannerName();
  double time_limit_s = 0.5;            // pairwise planners: search time per leg, and as much again for refinement
  double lattice_spacing_m = 0.4;       // roadmap and lattice: between lattice nodes
  int lattice_stride = 0;               // when > 0, the spacing in voxels of the map instead (to be retired)
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
};

struct TourStop {
  mission::InspectionTarget target;  // its standoff range as searched in this mode
  mission::Viewpoint viewpoint;
};

struct TourResult {
  std::string mode;
  TourOptions options;
  std::vector<std::string> names;             // places: 0 home, k the target of stops[k - 1]
  std::vector<Eigen::Vector3d> places_m;
  std::vector<TourStop> stops;
  std::vector<std::vector<TourLeg>> legs;     // legs[i][j], i != j
  mission::TourOrder order;
  mission::SortiePlan plan;
  // Per sortie, the flown samples from take-off (dwells included, as hovering samples), the
  // SOC counted from the start SOC over the sortie's own samples.
  std::vector<std::vector<planner::PathSample>> sortie_samples;
  std::vector<mission::PlanWear> wear;        // fec, xu, woehler, schmalstieg
  battery::DutyResult duty;
  double start_soc = 0.0;
  double reserve_soc = 0.0;
};

// The planning flags a mission file stands for: its map, vehicle, battery and speeds.
PlanningArguments planningArguments(const MissionFile& mission);

// Throws ceilplan::InputError for invalid home or a target without a viewpoint (named),
// NoPathError for a leg without a path (naming both places), ceilplan::InputError from
// planSorties for a target no single sortie can reach and return from, std::runtime_error if a
// leg fails the dense re-check.
TourResult planTour(const MissionFile& mission, const PlanningSetup& setup, PlanningMode mode,
                    const TourOptions& options);

}  // namespace ceilplan::app
