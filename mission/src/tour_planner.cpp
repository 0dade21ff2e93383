#include "ceilplan/mission/tour_planner.hpp"

#include "ceilplan/mission/contact_points.hpp"
#include "ceilplan/mission/duty_projection.hpp"
#include "ceilplan/mission/route_planning.hpp"

#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/core/install_paths.hpp"
#include "ceilplan/core/parallel_for.hpp"
#include "ceilplan/energy/lipo_open_circuit_voltage.hpp"
#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/lattice_roadmap.hpp"
#include "ceilplan/planner/path_refinement.hpp"
#include "ceilplan/planner/reachable_space.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <ctime>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>
#include <utility>

namespace ceilplan::mission {
namespace {

using Pairs = std::vector<std::pair<int, int>>;

// The tour's progress callback for one stage.
FractionCallback stageProgress(const TourOptions& options, const std::string& stage) {
  if (!options.progress) return {};
  return [callback = options.progress, stage](double fraction) { callback(stage, fraction); };
}

// CPU seconds of the whole process, every thread: what a phase costs on a shared machine.
double processCpuS() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// Adds the CPU seconds of its scope to `total_s`.
class CpuTimer {
 public:
  explicit CpuTimer(double& total_s) : total_s_(total_s), start_s_(processCpuS()) {}
  ~CpuTimer() { total_s_ += processCpuS() - start_s_; }
  CpuTimer(const CpuTimer&) = delete;
  CpuTimer& operator=(const CpuTimer&) = delete;

