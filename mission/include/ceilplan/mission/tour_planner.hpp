#pragma once
/// @file
/// One inspection tour in one mode, end to end: the stops (a viewpoint per point target and per
/// contact point; in a coverage mission, a fixed pose per photo of the coverage plan), legs
/// between the places (home and the stops: every pair in a small tour, near neighbours and what
/// the plan flies in a large one), the visiting order, the sorties, the flown samples, the wear
/// under every ageing model and the founding paper's month-long duty projection; for coverage,
/// the photos as flown and the independent re-check of what they cover. docs/tours.md,
/// docs/coverage.md.

#include "ceilplan/battery/duty_cycle.hpp"
#include "ceilplan/core/progress.hpp"
#include "ceilplan/environment/map_index.hpp"
#include "ceilplan/mission/coverage_check.hpp"
#include "ceilplan/mission/coverage_plan.hpp"
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
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::mission {

/// The founding paper's 15 missions a day.
inline constexpr int kDefaultToursPerDay = 15;

/// How a tour searches; the settings it shares with routes (seed, ageing model, temperature,
/// speeds, standoff, unknown space) are the context's PlanningOptions.
struct TourOptions {
  /// The leg planner, by the factory's name: the roadmap (the default) searches one lattice
  /// roadmap from each place, deterministic; the other planners search each pair of places.
  std::string planner = planner::defaultTourPlannerName();
  double time_limit_s = 0.5;                                  ///< pairwise planners: search time per leg
  double lattice_spacing_m = planner::kTourLatticeSpacing_m;  ///< roadmap and lattice: between lattice nodes
  bool straight_when_clear = true;  ///< a pair joined by a valid straight motion skips the search
  /// Free mode keeps each point target's own standoff range. Given, a target whose range holds no
  /// viewpoint keeping the conventional standoff may be seen from up to this far (a conventional
  /// planner with a zoom lens), and is reported so (TourStop::beyond_standoff_range).
  std::optional<double> free_standoff_max_m;
  int workers = 2;  ///< threads planning legs; from 2, planTours also plans its modes at once
  /// With a calibrated vehicle, each sortie's landing odds are checked by this many Monte Carlo
  /// draws (Sortie::sampled_landing, seeded with the planning seed); 0: not checked.
  int landing_draws = 1000;
  /// Duty projection, the founding paper's month: the whole tour is one mission.
  std::optional<int> missions_per_day;  ///< unset: as often as fits in a day, at most kDefaultToursPerDay
  int days = 30;                        ///< length of the duty projection
  double idle_min = 5.0;                ///< after each mission, before the charge
  double charge_max_min = 60.0;         ///< per sortie, back to the start SOC
  /// Large tours (docs/tours.md, "Large tours"). Up to `all_pairs_max_places` places (home and
  /// the stops) a leg joins every pair, as above. Beyond, the order search moves each place only
  /// next to its `neighbours` nearest (straight-line distance), legs are estimated (the straight
  /// line, scored) where the search looks and routed once a plan flies them, and sorties may
  /// start at evenly spaced positions of the order, at least `split_points` of them and more where
  /// the tour needs more sorties, and around the best of them.
  /// `order_kicks` rounds of iterated local search (segment double bridges, from `seed`) follow
  /// the first local search: on the bridge soffit 100 of them save 0.6 % of the charge and take
  /// about as long again as the search.
  int all_pairs_max_places = 32;
  int neighbours = 10;        ///< large tours: the nearest places each place may move next to
  int split_points = 60;      ///< large tours: the fewest positions a sortie may start at
  int order_kicks = 0;        ///< large tours: rounds of iterated local search on the order
  ProgressCallback progress;  ///< stages: coverage views, the roadmap, routing, refining
  /// Candidate views' covers shared with the other modes planned at once (planTours sets it when
  /// it plans its modes on their own threads); empty: the tour finds its own.
  std::shared_ptr<SharedCovers> shared_covers;

  /// Throws ceilplan::InputError for options no tour can use (a lattice spacing out of its range,
  /// no worker, ...); planTour checks them first, a front end before it indexes the map.
  void validate() const;
};

/// One stop of a tour: a target (or photo, or contact point) and the pose it is inspected from.
struct TourStop {
  InspectionTarget target;    ///< as the mission gives it; a photo: its aim point and hold
  Viewpoint viewpoint;        ///< where the vehicle hovers to inspect it
  planner::PathSample hover;  ///< hovering at the viewpoint under the full model (the record's dwell)
  /// A photo stop: its index in TourResult::coverage->photos. The pose is the plan's (position,
  /// yaw, gimbal pitch), never searched again; the hold is the capture's stop (0 on the move).
  std::optional<std::size_t> photo;
  std::optional<double> yaw_deg;           ///< heading at the stop (photos; none: aim at the target)
  std::optional<double> gimbal_pitch_deg;  ///< camera pitch at the stop (photos; 90 is straight up)
  std::optional<double> max_speed_m_s;     ///< on the move: no faster than this from this photo to the next
  bool contact = false;                    ///< a contact grid point: its dwell is a reading, not a photo
  /// Free mode, a point target: no viewpoint within its standoff range keeps the conventional
  /// standoff from every structure; it is seen from within the range all the same, keeping less
  /// (viewpoint.standoff_m), or from beyond the range's maximum where TourOptions::
  /// free_standoff_max_m allows it and that keeps more (beyond_standoff_range).
  bool standoff_limited = false;
  bool beyond_standoff_range = false;  ///< seen from beyond its standoff range (TourOptions::free_standoff_max_m)
  /// A point target given inside a structure (its point in an occupied voxel, as a scanned point
  /// is), moved onto the structure's surface (mission::surfacePoint): where the mission put it.
  std::optional<Eigen::Vector3d> given_point_m;
};

/// Seconds spent per phase of planTour.
struct TourTimes {
  double stops_s = 0.0;      ///< coverage views and viewpoints
  double legs_s = 0.0;       ///< every pair, or the neighbours' estimates
  double order_s = 0.0;      ///< visiting order and sortie split, every round
  double order_cpu_s = 0.0;  ///< the same phase's CPU time, every thread (a loaded machine stretches order_s)
  double split_cpu_s = 0.0;  ///< of order_cpu_s, the sortie split: choosing split points, estimating legs, planSorties
  double routing_s = 0.0;    ///< large tours: the legs a plan flies, routed (the roadmap built on first need)
  double refining_s = 0.0;   ///< post-processing the legs flown
  double record_s = 0.0;     ///< dense re-check, flight record, wear, duty
  double coverage_check_s = 0.0;  ///< the independent re-check of the photos flown
  int rounds = 0;                 ///< order-split-refine rounds
  // CPU time of every thread in the phases above (a loaded machine stretches their wall times):
  // what a phase costs, as benchmarks compare it.
  double stops_cpu_s = 0.0;     ///< CPU time of stops_s, every thread
  double legs_cpu_s = 0.0;      ///< CPU time of legs_s, every thread
  double routing_cpu_s = 0.0;   ///< CPU time of routing_s, every thread
  double refining_cpu_s = 0.0;  ///< CPU time of refining_s, every thread
  double record_cpu_s = 0.0;    ///< CPU time of record_s, every thread
};

/// The founding paper's month for a tour: a report, never a reason to abort the plan.
struct DutyProjection {
  int missions_per_day = 0;                   ///< missions flown each day
  int days = 0;                               ///< days projected
  double mission_min = 0.0;                   ///< the tour with its recharges and idle
  std::optional<battery::DutyResult> result;  ///< none: not projected, `note` says why
  std::string note;                           ///< why there is no result, or what to know about it
};

/// One tour in one mode (planTour): stops, legs, order, sorties, the flown record, wear and duty.
struct TourResult {
  FlightMode mode = FlightMode::Ceiling;  ///< the mode it was planned in
  TourOptions options;                    ///< the options it was planned with
  PlanningOptions planning;               ///< the settings it was planned with: the context's (seed, ageing model, ...)
  std::vector<std::string> names;         ///< places: 0 home, k the target of stops[k - 1]
  std::vector<Eigen::Vector3d> places_m;  ///< places: 0 home, k the viewpoint of stops[k - 1], map coordinates
  std::vector<TourStop> stops;            ///< the inspection stops: stops[k - 1] is place k
  LegTable legs;        ///< legs[i][j]: every pair, or those a large tour looked at; samples only where the plan flies
  TourOrder order;      ///< the visiting order of the places
  SortiePlan plan;      ///< the sorties with their charge, DoD and landing SOC
  FlightRecord record;  ///< what the plan flies, sample by sample
  std::vector<SortieRoute> routes;                   ///< per sortie, as a vehicle flies it (autopilot files, maps)
  std::vector<Trajectory> trajectories;              ///< the routes time-scaled into setpoints
  std::vector<PlanWear> wear;                        ///< fec, xu, woehler, schmalstieg
  DutyProjection duty;                               ///< the founding paper's month flying the tour
  double start_soc = 0.0;                            ///< the battery's SOC at each take-off
  double reserve_soc = 0.0;                          ///< the lowest SOC a sortie may land at
  environment::UnknownSpace unknown_space;           ///< the map's policy, as planned
  environment::UnknownSpaceSummary unknown_summary;  ///< what it assumed free in the map
  double assumed_free_m = 0.0;                       ///< of the flown route, relying on the policy
  std::optional<TourStandoff> standoff;              ///< free mode: where the conventional standoff was not kept
  /// A coverage tour (the mission has surfaces): the views planned in this mode, the photos as
  /// flown (flying order, with sortie and time of the shot) and the independent re-check of them.
  std::optional<CoveragePlan> coverage;
  std::vector<PhotoRow> photos;                 ///< coverage: the photos as flown, in flying order
  std::optional<CoverageCheck> coverage_check;  ///< coverage: the independent re-check of the photos flown
  /// The first choice of stops left one where no route from home reached (a pocket a fine scan
  /// resolves, a room behind a door narrower than the vehicle): the stops were chosen again among
  /// the places a flood from home reaches (planner::ReachableSpace). This is that second plan.
  bool stops_rechosen = false;
  TourTimes times;  ///< seconds per phase of the planning
};

/// Plans the mission's tour in one mode with the context's map, vehicle, battery and settings
/// (PlanningContext::options(): the order's seed, the split's ageing model, ...): its point
/// targets, contact grid points and, with surfaces, the photos of planCoverage in this mode.
/// Throws ceilplan::InputError for an invalid home, a target without a viewpoint (named), a bad
/// camera or region (planCoverage),
/// ceilplan::NoPathError for a leg without a path (naming both places) that remains after the
/// stops were chosen again among the places a route from home reaches (TourResult::stops_rechosen),
/// ceilplan::InfeasibleError for a target no single sortie can reach and return from,
/// ceilplan::Error if a leg fails the dense re-check.
TourResult planTour(const Mission& mission, const PlanningContext& context, FlightMode mode,
                    const TourOptions& options = {});

/// Called by planTours with each tour as soon as it is planned (a front end writes its outputs).
using TourPlanned = std::function<void(const TourResult&)>;

/// The mission's tour in each of `modes` (tourFlightModes: both to compare them), each exactly
/// as planTour plans it, to the bit. With TourOptions::workers of 2 or more the modes are planned
/// at once, each on its own thread, sharing the context; each mode's parallel phases take up to
/// `workers` threads more. TourOptions::progress and `planned` are called from the calling thread
/// only: progress with the stages of the modes interleaved (each stage names its mode), `planned`
/// with each tour in the order of `modes` once it and those before it are planned, so one mode's
/// outputs are written while the next is planned. Throws what planTour throws for the first mode,
/// in that order, that fails, after handing over the tours before it; a failure, or an exception
/// from `planned` or the progress callback, stops the modes after it at their next progress report.
std::vector<TourResult> planTours(const Mission& mission, const PlanningContext& context,
                                  const std::vector<FlightMode>& modes, const TourOptions& options = {},
                                  const TourPlanned& planned = {});

}  // namespace ceilplan::mission