 private:
  double& total_s_;
  double start_s_;
};

class Stopwatch {
 public:
  double lap_s() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - start_).count();
    start_ = now;
    return seconds;
  }
  // The wall time since the last lap, and adds the process's CPU time since then to `cpu_s`.
  double lap_s(double& cpu_s) {
    const double now_cpu_s = processCpuS();
    cpu_s += now_cpu_s - start_cpu_s_;
    start_cpu_s_ = now_cpu_s;
    return lap_s();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  double start_cpu_s_ = processCpuS();
};

// The rotors stay this much farther from the surface at a viewpoint than the planner's
// minimum gap, so the leg's end passes the dense re-check with its rounding.
constexpr double kViewpointGapMarginM = 0.01;

// A target point within this of a structure's surface is on it.
constexpr double kSurfaceTolerance_m = 1e-3;

// A leg an OMPL planner misses is searched again this many times longer, twice: BIT* finds
// long legs round the bridge's girders in a few seconds, but not always in 0.5 s.
constexpr double kRetryTimeFactors[] = {10.0, 40.0};

// Hovering at a viewpoint under the full model: the sample the record repeats over the dwell.
planner::PathSample hoverSample(const PlanningContext& context, const Eigen::Vector3d& position_m) {
  const planner::FlightCostModel& model = context.fullModel();
  const planner::PointConditions conditions = model.exactConditionsAt(position_m);
  planner::PathSample hover;
  hover.position_m = position_m;
  hover.speed_m_s = 0.0;
  hover.ceiling_gap_m = conditions.nearest_ceiling_gap_m;
  hover.ground_gap_m = conditions.ground_gap_m;
  hover.clearance_m = context.environment().clearance_m(position_m);
  hover.propulsion_power_w =
      model.breakdown(conditions, model.hoverAt(conditions), context.battery().start_soc).propulsionW();
  return hover;
}

ViewpointOptions viewpointOptions(const PlanningContext& context, FlightMode mode,
                                  const planner::ReachablePredicate& reachable) {
  ViewpointOptions options;
  options.mode = mode;
  options.reachable = reachable;
  options.min_ceiling_gap_m = context.options().min_ceiling_gap_m + kViewpointGapMarginM;
  options.standoff_m = context.options().standoff_m;
  return options;
}

// A point target given inside a structure moves onto its surface, and keeps where it was given;
// within a millimetre it stays where it is.
void moveOntoSurface(TourStop& stop, const environment::Environment& environment) {
  const std::optional<Eigen::Vector3d> surface = surfacePoint(stop.target, environment);
  if (!surface || (*surface - stop.target.point_m).norm() <= kSurfaceTolerance_m) return;
  stop.given_point_m = stop.target.point_m;
  stop.target.point_m = *surface;
}

// A viewpoint per target, searched on the tour's threads, within the target's standoff range. A
// point target whose range keeps less than free mode's conventional standoff is marked, and seen
// from farther only where the options allow a zoom lens; a contact probe has no zoom.
std::vector<TourStop> viewpointStops(const std::vector<InspectionTarget>& targets, std::size_t point_targets,
                                     const PlanningContext& context, FlightMode mode, const TourOptions& options,
                                     const planner::ReachablePredicate& reachable) {
  const ViewpointOptions viewpoint_options = viewpointOptions(context, mode, reachable);
  for (std::size_t k = 0; k < point_targets; ++k) requireOnStructure(targets[k], context.environment());
  std::vector<TourStop> stops(targets.size());
  parallelFor(targets.size(), options.workers, [&](std::size_t k) {
    TourStop stop;
    stop.target = targets[k];
    if (k < point_targets) moveOntoSurface(stop, context.environment());
    stop.viewpoint = chooseViewpoint(stop.target, context.environment(), context.energy(), viewpoint_options);
    stop.standoff_limited = mode == FlightMode::Free && k < point_targets &&
                            stop.viewpoint.standoff_m < viewpoint_options.standoff_m - planner::kStandoffTolerance_m;
    if (stop.standoff_limited && options.free_standoff_max_m &&
        *options.free_standoff_max_m > stop.target.standoff_max_m) {
      InspectionTarget wider = stop.target;
      wider.standoff_max_m = *options.free_standoff_max_m;
      const Viewpoint farther = chooseViewpoint(wider, context.environment(), context.energy(), viewpoint_options);
      stop.beyond_standoff_range = farther.distance_m > stop.target.standoff_max_m &&
                                   farther.standoff_m > stop.viewpoint.standoff_m + planner::kStandoffTolerance_m;
      if (stop.beyond_standoff_range) stop.viewpoint = farther;
    }
    stop.hover = hoverSample(context, stop.viewpoint.position_m);
    stops[k] = std::move(stop);
  });
  return stops;
}

// The coverage plan of the mission's surfaces in this mode (docs/coverage.md).
CoveragePlan planMissionCoverage(const Mission& mission, const PlanningContext& context, FlightMode mode,
                                 const TourOptions& options, const planner::ReachablePredicate& reachable) {
  if (!mission.camera)
    throw InputError(mission.name() + ": surfaces are photographed: add a 'camera' (" + docPage("coverage.md") +
                     ", \"Mission keys\")");
  CoveragePlanOptions coverage;
  coverage.views.mode = mode;
  coverage.views.free_standoff_m = context.options().standoff_m;
  coverage.views.min_ceiling_gap_m = context.options().min_ceiling_gap_m + kViewpointGapMarginM;
  coverage.views.workers = options.workers;
  coverage.views.reachable = reachable;
  coverage.views.shared_covers = options.shared_covers;
  coverage.costs.transit_speed_m_s = context.options().speeds.inspection_m_s;
  coverage.costs.workers = options.workers;
  if (options.progress)
    coverage.progress = [&options, mode](const std::string& phase, double share) {
      options.progress(flightModeName(mode) + " mode: " + phase, share);
    };
  const PlanningContext::Mode planning = context.mode(mode);
  return planCoverage(context.environment(), *planning.model, *mission.camera, mission.surfaces, coverage);
}

// A photo of the plan as a stop: its pose as planned, its hold, aimed at the centre of what it covers.
TourStop photoStop(const CoveragePlan& plan, std::size_t k, const Camera& camera, const PlanningContext& context) {
  const PlannedPhoto& photo = plan.photos[k];
  TourStop stop;
  stop.photo = k;
  stop.target.name =
      plan.regions.at(static_cast<std::size_t>(photo.region)).region.name + "_photo" + std::to_string(k + 1);
  const CameraFrame frame(camera, photo.pose);
  stop.target.point_m = frame.position_m() + photo.distance_m * frame.forward();
  stop.target.standoff_min_m = stop.target.standoff_max_m = (stop.target.point_m - photo.pose.body_m).norm();
  stop.target.dwell_s = photo.stop_s;
  stop.viewpoint.position_m = photo.pose.body_m;
  stop.viewpoint.distance_m = stop.target.standoff_min_m;
  stop.hover = hoverSample(context, photo.pose.body_m);
  stop.viewpoint.ceiling_gap_m = stop.hover.ceiling_gap_m;
  stop.viewpoint.dwell_current_a =
      hoverCurrentA(context.environment(), context.energy(), photo.pose.body_m, ViewpointOptions{}.soc);
  stop.viewpoint.dwell_charge_ah = stop.viewpoint.dwell_current_a * photo.stop_s / 3600.0;
  stop.yaw_deg = photo.pose.yaw_deg;
  stop.gimbal_pitch_deg = photo.pose.gimbal_pitch_deg;
  if (photo.stop_s == 0.0) stop.max_speed_m_s = photo.max_speed_m_s;
  return stop;
}

// Every stop of the mission: the coverage plan's photos in its order (region by region, pass by
// pass), the contact grids' points, then the point targets.
std::vector<TourStop> chooseStops(const Mission& mission, const PlanningContext& context, FlightMode mode,
                                  const TourOptions& options, const planner::ReachablePredicate& reachable,
                                  TourResult& tour) {
  std::vector<TourStop> stops;
  if (!mission.surfaces.empty()) {
    tour.coverage = planMissionCoverage(mission, context, mode, options, reachable);
    for (std::size_t k = 0; k < tour.coverage->photos.size(); ++k)
      stops.push_back(photoStop(*tour.coverage, k, *mission.camera, context));
  }
  std::vector<InspectionTarget> targets = mission.targets;
  for (const ContactGrid& grid : mission.contact_grids) {
    const std::vector<InspectionTarget> points = contactTargets(context.environment().grid(), grid);
    targets.insert(targets.end(), points.begin(), points.end());
  }
  // Point targets first in the search, so that free mode marks them only; the stops list contact
  // points before them.
  std::vector<TourStop> viewpoints = viewpointStops(targets, mission.targets.size(), context, mode, options, reachable);
  std::rotate(viewpoints.begin(), viewpoints.begin() + static_cast<std::ptrdiff_t>(mission.targets.size()),
              viewpoints.end());
  for (std::size_t k = 0; k + mission.targets.size() < viewpoints.size(); ++k) viewpoints[k].contact = true;
  stops.insert(stops.end(), viewpoints.begin(), viewpoints.end());
  if (stops.empty())
    throw InputError(mission.name() + ": nothing to inspect: no targets, surfaces or contact grid points");
  return stops;
}

// Free air at `speed_m_s` and the start SOC: where a leg without samples (an estimate's totals)
// is taken to fly for its sensitivity to the calibrated parameters.
planner::PathSample freeAirCondition(const PlanningContext& context, double speed_m_s) {
  planner::PathSample condition;
  condition.ceiling_gap_m = energy::kNoSurface;
  condition.ground_gap_m = energy::kNoSurface;
  condition.speed_m_s = speed_m_s;
  condition.soc = context.battery().start_soc;
  return condition;
}

LegCost legCost(const planner::PathEvaluation& evaluation, const PlanningContext& context) {
  LegCost cost;
  cost.charge_ah = evaluation.charge_ah;
  cost.duration_s = evaluation.duration_s;
  cost.mean_current_a = evaluation.mean_current_a;
  for (const planner::PathSample& s : evaluation.samples) cost.load_profile.push_back({s.t_s, s.propulsion_power_w});
  if (const auto& fit = context.vehicle().calibration) {
    const double speed_m_s = evaluation.duration_s > 0.0 ? evaluation.length_m / evaluation.duration_s : 0.0;
    cost.sensitivity =
        evaluation.samples.size() >= 2
            ? pathChargeSensitivity(context.energy(), evaluation.samples, *fit, SortieWind::of(context.fullModel()))
            : steadyChargeSensitivity(context.energy(), freeAirCondition(context, speed_m_s), evaluation.charge_ah,
                                      evaluation.duration_s, *fit, SortieWind::of(context.fullModel()));
  }
  return cost;
}

// The pack current a propulsion power draws at an SOC (the energy model's Rint pack).
CurrentAtSoc packCurrent(const energy::EnergyModel& energy) {
  return [&energy](double propulsion_w, double soc) {
    return energy.pack().operatingPoint(propulsion_w, std::clamp(soc, 0.0, 1.0)).current_a;
  };
}

// The record of each sortie of the plan: the same integration as planSorties, sample by sample.
FlightRecord recordFlight(const TourResult& tour, const PlanningContext& context) {
  const BatterySpec& battery = context.battery();
  const CurrentAtSoc current = packCurrent(context.energy());
  const energy::PackElectrics& pack = context.energy().pack();
  FlightRecord record;
  double clock_s = 0.0;
  for (const Sortie& sortie : tour.plan.sorties) {
    SortieRecord sortie_record;
    SocIntegrator flight(battery.pack, battery.start_soc, current);
    const auto add = [&](planner::PathSample sample, double current_a, FlightPhase phase, int step) {
      sample.t_s = flight.time_s();
      sample.current_a = current_a;
      sample.soc = flight.soc();
      sample.power_w =
          sample.propulsion_power_w +
          pack.operatingPoint(sample.propulsion_power_w, std::clamp(sample.soc, 0.0, 1.0)).terminal_voltage_v *
              pack.avionicsCurrentA();
      sortie_record.samples.push_back(sample);
      sortie_record.phases.push_back(phase);
      sortie_record.steps.push_back(step);
    };
    for (std::size_t step = 0; step < sortie.legs.size(); ++step) {
      const SortieLeg& leg = sortie.legs[step];
      const std::vector<planner::PathSample>& samples = tour.legs[leg.from][leg.to].evaluation.samples;
      std::vector<LoadSample> loads;
      loads.reserve(samples.size());
      for (const planner::PathSample& s : samples) loads.push_back({s.t_s, s.propulsion_power_w});
      flyProfile(flight, loads, [&](std::size_t k, double current_a) {
        add(samples[k], current_a, FlightPhase::Leg, static_cast<int>(step));
      });
      if (leg.to == 0) continue;
      const planner::PathSample& hover_sample = tour.stops[leg.to - 1].hover;
      hover(flight, hover_sample.propulsion_power_w, tour.stops[leg.to - 1].target.dwell_s,
            [&](std::size_t, double current_a) {
              add(hover_sample, current_a, FlightPhase::Dwell, static_cast<int>(step));
            });
    }
    sortie_record.takeoff_s = clock_s;
    sortie_record.turnaround_s = sortie.turnaround_s;
    sortie_record.recharge_s = sortie.recharge_s;
    clock_s += sortie_record.flightS() + sortie.turnaround_s;
    record.sorties.push_back(std::move(sortie_record));
  }
  return record;
}

// The Monte Carlo check of each sortie's landing odds, over its flight record.
void checkLandings(TourResult& tour, const PlanningContext& context, const TourOptions& options) {
  const auto& fit = context.vehicle().calibration;
  if (!fit || options.landing_draws <= 0) return;
  for (std::size_t s = 0; s < tour.plan.sorties.size(); ++s) {
    Sortie& sortie = tour.plan.sorties[s];
    sortie.sampled_landing =
        sampleLanding(context.energy(), tour.record.sorties[s].samples, sortie.lowest_soc,
                      context.battery().pack.usableCapacityAh(), context.battery().reserve_soc, *fit,
                      options.landing_draws, context.options().seed, SortieWind::of(context.fullModel()));
  }
}

// The founding paper's month, for the tour as one mission: each sortie's recorded current,
// then the recharge back to the start SOC, then idle. A projection that cannot run (the tour
// does not fit a day as often as asked, or the pack would run out) says why and is skipped.
DutyProjection projectDuty(const TourResult& tour, const BatterySpec& battery, const TourOptions& options) {
  DutyProjection projection;
  battery::DutyCycle duty;
  for (const SortieRecord& sortie : tour.record.sorties) {
    const battery::LoadProfile flight = dischargeProfile(sortie.samples);
    duty.mission.segments.insert(duty.mission.segments.end(), flight.begin(), flight.end());
    duty.mission.segments.push_back(
        battery::Segment::charge(battery.pack.charge_current_a, 60.0 * options.charge_max_min, battery.start_soc));
  }
  duty.mission.segments.push_back(battery::Segment::idle(60.0 * options.idle_min));
  duty.days = options.days;
  duty.initial_soc = battery.start_soc;
  const double mission_s = duty.mission.periodS();
  const int fit = static_cast<int>(std::floor(duty.day_s / mission_s));
  projection.missions_per_day =
      options.missions_per_day ? *options.missions_per_day : std::min(kDefaultToursPerDay, fit);
  projection.days = options.days;
  projection.mission_min = mission_s / 60.0;
  if (projection.missions_per_day < 1 || projection.missions_per_day > fit) {
    projection.note =
        "not projected: the tour takes " + formatFixed(mission_s / 60.0, 1) + " min with its recharges and idle, so " +
        (fit < 1
             ? std::string("it does not fit in a day even once")
             : "at most " + std::to_string(fit) + " fit in a day, not " + std::to_string(projection.missions_per_day)) +
        "; set the tours per day (--missions-per-day) or shorten the charge (--charge-max-min)";
    return projection;
  }
  duty.missions_per_day = projection.missions_per_day;
  battery::DutyOptions duty_options;
  duty_options.record_first_day = false;
  try {
    projection.result = battery::simulateDuty(battery.pack, duty, duty_options);
  } catch (const battery::DepletionError& e) {
    projection.note = std::string("not projected: ") + e.what() +
                      "; allow a longer charge between tours (--charge-max-min) or fewer tours a day";
  }
  return projection;
}

std::string legName(const TourResult& tour, int from, int to) { return tour.names[from] + " -> " + tour.names[to]; }

// "no path between home at (x, y, z) and NAME at (x, y, z)": where the places are, since a
// viewpoint's position is the planner's choice, not the mission's.
std::string noPathBetween(const TourResult& tour, int from, int to) {
  return flightModeName(tour.mode) + " mode: no path between " + tour.names[from] + " at " +
         formatPoint(tour.places_m[from]) + " and " + tour.names[to] + " at " + formatPoint(tour.places_m[to]) + ": ";
}

// The rules, cost model and planner for the legs between two places.
struct LegPlanner {
  PlanningContext::Mode planning;
  std::unique_ptr<planner::FlightPlanner> planner;
};

planner::LatticeSettings latticeSettings(const TourOptions& options) {
  planner::LatticeSettings settings;
  settings.spacing_m = options.lattice_spacing_m;
  settings.workers = options.workers;
  return settings;
}

LegPlanner legPlanner(const PlanningContext& context, FlightMode mode, const Eigen::Vector3d& a,
                      const Eigen::Vector3d& b) {
  LegPlanner leg{context.mode(mode), nullptr};
  leg.planner =
      std::make_unique<planner::FlightPlanner>(*leg.planning.rules, *leg.planning.model, context.objective(a, b));
  return leg;
}

// One search between two places with a pairwise planner (OMPL's or the lattice A*), the path
// post-processed.
std::vector<Eigen::Vector3d> searchLeg(const TourResult& tour, const LegPlanner& leg, const TourOptions& options,
                                       int from, int to) {
  const Eigen::Vector3d &a = tour.places_m[from], &b = tour.places_m[to];
  planner::PlanRequest request;
  request.start_m = a;
  request.goal_m = b;
  request.planner = options.planner;
  request.time_limit_s = options.time_limit_s;
  request.lattice = latticeSettings(options);
  request.lattice.workers = 1;
  // A clear straight line needs no search: the refinement bends it where that saves charge
  // (up towards a ceiling), and the dense re-check still applies.
  if (options.straight_when_clear && leg.planning.rules->isMotionValid(a, b)) {
    const double pieces = static_cast<double>(request.refinement.max_waypoints - 1);
    return leg.planner->postProcess(planner::subdivide({a, b}, (b - a).norm() / pieces + 1e-9), request.refinement);
  }
  // An anytime planner may miss a narrow passage in a short search: search again, longer.
  std::string failures;
  const int attempts =
      planner::plannerInfo(options.planner).deterministic() ? 1 : static_cast<int>(std::size(kRetryTimeFactors)) + 1;
  for (int attempt = 0; attempt < attempts; ++attempt) {
    if (attempt > 0)
      request.time_limit_s =
          std::min(kRetryTimeFactors[attempt - 1] * options.time_limit_s, planner::PlanRequest::kMaxTimeLimit_s);
    try {
      return leg.planner->plan(request).waypoints;
    } catch (const ceilplan::NoPathError& e) {
      failures += std::string(failures.empty() ? "" : "; ") + e.what();
    } catch (...) {
      rethrowWithContext(flightModeName(tour.mode) + " mode: leg " + legName(tour, from, to) + ": ");
    }
  }
  throw NoPathError(noPathBetween(tour, from, to) + failures);
}

// The roadmap over the map for the tour's places, with what its legs are judged by.
class TourRoadmap {
 public:
  TourRoadmap(const TourResult& tour, const PlanningContext& context, FlightMode mode, const TourOptions& options)
      : tour_(tour),
        planner_(legPlanner(context, mode, tour.places_m.front(), tour.places_m.front())),
        straight_when_clear_(options.straight_when_clear) {
    planner::LatticeSettings settings = latticeSettings(options);
    settings.progress = stageProgress(options, flightModeName(tour.mode) + " mode: building the roadmap");
    roadmap_ = std::make_unique<planner::LatticeRoadmap>(planner_.planner->spaceInformation(), settings);
    // The modes' safety rules are the same: what one roadmap checks, the other need not.
    roadmap_->build(planner_.planner->objective(), tour.places_m, context.latticeValidity(settings.spacing_m));
  }

  // The raw legs from one place to `goals` (every other place when empty): the roadmap's route,
  // shortcut under the pair's rules, or the straight line where that is valid and cheaper.
  // Safe from several threads.
  std::vector<std::vector<Eigen::Vector3d>> legsFrom(int from, const std::vector<int>& goals) const {
    const std::vector<std::optional<planner::RoadmapRoute>> routes =
        goals.empty() ? roadmap_->routesFrom(from) : roadmap_->routesFrom(from, goals);
    const int places = static_cast<int>(tour_.places_m.size());
    std::vector<std::vector<Eigen::Vector3d>> paths(places);
    const auto leg = [&](int to) { paths[to] = bestLeg(from, to, routes[to] ? &routes[to]->waypoints : nullptr); };
    if (goals.empty()) {
      for (int to = 0; to < places; ++to)
        if (to != from) leg(to);
    } else {
      for (int to : goals) leg(to);
    }
    return paths;
  }

  // A large tour's legs out of home and back (safe from several threads): the roadmap's route
  // out of home, one search for every place, reversed for the way back, or the straight line
  // where that is valid and cheaper; not shortcut (the legs a plan flies are post-processed).
  std::vector<Eigen::Vector3d> homeLeg(int from, int to) const {
    std::call_once(home_routes_once_, [this] { home_routes_ = roadmap_->routesFrom(0); });
    const std::optional<planner::RoadmapRoute>& route = home_routes_[from == 0 ? to : from];
    if (!route) return bestLeg(from, to, nullptr);
    std::vector<Eigen::Vector3d> path = route->waypoints;
    if (from != 0) std::reverse(path.begin(), path.end());
    const planner::FlightObjective& objective = planner_.planner->objective();
    const Eigen::Vector3d &a = tour_.places_m[from], &b = tour_.places_m[to];
    if (straight_when_clear_ && planner_.planning.rules->isMotionValid(a, b) &&
        objective.motionCost(a, b) < route->cost)
      return {a, b};
    return path;
  }

 private:
  std::vector<Eigen::Vector3d> bestLeg(int from, int to, const std::vector<Eigen::Vector3d>* route) const {
    const planner::SafetyRules& rules = *planner_.planning.rules;
    const planner::FlightObjective& objective = planner_.planner->objective();
    const Eigen::Vector3d &a = tour_.places_m[from], &b = tour_.places_m[to];
    std::optional<std::vector<Eigen::Vector3d>> best;
    if (route) best = planner::shortcutPath(*route, rules, objective);
    if (straight_when_clear_ && rules.isMotionValid(a, b) &&
        (!best || objective.motionCost(a, b) < objective.pathCost(*best)))
      best = std::vector<Eigen::Vector3d>{a, b};
    if (!best) {
      const std::optional<planner::Blockage> blockage = roadmap_->blockage(from, to);
      throw NoPathError(noPathBetween(tour_, from, to) +
                        (blockage ? blockage->describe() : std::string("the roadmap does not join them")));
    }
    return std::move(*best);
  }

  const TourResult& tour_;
  LegPlanner planner_;
  bool straight_when_clear_;
  std::unique_ptr<planner::LatticeRoadmap> roadmap_;
  mutable std::once_flag home_routes_once_;
  mutable std::vector<std::optional<planner::RoadmapRoute>> home_routes_;
};

// Every leg from one roadmap over the map: each place's route to every other. Raw: the legs a
// plan flies are refined later.
LegTable roadmapLegs(const TourResult& tour, const PlanningContext& context, FlightMode mode,
                     const TourOptions& options, const LegScorer& score) {
  const TourRoadmap roadmap(tour, context, mode, options);
  const RoutesFrom routes_from = [&](int from) { return roadmap.legsFrom(from, {}); };
  return planLegsByPlace(static_cast<int>(tour.places_m.size()), routes_from, score, options.workers,
                         stageProgress(options, flightModeName(tour.mode) + " mode: routing legs"));
}

// What a visit costs in the order: the leg into a stop and the stop's dwell.
double visitCost(const TourResult& tour, const TourLeg& leg, int to) {
  return leg.evaluation.charge_ah + (to > 0 ? tour.stops[to - 1].viewpoint.dwell_charge_ah : 0.0);
}

TourCosts tourCosts(const TourResult& tour, const PlanningContext& context) {
  TourCosts costs;
  costs.names = tour.names;
  costs.current_at_soc = packCurrent(context.energy());
  costs.uncertainty = context.vehicle().calibration;
  const int places = static_cast<int>(tour.places_m.size());
  costs.legs = PairTable<LegCost>(places);
  costs.dwells.assign(places, {});
  for (int k = 1; k < places; ++k) {
    const TourStop& stop = tour.stops[k - 1];
    costs.dwells[k] = {stop.target.dwell_s, stop.viewpoint.dwell_current_a, stop.hover.propulsion_power_w, {}};
    if (costs.uncertainty) {
      // At the start SOC, as the legs are flown, and in the mean wind, as the split flies the
      // hover's power: the stop's hover keeps its power, not an SOC, and the viewpoint's dwell
      // charge is still air's.
      planner::PathSample hover = stop.hover;
      hover.soc = context.battery().start_soc;
      const double charge_ah = costs.current_at_soc(hover.propulsion_power_w, hover.soc) * stop.target.dwell_s / 3600.0;
      costs.dwells[k].sensitivity = steadyChargeSensitivity(context.energy(), hover, charge_ah, stop.target.dwell_s,
                                                            *costs.uncertainty, SortieWind::of(context.fullModel()));
    }
  }
  return costs;
}

SortieOptions sortieOptions(const PlanningOptions& settings) {
  SortieOptions sortie_options;
  sortie_options.ageing_model = settings.ageing_model;
  sortie_options.ageing = ageingModelOptions(settings.temperature_c);
  return sortie_options;
}

// The visiting order and the sorties for the legs as they are, every pair known.
void orderAndSplit(TourResult& tour, const PlanningContext& context) {
  TourCosts legs = tourCosts(tour, context);
  const int places = static_cast<int>(tour.places_m.size());
  CostMatrix costs = CostMatrix::Zero(places, places);
  for (int i = 0; i < places; ++i)
    for (int j = 0; j < places; ++j) {
      if (i == j) continue;
      legs.legs(i, j) = legCost(tour.legs[i][j].evaluation, context);
      // The charge matrix orders by what a visit costs: the leg into a target and its dwell.
      costs(i, j) = visitCost(tour, tour.legs[i][j], j);
    }
  TourOrderOptions order_options;
  order_options.seed = context.options().seed;
  tour.order = orderTour(costs, order_options);
  const CpuTimer timer(tour.times.split_cpu_s);
  tour.plan = planSorties(legs, tour.order.targets, context.battery(), sortieOptions(context.options()));
}

// Positions 0, n / count, 2 n / count, ... of an order of n.
std::set<int> evenlySpaced(int n, int count) {
  std::set<int> positions;
  for (int k = 0; k < count; ++k) positions.insert(static_cast<int>(static_cast<long long>(k) * n / count));
  return positions;
}

// Rounds of a large tour that search the order again (see SparseLegs::orderAndSplit).
constexpr int kSearchRounds = 2;
// A large tour's blocked leg (SparseLegs::firstLeg) is priced at this many times the straight
// line's charge until it is routed.
constexpr double kBlockedLegFactor = 2.0;

// A leg's totals, as a LegScorer's estimate has them, and what it draws at each of its samples,
// as a LegScorer's samples have it: one integration.
struct LegDraws {
  planner::PathEvaluation totals;
  std::vector<LoadSample> loads;
};
using LegLoads = std::function<LegDraws(int from, int to, const std::vector<Eigen::Vector3d>&)>;

// The legs of a large tour: estimated where the order search or the split looks, routed and
// refined where the plan flies.
class SparseLegs {
 public:
  SparseLegs(TourResult& tour, const PlanningContext& context, FlightMode mode, const TourOptions& options,
             const LegScorer& score, const LegScorer& score_totals, const LegLoads& loads)
      : tour_(tour),
        context_(context),
        mode_(mode),
        options_(options),
        score_(score),
        score_totals_(score_totals),
        loads_(loads),
        planning_(context.mode(mode)),
        neighbours_(nearestPlaces(tour.places_m,
                                  std::min<int>(options.neighbours, static_cast<int>(tour.places_m.size()) - 1))) {
    tour_.legs = LegTable(static_cast<int>(tour.places_m.size()));
    home_costs_ = PairTable<LegCost>(static_cast<int>(tour.places_m.size()));
    planner::CostWeights charge;
    charge.per_ah = 1.0;
    min_ah_per_m_ = context.fullModel().minCostPerMetre(charge);
    if (planner::plannerInfo(options.planner).multiQuery())
      roadmap_ = std::make_unique<TourRoadmap>(tour, context, mode, options);
  }

  const std::vector<std::vector<int>>& neighbours() const { return neighbours_; }
  const std::set<int>& lastSplitPoints() const { return last_split_points_; }

  // Estimates the legs not stored yet, on the tour's threads; with `keep_loads`, also keeps what
  // the split flies of each (home_costs_, as profileHomeLegs would) from the same integration.
  void estimate(Pairs pairs, bool keep_loads = false) {
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    Pairs missing;
    for (const auto& [from, to] : pairs)
      if (from != to && !tour_.legs.contains(from, to)) missing.emplace_back(from, to);
    // A pair missing both ways is estimated in one task (the map read once for the two); the
    // reverse of such a pair is left out of `tasks`, and marked in `both`.
    Pairs tasks;
    std::vector<bool> both;
    for (const auto& [from, to] : missing) {
      const bool reverse_missing =
          !viaRoadmap(from, to) && std::binary_search(missing.begin(), missing.end(), std::make_pair(to, from));
      if (reverse_missing && to < from) continue;
      tasks.emplace_back(from, to);
      both.push_back(reverse_missing);
    }
    // Stored once all are estimated: an estimate that throws (no route joins the places) leaves
    // no empty leg behind for a later round to fly.
    std::vector<std::pair<TourLeg, TourLeg>> estimated(tasks.size());
    std::vector<LegCost> kept(keep_loads ? tasks.size() : 0);
    parallelFor(tasks.size(), options_.workers, [&](std::size_t k) {
      const auto [from, to] = tasks[k];
      if (both[k]) {
        estimated[k] = firstLegsBothWays(from, to);
        return;
      }
      std::vector<LoadSample> loads;
      estimated[k].first = firstLeg(from, to, keep_loads ? &loads : nullptr);
      if (keep_loads) kept[k] = homeCost(estimated[k].first.evaluation, loads);
    });
    for (std::size_t k = 0; k < tasks.size(); ++k) {
      const auto [from, to] = tasks[k];
      tour_.legs(from, to) = std::move(estimated[k].first);
      if (both[k]) tour_.legs(to, from) = std::move(estimated[k].second);
      if (keep_loads && !both[k]) home_costs_(from, to) = std::move(kept[k]);
    }
  }

  // Every place's neighbours, both ways.
  void estimateNeighbours() {
    Pairs pairs;
    for (int from = 0; from < static_cast<int>(neighbours_.size()); ++from)
      for (int to : neighbours_[from]) pairs.insert(pairs.end(), {{from, to}, {to, from}});
    estimate(pairs);
  }

  // What a visit costs, estimating the leg on first use (from the order search's thread).
  double visitCost(int from, int to) {
    if (const double* known = knownVisit(from, to)) return *known;
    // Stored once estimated: an estimate that throws (no route joins the places) leaves no empty
    // leg behind, which a later round would fly as a leg without a waypoint.
    TourLeg estimated = firstLeg(from, to, nullptr);
    const TourLeg& leg = tour_.legs(from, to) = std::move(estimated);
    const double cost = mission::visitCost(tour_, leg, to);
    std::vector<std::pair<int, double>>& row = visit_costs_[from];
    row.insert(visitAt(row, to), {to, cost});
    return cost;
  }

  // A lower bound on what a visit costs, the cost itself where the leg is known: the straight
  // line at the least charge per metre any flight draws (with a margin for the model's
  // rounding), then the dwell.
  double visitBound(int from, int to) const {
    if (const double* known = knownVisit(from, to)) return *known;
    return 0.9 * min_ah_per_m_ * (tour_.places_m[to] - tour_.places_m[from]).norm() +
           (to > 0 ? tour_.stops[to - 1].viewpoint.dwell_charge_ah : 0.0);
  }

  // What each stored leg's visit costs, for the order search, which asks tens of millions of
  // times (a lookup in the leg table's map was 4 % of a 0.3 mm/px soffit's CPU): each place's
  // row sorted by destination, kept while the search runs (no leg is routed or refined then).
  void indexVisitCosts() {
    visit_costs_.assign(tour_.places_m.size(), {});
    for (int from = 0; from < tour_.legs.placeCount(); ++from)
      for (const auto& [to, leg] : tour_.legs.row(from))
        visit_costs_[from].emplace_back(to, mission::visitCost(tour_, leg, to));
  }

  const double* knownVisit(int from, int to) const {
    const std::vector<std::pair<int, double>>& row = visit_costs_[from];
    const auto it = visitAt(row, to);
    return it != row.end() && it->first == to ? &it->second : nullptr;
  }

  // Where `to` is, or belongs, in a row of visit_costs_.
  template <class Row>
  static auto visitAt(Row& row, int to) -> decltype(row.begin()) {
    return std::lower_bound(row.begin(), row.end(), to,
                            [](const auto& entry, int place) { return entry.first < place; });
  }

  // The order, from the last one (or a nearest-neighbour one), then the sorties: at evenly
  // spaced split points first, then also around the sorties' starts. Legs the plan flies are
  // refined between rounds, which changes their cost (free mode's refinement keeps the
  // standoff, at a price in charge), so after kSearchRounds rounds the order is kept and the
  // sorties may only keep or merge their boundaries: the loop ends once those legs are refined.
  void orderAndSplit(int round) {
    const int targets = static_cast<int>(tour_.stops.size());
    split_memo_.clear();  // refining and routing between rounds changed legs
    if (round > kSearchRounds && !tour_.plan.sorties.empty()) {
      std::set<int> boundaries;
      int position = 0;
      for (const Sortie& sortie : tour_.plan.sorties) {
        boundaries.insert(position);
        position += static_cast<int>(sortie.targets.size());
      }
      try {
        tour_.plan = split(tour_.order.targets, boundaries);
        return;
      } catch (const InfeasibleError&) {
        // Refined legs no longer fit those sorties: split afresh.
      }
    } else {
      std::vector<std::vector<int>> starts{tour_.order.targets};
      if (starts.front().empty()) starts.front() = nearestNeighbourOrder(tour_.places_m, neighbours_);
      indexVisitCosts();
      tour_.order = neighbourListTour(
          targets, [this](int from, int to) { return visitCost(from, to); },
          [this](int from, int to) { return visitBound(from, to); }, neighbours_, starts,
          round == 1 ? options_.order_kicks : 0, context_.options().seed);
      std::vector<std::vector<std::pair<int, double>>>().swap(visit_costs_);
    }
    const std::vector<int>& order = tour_.order.targets;
    // Split points: evenly spaced, at least --split-points of them, more where a stretch between
    // two is more than a sortie can fly; then, with the sorties that needs known, spaced
    // ~sqrt(targets per sortie / 2) apart at most. From each point the split flies about a
    // sortie's targets, so the points cost targets x sqrt(targets per sortie / 2) flights, as
    // much as the windows of every position a spacing either side of the sorties' starts that
    // follow: the split grows with the targets, not with their square.
    int coarse = std::max(1, std::min(options_.split_points, targets));
    std::set<int> split_points = flyableSplitPoints(order, evenlySpaced(targets, coarse));
    tour_.plan = split(order, split_points);
    const double per_sortie = static_cast<double>(targets) / static_cast<double>(tour_.plan.sorties.size());
    const int spacing = std::max(1, static_cast<int>(std::sqrt(per_sortie / 2.0)));
    if (spacing < (targets + coarse - 1) / coarse) {
      coarse = (targets + spacing - 1) / spacing;
      const std::set<int> closer = evenlySpaced(targets, coarse);
      split_points.insert(closer.begin(), closer.end());
      tour_.plan = split(order, split_points);
    }
    if (coarse < targets && tour_.plan.sorties.size() > 1) {
      const int stride = (targets + coarse - 1) / coarse;
      int position = 0;
      for (const Sortie& sortie : tour_.plan.sorties) {
        if (position > 0)
          for (int p = std::max(0, position - stride); p <= std::min(targets - 1, position + stride); ++p)
            split_points.insert(p);
        position += static_cast<int>(sortie.targets.size());
      }
      tour_.plan = split(order, split_points);
    }
  }

  // The legs out of home to, and back from, the ends of every stretch between split points:
  // what a sortie that cannot fly may need refined. None before there is an order (the order
  // search itself may have failed).
  Pairs homeLegs(const std::vector<int>& order, const std::set<int>& split_points) const {
    Pairs pairs;
    if (order.empty()) return pairs;
    for (int p : split_points) {
      pairs.emplace_back(0, order[p]);
      if (p > 0) pairs.emplace_back(order[p - 1], 0);
    }
    pairs.emplace_back(order.back(), 0);
    return pairs;
  }

  // Scores the legs `pairs` (stored) in full where they are estimates, which have totals only,
  // on the tour's threads: the samples are what the split and the flight record fly, and a leg
  // flown as estimated reports the figures only samples give (clearance, ceiling gap, assumed
  // free). A blocked estimate keeps its priced-up charge.
  void profile(Pairs pairs) {
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    Pairs bare;
    std::vector<TourLeg*> cells;
    for (const auto& [from, to] : pairs) {
      TourLeg& leg = tour_.legs(from, to);
      if (leg.evaluation.samples.empty()) bare.emplace_back(from, to), cells.push_back(&leg);
    }
    parallelFor(bare.size(), options_.workers, [&](std::size_t k) {
      planner::PathEvaluation evaluation = score_(bare[k].first, bare[k].second, cells[k]->waypoints);
      if (!cells[k]->routed) evaluation.charge_ah *= kBlockedLegFactor;
      cells[k]->evaluation = std::move(evaluation);
    });
  }

  // Routes the legs `which` that are estimates: over the roadmap (one search from each place
  // to the estimates out of it), or with a pairwise planner (then post-processed).
  void route(const Pairs& which) {
    Pairs estimates;
    for (const auto& [from, to] : which)
      if (!tour_.legs.at(from, to).routed) estimates.emplace_back(from, to);
    if (estimates.empty()) return;
    std::sort(estimates.begin(), estimates.end());
    const FractionCallback progress = stageProgress(
        options_, flightModeName(tour_.mode) + " mode: routing " + std::to_string(estimates.size()) + " legs");
    if (roadmap_) {
      std::map<int, std::vector<int>> goals;
      for (const auto& [from, to] : estimates) goals[from].push_back(to);
      const std::vector<std::pair<int, std::vector<int>>> searches(goals.begin(), goals.end());
      std::vector<std::vector<std::vector<Eigen::Vector3d>>> paths(searches.size());
      parallelFor(
          searches.size(), options_.workers,
          [&](std::size_t k) { paths[k] = roadmap_->legsFrom(searches[k].first, searches[k].second); }, progress);
      for (std::size_t k = 0; k < searches.size(); ++k)
        for (int to : searches[k].second) tour_.legs(searches[k].first, to).waypoints = std::move(paths[k][to]);
      parallelFor(estimates.size(), options_.workers, [&](std::size_t k) {
        const auto [from, to] = estimates[k];
        TourLeg& leg = *tour_.legs.find(from, to);
        leg.evaluation = score_(from, to, leg.waypoints);
        leg.routed = true;
      });
      return;
    }
    const LegRework search = [&](int from, int to, const std::vector<Eigen::Vector3d>&) {
      return searchLeg(tour_, legPlanner(context_, mode_, tour_.places_m[from], tour_.places_m[to]), options_, from,
                       to);
    };
    routeLegs(tour_.legs, estimates, search, score_, options_.workers, progress);
    for (const auto& [from, to] : estimates) tour_.legs(from, to).refined = true;
  }

 private:
  // A leg as the search first sees it: the straight line where it is valid (near neighbours
  // need no search; refinement bends it where that saves charge), else an L or a dogleg round
  // what blocks it (turnCandidates); out of home and back, the roadmap's route or the straight
  // line, the cheaper. Else an estimate, routed once a plan flies it: the straight line scored at
  // kBlockedLegFactor times its charge (a search here, in a pocket of the structure, may take
  // a tenth of a second, and the order avoids such legs anyway).
  // `loads` (when given) gains what the leg draws at each sample (scoredEstimate).
  TourLeg firstLeg(int from, int to, std::vector<LoadSample>* loads) const {
    if (viaRoadmap(from, to)) return scoredEstimate(from, to, roadmap_->homeLeg(from, to), true, loads);
    return firstLeg(from, to, shapeBetween(tour_.places_m[from], tour_.places_m[to]), loads);
  }

  // firstLeg(from, to) and firstLeg(to, from), the same legs, with the map read once for the two.
  std::pair<TourLeg, TourLeg> firstLegsBothWays(int from, int to) const {
    const LegShape shape = shapeBetween(tour_.places_m[from], tour_.places_m[to]);
    return {firstLeg(from, to, shape, nullptr), firstLeg(to, from, shape, nullptr)};
  }

  bool viaRoadmap(int from, int to) const { return roadmap_ && (from == 0 || to == 0); }

  // What the safety rules say of the straight line between two places and of the turns round it,
  // either way: a straight motion visits the same states from either end, so it is valid both
  // ways or neither, and so is a turn's.
  struct LegShape {
    bool straight = false;               // the straight line is valid
    std::vector<Eigen::Vector3d> turns;  // where it is not, the valid turnCandidates
  };

  LegShape shapeBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    LegShape shape;
    if (!options_.straight_when_clear) return shape;
    const planner::SafetyRules& rules = *planning_.rules;
    shape.straight = rules.isMotionValid(a, b);
    if (shape.straight) return shape;
    for (const Eigen::Vector3d& turn : turnCandidates(a, b))
      if ((turn - a).norm() >= 1e-6 && (turn - b).norm() >= 1e-6 && rules.isStateValid(turn) &&
          rules.isMotionValid(a, turn) && rules.isMotionValid(turn, b))
        shape.turns.push_back(turn);
    return shape;
  }

  // The leg from `from` to `to` that `shape` (of the line between them) allows: the straight
  // line, else the valid turn of least charge this way (the first in turnCandidates' order on a
  // tie), else the blocked estimate.
  TourLeg firstLeg(int from, int to, const LegShape& shape, std::vector<LoadSample>* loads) const {
    const Eigen::Vector3d &a = tour_.places_m[from], &b = tour_.places_m[to];
    if (shape.straight) return scoredEstimate(from, to, {a, b}, true, loads);
    std::optional<Eigen::Vector3d> best;
    double best_cost = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& turn : turnCandidates(a, b)) {
      if (std::find(shape.turns.begin(), shape.turns.end(), turn) == shape.turns.end()) continue;
      const double cost = planning_.model->integrate(a, turn).charge_ah + planning_.model->integrate(turn, b).charge_ah;
      if (cost < best_cost) {
        best_cost = cost;
        best = turn;
      }
    }
    if (best) return scoredEstimate(from, to, {a, *best, b}, true, loads);
    return scoredEstimate(from, to, {a, b}, false, loads);
  }

  // Between near neighbours the straight line is often blocked by a flange or a pier cap's
  // corner: an L round it (level then vertical, vertical then level), or a dogleg half a metre
  // or a metre above or below the middle. The same points from either end, the Ls swapped.
  static std::array<Eigen::Vector3d, 6> turnCandidates(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const Eigen::Vector3d middle = 0.5 * (a + b);
    return {Eigen::Vector3d(b.x(), b.y(), a.z()),
            Eigen::Vector3d(a.x(), a.y(), b.z()),
            Eigen::Vector3d(middle + 0.5 * Eigen::Vector3d::UnitZ()),
            Eigen::Vector3d(middle - 0.5 * Eigen::Vector3d::UnitZ()),
            Eigen::Vector3d(middle + Eigen::Vector3d::UnitZ()),
            Eigen::Vector3d(middle - Eigen::Vector3d::UnitZ())};
  }

  // An estimate on `waypoints`: its totals (a blocked leg's charge priced up). The order search
  // reads the totals only, and about twenty legs are estimated per place: their samples would
  // hold most of a large tour's memory, and the lookups only samples need (clearance) cost time.
  // profile() scores them in full where a split needs them. With `loads`, what the leg draws
  // at each sample too, from the same integration (the same totals, to the bit).
  TourLeg scoredEstimate(int from, int to, std::vector<Eigen::Vector3d> waypoints, bool routed,
                         std::vector<LoadSample>* loads = nullptr) const {
    TourLeg leg;
    leg.waypoints = std::move(waypoints);
    leg.routed = routed;
    if (loads) {
      LegDraws draws = loads_(from, to, leg.waypoints);
      leg.evaluation = std::move(draws.totals);
      *loads = std::move(draws.loads);
    } else {
      leg.evaluation = score_totals_(from, to, leg.waypoints);
    }
    if (!leg.routed) leg.evaluation.charge_ah *= kBlockedLegFactor;
    return leg;
  }

  // The legs a split at `split_points` may fly, estimated where they are not stored yet. The
  // profiles kept for legs out of home and back (home_costs_) are lent to the costs, not copied: a
  // long structure's way home is thousands of samples at each of a thousand split points. The
  // costs hold them until the SplitCosts is destroyed, which gives them back (a split may throw).
  class SplitCosts {
   public:
    SplitCosts(SparseLegs& legs, const std::vector<int>& order, const std::set<int>& split_points) : legs_(legs) {
      Pairs home = legs.homeLegs(order, split_points);
      std::sort(home.begin(), home.end());
      home.erase(std::unique(home.begin(), home.end()), home.end());
      // A leg out of home or back is estimated and profiled at once (an uncalibrated vehicle's
      // profile is its samples' loads): a long structure's is as long as the way home.
      legs.estimate(home, !legs.context_.vehicle().calibration);
      legs.profileHomeLegs(home);
      Pairs consecutive;
      for (std::size_t k = 1; k < order.size(); ++k) consecutive.emplace_back(order[k - 1], order[k]);
      legs.estimate(consecutive);
      legs.profile(consecutive);
      costs_ = tourCosts(legs.tour_, legs.context_);
      for (const auto& [from, to] : consecutive)
        costs_.legs(from, to) = legCost(legs.tour_.legs.at(from, to).evaluation, legs.context_);
      for (const auto& [from, to] : home) {
        const TourLeg& leg = legs.tour_.legs.at(from, to);
        if (!leg.evaluation.samples.empty()) {  // routed or refined since: its own samples are the ones to fly
          costs_.legs(from, to) = legCost(leg.evaluation, legs.context_);
        } else {
          costs_.legs(from, to) = std::move(legs.home_costs_(from, to));
          lent_.emplace_back(from, to);
        }
      }
      legs.last_split_points_ = split_points;
    }
    SplitCosts(const SplitCosts&) = delete;
    SplitCosts& operator=(const SplitCosts&) = delete;
    ~SplitCosts() {
      for (const auto& [from, to] : lent_) legs_.home_costs_(from, to) = std::move(costs_.legs(from, to));
    }
    const TourCosts& costs() const { return costs_; }

   private:
    SparseLegs& legs_;
    TourCosts costs_;
    Pairs lent_;
  };

  // Scores the legs of `pairs` that have neither samples nor a profile kept (home_costs_), on the
  // tour's threads, and keeps their profiles in a hover's steps: the split flies thousands of
  // ways home from its split points, and a way home as long as the structure is tens of thousands
  // of samples, in steps a few hundred.
  void profileHomeLegs(Pairs pairs) {
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    Pairs bare;
    for (const auto& [from, to] : pairs)
      if (tour_.legs.at(from, to).evaluation.samples.empty() && !home_costs_.contains(from, to))
        bare.emplace_back(from, to);
    std::vector<LegCost> costs(bare.size());
    parallelFor(bare.size(), options_.workers, [&](std::size_t k) {
      const auto [from, to] = bare[k];
      const TourLeg& leg = tour_.legs.at(from, to);
      planner::PathEvaluation evaluation = leg.evaluation;  // its totals as estimated (a blocked leg's doubled)
      if (context_.vehicle().calibration) {
        evaluation.samples = score_(from, to, leg.waypoints).samples;  // the sensitivities read every sample
        costs[k] = legCost(evaluation, context_);
        costs[k].load_profile = stepProfile(costs[k].load_profile, kHoverStepS);
      } else {
        costs[k] = homeCost(evaluation, loads_(from, to, leg.waypoints).loads);
      }
    });
    for (std::size_t k = 0; k < bare.size(); ++k) home_costs_(bare[k].first, bare[k].second) = std::move(costs[k]);
  }

  // What the split flies of an uncalibrated vehicle's leg out of home or back: its estimate's
  // totals and its loads in a hover's steps.
  LegCost homeCost(const planner::PathEvaluation& estimate, const std::vector<LoadSample>& loads) const {
    LegCost cost = legCost(estimate, context_);
    cost.load_profile = stepProfile(loads, kHoverStepS);
    return cost;
  }

  SortiePlan split(const std::vector<int>& order, const std::set<int>& split_points) {
    const CpuTimer timer(tour_.times.split_cpu_s);
    SortieOptions sortie_options = sortieOptions(context_.options());
    sortie_options.split_points.assign(split_points.begin(), split_points.end());
    const SplitCosts costs(*this, order, split_points);
    return planSorties(costs.costs(), order, context_.battery(), sortie_options, split_memo_);
  }

  // `split_points` and more, until one sortie flies each stretch between them alone: a stretch
  // no sortie flies is halved, down to single targets (which planSorties then names).
  std::set<int> flyableSplitPoints(const std::vector<int>& order, std::set<int> split_points) {
    const CpuTimer timer(tour_.times.split_cpu_s);
    const int targets = static_cast<int>(order.size());
    for (bool halved = true; halved;) {
      halved = false;
      const std::vector<int> points(split_points.begin(), split_points.end());
      const SplitCosts costs(*this, order, split_points);
      for (int first : stretchesNoSortieFlies(costs.costs(), order, context_.battery(), points)) {
        const auto next = split_points.upper_bound(first);
        const int end = next == split_points.end() ? targets : *next;
        if (end - first < 2) continue;
        split_points.insert(first + (end - first) / 2);
        halved = true;
      }
    }
    return split_points;
  }

  TourResult& tour_;
  const PlanningContext& context_;
  FlightMode mode_;
  const TourOptions& options_;
  const LegScorer& score_;
  const LegScorer& score_totals_;  // an estimate's: evaluatePathTotals, what score_ gives without samples
  const LegLoads& loads_;          // what score_'s samples draw, without the rest of each sample
  PlanningContext::Mode planning_;
  std::vector<std::vector<int>> neighbours_;
  std::unique_ptr<TourRoadmap> roadmap_;
  // What the split flies of a leg out of home or back while the leg is the estimate it was: its
  // load profile, kept apart from the leg. A large tour needs these legs at every split point (a
  // few thousand), each as long as the way home, and the plan flies a few of them: their samples
  // (13 numbers each, where the profile keeps 2) held a third of a mode's memory. A leg with
  // samples was routed or refined since (SplitCosts flies those samples instead).
  PairTable<LegCost> home_costs_;
  SortieMemo split_memo_;                                         // the sorties this round's splits flew home
  std::vector<std::vector<std::pair<int, double>>> visit_costs_;  // indexVisitCosts
  std::set<int> last_split_points_;
  double min_ah_per_m_ = 0.0;
};

// The photos as flown: in flying order, each with its sortie and the time of the shot on the
// tour's clock (the end of the hold, or the passing), and the re-check of what they cover.
void recordPhotos(TourResult& tour, const Mission& mission, const PlanningContext& context,
                  const TourOptions& options) {
  std::vector<CameraPose> poses;
  for (std::size_t s = 0; s < tour.plan.sorties.size(); ++s) {
    const SortieRecord& record = tour.record.sorties[s];
    std::vector<double> shot_s(tour.plan.sorties[s].legs.size(), 0.0);
    for (std::size_t i = 0; i < record.samples.size(); ++i) shot_s[record.steps[i]] = record.samples[i].t_s;
    for (std::size_t step = 0; step < tour.plan.sorties[s].legs.size(); ++step) {
      const int to = tour.plan.sorties[s].legs[step].to;
      if (to == 0 || !tour.stops[to - 1].photo) continue;
      const std::size_t k = *tour.stops[to - 1].photo;
      PhotoRow row = photoRow(*tour.coverage, k, static_cast<int>(tour.photos.size() + 1));
      row.sortie = static_cast<int>(s + 1);
      row.t_s = record.takeoff_s + shot_s[step];
      tour.photos.push_back(row);
      poses.push_back(tour.coverage->photos[k].pose);
    }
  }
  std::vector<RegionSurface> surfaces;
  std::vector<std::vector<std::uint8_t>> reachable;
  for (const RegionPlan& region : tour.coverage->regions) {
    surfaces.push_back(region.surface);
    reachable.push_back(region.reachable);
  }
  tour.coverage_check = checkCoverage(context.map().tree(), *mission.camera, mission.surfaces, surfaces, reachable,
                                      poses, options.workers);
}

// Releases the samples of the legs the plan does not fly: they served the order search and the
// split only, and a large tour (thousands of photos, about twenty legs stored for each) would
// otherwise hold hundreds of megabytes of them while its other mode plans.
void releaseUnflownSamples(TourResult& tour) {
  std::set<std::pair<int, int>> flown;
  for (const Sortie& sortie : tour.plan.sorties)
    for (const SortieLeg& leg : sortie.legs) flown.emplace(leg.from, leg.to);
  for (int from = 0; from < tour.legs.placeCount(); ++from) {
    std::vector<int> unflown;
    for (const auto& entry : tour.legs.row(from))
      if (flown.count({from, entry.first}) == 0) unflown.push_back(entry.first);
    for (const int to : unflown) std::vector<planner::PathSample>().swap(tour.legs.find(from, to)->evaluation.samples);
  }
}

// The tour with stops where `reachable` holds (every valid place when empty).
TourResult planTourWith(const Mission& mission, const PlanningContext& context, FlightMode mode,
                        const TourOptions& options, const planner::ReachablePredicate& reachable) {
  TourResult tour;
  tour.mode = mode;
  tour.options = options;
  tour.planning = context.options();
  tour.start_soc = context.battery().start_soc;
  tour.reserve_soc = context.battery().reserve_soc;
  Stopwatch clock;

  tour.stops = chooseStops(mission, context, mode, options, reachable, tour);
  tour.names.push_back("home");
  tour.places_m.push_back(mission.home_m);
  for (const TourStop& stop : tour.stops) {
    tour.names.push_back(stop.target.name);
    tour.places_m.push_back(stop.viewpoint.position_m);
  }
  tour.times.stops_s = clock.lap_s(tour.times.stops_cpu_s);

  const battery::Pack& pack = context.battery().pack;
  // On the move, the legs from photo to photo are flown no faster than the slower one allows.
  const auto speedCap = [&](int from, int to) {
    double cap = std::numeric_limits<double>::infinity();
    if (from > 0 && to > 0 && tour.stops[from - 1].photo && tour.stops[to - 1].photo)
      for (const int place : {from, to})
        if (const auto& speed = tour.stops[place - 1].max_speed_m_s) cap = std::min(cap, *speed);
    return cap;
  };
  const LegScorer score = [&](int from, int to, const std::vector<Eigen::Vector3d>& waypoints) {
    return planner::evaluatePath(context.fullModel(), pack, tour.start_soc, waypoints, speedCap(from, to));
  };
  const LegScorer score_totals = [&](int from, int to, const std::vector<Eigen::Vector3d>& waypoints) {
    return planner::evaluatePathTotals(context.fullModel(), pack, tour.start_soc, waypoints, speedCap(from, to));
  };
  const LegLoads loads = [&](int from, int to, const std::vector<Eigen::Vector3d>& waypoints) {
    std::vector<planner::PathDraw> draws;
    LegDraws leg;
    leg.totals =
        planner::evaluatePathTotals(context.fullModel(), pack, tour.start_soc, waypoints, speedCap(from, to), draws);
    leg.loads.reserve(draws.size());
    for (const planner::PathDraw& draw : draws) leg.loads.push_back({draw.t_s, draw.propulsion_power_w});
    return leg;
  };
  const auto legPlannerFor = [&](int from, int to) {
    return legPlanner(context, mode, tour.places_m[from], tour.places_m[to]);
  };
  const int places = static_cast<int>(tour.places_m.size());
  const bool all_pairs = places <= options.all_pairs_max_places;
  const planner::RefinementOptions refinement;
  std::unique_ptr<SparseLegs> sparse;
  if (planner::plannerInfo(options.planner).multiQuery()) {
    if (all_pairs) tour.legs = roadmapLegs(tour, context, mode, options, score);
  } else {
    const PairPlanner plan_pair = [&](int from, int to) {
      return searchLeg(tour, legPlannerFor(from, to), options, from, to);
    };
    if (all_pairs)
      tour.legs = planLegsByPair(places, plan_pair, score, options.workers,
                                 stageProgress(options, flightModeName(tour.mode) + " mode: planning legs"));
  }
  if (!all_pairs) {
    sparse = std::make_unique<SparseLegs>(tour, context, mode, options, score, score_totals, loads);
    sparse->estimateNeighbours();
  }
  tour.times.legs_s = clock.lap_s(tour.times.legs_cpu_s);

  // Order and split with the legs as they are, post-process the raw legs the plan flies (a
  // large tour routes the estimates among them first), and again until the plan flies
  // post-processed legs only (each round refines at least one leg).
  const LegRefiner refine = [&](int from, int to, const std::vector<Eigen::Vector3d>& raw) {
    try {
      return legPlannerFor(from, to).planner->postProcess(raw, refinement);
    } catch (...) {
      rethrowWithContext(flightModeName(tour.mode) + " mode: leg " + legName(tour, from, to) + ": ");
    }
  };
  // A straight hop between two photos is flown as it is: a pass is a stretch of such hops, and
  // refining a hop of a few decimetres bends it by millimetres while multiplying the autopilot's
  // mission items.
  const auto passHop = [&](int from, int to, const TourLeg& leg) {
    return from > 0 && to > 0 && tour.stops[from - 1].photo && tour.stops[to - 1].photo && leg.routed &&
           leg.waypoints.size() == 2;
  };
  const auto unrefined = [&](const Pairs& candidates) {
    Pairs raw;
    for (const auto& [from, to] : candidates) {
      const TourLeg& leg = tour.legs.at(from, to);
      if (!leg.refined && !passHop(from, to, leg)) raw.emplace_back(from, to);
    }
    std::sort(raw.begin(), raw.end());
    raw.erase(std::unique(raw.begin(), raw.end()), raw.end());
    return raw;
  };
  for (;;) {
    ++tour.times.rounds;
    Pairs flown;
    try {
      if (sparse) {
        sparse->orderAndSplit(tour.times.rounds);
      } else {
        orderAndSplit(tour, context);
      }
      for (const Sortie& sortie : tour.plan.sorties)
        for (const SortieLeg& leg : sortie.legs) flown.emplace_back(leg.from, leg.to);
    } catch (const InfeasibleError&) {
      // A target no sortie can reach and return from, perhaps only on raw legs: refine the
      // legs out of home and back, then decide.
      if (sparse) {
        flown = sparse->homeLegs(tour.order.targets, sparse->lastSplitPoints());
      } else {
        for (int k = 1; k < places; ++k) flown.insert(flown.end(), {{0, k}, {k, 0}});
      }
      if (unrefined(flown).empty()) throw;
    }
    tour.times.order_s += clock.lap_s(tour.times.order_cpu_s);
    const Pairs raw_legs = unrefined(flown);
    if (raw_legs.empty()) break;
    if (sparse) {
      sparse->route(raw_legs);
      tour.times.routing_s += clock.lap_s(tour.times.routing_cpu_s);
    }
    const Pairs to_refine = unrefined(raw_legs);
    refineLegs(tour.legs, to_refine, refine, score, options.workers,
               stageProgress(options, flightModeName(tour.mode) + " mode: refining " +
                                          std::to_string(to_refine.size()) + " legs"));
    tour.times.refining_s += clock.lap_s(tour.times.refining_cpu_s);
  }

  if (sparse) {  // the flight record flies the samples of every leg flown
    Pairs flown;
    for (const Sortie& sortie : tour.plan.sorties)
      for (const SortieLeg& leg : sortie.legs) flown.emplace_back(leg.from, leg.to);
    sparse->profile(flown);
    sparse.reset();  // its roadmap and the split's profiles, before the flight record grows
  }

  // The independent re-check of every leg flown (the planner checked them too), on the tour's
  // threads; the first leg in flying order that fails is the one named.
  std::vector<const SortieLeg*> flown_legs;
  for (const Sortie& sortie : tour.plan.sorties)
    for (const SortieLeg& leg : sortie.legs) flown_legs.push_back(&leg);
  parallelFor(flown_legs.size(), options.workers, [&](std::size_t k) {
    const SortieLeg& leg = *flown_legs[k];
    if (const auto violation = context.baseRules().checkPathDensely(tour.legs.at(leg.from, leg.to).waypoints))
      throw Error(flightModeName(tour.mode) + " mode: leg " + legName(tour, leg.from, leg.to) +
                  " fails the dense re-check: " + *violation);
  });

  tour.unknown_space = context.environment().index()->unknownSpace();
  tour.unknown_summary = context.environment().index()->unknownSummary();
  for (const Sortie& sortie : tour.plan.sorties)
    for (const SortieLeg& leg : sortie.legs)
      tour.assumed_free_m += tour.legs[leg.from][leg.to].evaluation.assumed_free_m;
  if (mode == FlightMode::Free)
    tour.standoff = measureTourStandoff(tour, context.environment(), context.options().standoff_m);
  tour.record = recordFlight(tour, context);
  checkLandings(tour, context, options);
  std::vector<RouteStop> route_stops;
  for (const TourStop& stop : tour.stops)
    route_stops.push_back({stop.target.name, stop.target.point_m, stop.target.dwell_s, stop.yaw_deg,
                           stop.gimbal_pitch_deg, stop.contact});
  tour.routes = sortieRoutes(tour.plan, tour.legs, route_stops, mission);
  assignTakeoffAndLanding(tour.routes, context.baseRules());
  tour.trajectories = routeTrajectories(tour.routes, mission, context.baseRules());
  for (const char* model : {"fec", "xu", "woehler", "schmalstieg"})
    tour.wear.push_back(planWear(tour.plan, model, ageingModelOptions(context.options().temperature_c)));
  tour.duty = projectDuty(tour, context.battery(), options);
  releaseUnflownSamples(tour);
  tour.times.record_s = clock.lap_s(tour.times.record_cpu_s);
  if (tour.coverage) {
    recordPhotos(tour, mission, context, options);
    tour.times.coverage_check_s = clock.lap_s();
  }
  return tour;
}

}  // namespace

void TourOptions::validate() const {
  if (all_pairs_max_places < 2 || neighbours < 1 || split_points < 1 || order_kicks < 0)
    throw InputError(
        "tour options: all_pairs_max_places must be at least 2, neighbours and split_points at least 1, "
        "order_kicks at least 0");
  latticeSettings(*this).validate();
  planner::plannerInfo(planner);  // an unknown name: refused by the factory
  if (free_standoff_max_m && !(*free_standoff_max_m > 0.0 && *free_standoff_max_m <= InspectionTarget::kMaxStandoff_m))
    throw InputError("tour options: free_standoff_max_m must be in (0, " +
                     formatNumber(InspectionTarget::kMaxStandoff_m) + "] m, got " + formatNumber(*free_standoff_max_m));
  // The duty projection's times and counts, under the same rules as a route comparison's.
  DutyOptions duty;
  duty.idle_min = idle_min;
  duty.charge_max_min = charge_max_min;
  duty.missions_per_day = missions_per_day.value_or(kDefaultToursPerDay);
  duty.days = days;
  duty.validate();
}

TourResult planTour(const Mission& mission, const PlanningContext& context, FlightMode mode,
                    const TourOptions& options) {
  options.validate();
  // Home as the planner would check a start (the same rules in both modes).
  if (!context.baseRules().isStateValid(mission.home_m))
    throw ceilplan::InputError(mission.name() + ": home " + formatPoint(mission.home_m) +
                               " is not a valid position for the vehicle (inside or too close to a structure, or "
                               "outside the map); move it into free space");
  try {
    return planTourWith(mission, context, mode, options, {});
  } catch (const NoPathError&) {
    // A stop where no route from home reaches: choose the stops again among the places a flood
    // from home reaches (the best reachable viewpoint of a target, the reachable photo poses).
    // The flood is sound but sees no passage narrower than its lattice, which the roadmap's
    // refinement finds: hence only now, after the first choice failed.
    const planner::ReachableSpace& space =
        context.reachableFrom(mission.home_m, options.lattice_spacing_m, options.workers);
    TourResult tour = planTourWith(mission, context, mode, options,
                                   [&space](const Eigen::Vector3d& body_m) { return space.reaches(body_m); });
    tour.stops_rechosen = true;
    return tour;
  }
}

}  // namespace ceilplan::mission
