#include "ceilplan/mission/tour_planner.hpp"

#include "ceilplan/mission/duty_projection.hpp"

#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/energy/lipo_open_circuit_voltage.hpp"
#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/lattice_roadmap.hpp"
#include "ceilplan/planner/path_refinement.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <algorithm>
#include <iterator>
#include <memory>
#include <stdexcept>

namespace ceilplan::mission {
namespace {

// The tour's progress callback for one stage.
FractionCallback stageProgress(const TourOptions& options, const std::string& stage) {
  if (!options.progress) return {};
  return [callback = options.progress, stage](double fraction) { callback(stage, fraction); };
}

// The rotors stay this much farther from the surface at a viewpoint than the planner's
// minimum gap, so the leg's end passes the dense re-check with its rounding.
constexpr double kViewpointGapMarginM = 0.01;

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
  hover.propulsion_power_w = model.breakdown(conditions, planner::Velocity{}, context.battery().start_soc).propulsionW();
  return hover;
}

std::vector<TourStop> chooseStops(const Mission& mission, const PlanningContext& context, FlightMode mode,
                                  const TourOptions& options) {
  ViewpointOptions viewpoint_options;
  viewpoint_options.mode = mode;
  viewpoint_options.min_ceiling_gap_m = context.options().min_ceiling_gap_m + kViewpointGapMarginM;
  viewpoint_options.standoff_m = context.options().standoff_m;
  const environment::Environment& environment = context.environment();
  std::vector<TourStop> stops;
  for (const InspectionTarget& target : mission.targets) {
    requireOnStructure(target, environment);  // as the mission gives it, before free mode widens the range
    TourStop stop{target, {}, {}};
    // A conventional planner inspects from where its standoff lets it, with a zoom lens.
    if (mode == FlightMode::Free)
      stop.target.standoff_max_m = std::max(target.standoff_max_m, options.free_standoff_max_m);
    stop.viewpoint = chooseViewpoint(stop.target, environment, context.energy(), viewpoint_options);
    stop.hover = hoverSample(context, stop.viewpoint.position_m);
    stops.push_back(stop);
  }
  return stops;
}

LegCost legCost(const planner::PathEvaluation& evaluation) {
  LegCost cost;
  cost.charge_ah = evaluation.charge_ah;
  cost.duration_s = evaluation.duration_s;
  cost.mean_current_a = evaluation.mean_current_a;
  for (const planner::PathSample& s : evaluation.samples) cost.load_profile.push_back({s.t_s, s.propulsion_power_w});
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
      sample.power_w = sample.propulsion_power_w +
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
      for (const planner::PathSample& s : samples) loads.push_back({s.t_s, s.propulsion_power_w});
      flyProfile(flight, loads, [&](std::size_t k, double current_a) {
        add(samples[k], current_a, FlightPhase::Leg, static_cast<int>(step));
      });
      if (leg.to == 0) continue;
      const planner::PathSample& hover_sample = tour.stops[leg.to - 1].hover;
      hover(flight, hover_sample.propulsion_power_w, tour.stops[leg.to - 1].target.dwell_s,
            [&](std::size_t, double current_a) { add(hover_sample, current_a, FlightPhase::Dwell, static_cast<int>(step)); });
    }
    sortie_record.takeoff_s = clock_s;
    sortie_record.turnaround_s = sortie.turnaround_s;
    sortie_record.recharge_s = sortie.recharge_s;
    clock_s += sortie_record.flightS() + sortie.turnaround_s;
    record.sorties.push_back(std::move(sortie_record));
  }
  return record;
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
  projection.missions_per_day = options.missions_per_day ? *options.missions_per_day : std::min(kDefaultToursPerDay, fit);
  projection.days = options.days;
  projection.mission_min = mission_s / 60.0;
  if (projection.missions_per_day < 1 || projection.missions_per_day > fit) {
    projection.note = "not projected: the tour takes " + formatFixed(mission_s / 60.0, 1) +
                      " min with its recharges and idle, so " +
                      (fit < 1 ? std::string("it does not fit in a day even once")
                               : "at most " + std::to_string(fit) + " fit in a day, not " +
                                     std::to_string(projection.missions_per_day)) +
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

// Refinement of roadmap legs stops at its evaluation budget; this time limit only guards
// against a pathological case, so refined legs do not depend on the machine's speed.
constexpr double kRefinementTimeGuardS = 30.0;

std::string legName(const TourResult& tour, int from, int to) { return tour.names[from] + " -> " + tour.names[to]; }

// The rules, cost model and planner for the legs between two places.
struct LegPlanner {
  PlanningContext::Mode planning;
  std::unique_ptr<planner::FlightPlanner> planner;
};

planner::LatticeSettings latticeSettings(const PlanningContext& context, const TourOptions& options) {
  planner::LatticeSettings settings;
  settings.spacing_m = options.lattice_stride > 0
                           ? options.lattice_stride * context.environment().grid().frame().resolution_m()
                           : options.lattice_spacing_m;
  settings.workers = options.workers;
  return settings;
}

LegPlanner legPlanner(const PlanningContext& context, FlightMode mode, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  LegPlanner leg{context.mode(mode), nullptr};
  leg.planner = std::make_unique<planner::FlightPlanner>(*leg.planning.rules, *leg.planning.model, context.objective(a, b));
  return leg;
}

// One search between two places with a pairwise planner (OMPL's or the lattice A*), the path
// post-processed.
std::vector<Eigen::Vector3d> searchLeg(const TourResult& tour, const PlanningContext& context, const LegPlanner& leg,
                                       const TourOptions& options, int from, int to) {
  const Eigen::Vector3d &a = tour.places_m[from], &b = tour.places_m[to];
  planner::PlanRequest request;
  request.start_m = a;
  request.goal_m = b;
  request.planner = options.planner;
  request.time_limit_s = options.time_limit_s;
  request.refinement.time_limit_s = options.time_limit_s;
  request.lattice = latticeSettings(context, options);
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
    if (attempt > 0) request.time_limit_s = kRetryTimeFactors[attempt - 1] * options.time_limit_s;
    try {
      return leg.planner->plan(request).waypoints;
    } catch (const ceilplan::NoPathError& e) {
      failures += std::string(failures.empty() ? "" : "; ") + e.what();
    } catch (...) {
      rethrowWithContext(flightModeName(tour.mode) + " mode: leg " + legName(tour, from, to) + ": ");
    }
  }
  throw NoPathError(flightModeName(tour.mode) + " mode: no path between " + tour.names[from] + " and " + tour.names[to] + ": " +
                    failures);
}

// Every leg from one roadmap over the map: the roadmap's route from each place to every other,
// shortcut under the pair's rules, or the straight line where that is valid and cheaper. Raw:
// the legs a plan flies are refined later.
LegTable roadmapLegs(const TourResult& tour, const PlanningContext& context, FlightMode mode, const TourOptions& options,
                     const LegScorer& score) {
  const Eigen::Vector3d& home = tour.places_m.front();
  const LegPlanner roadmap_planner = legPlanner(context, mode, home, home);
  const planner::SafetyRules& rules = *roadmap_planner.planning.rules;
  const planner::FlightObjective& objective = roadmap_planner.planner->objective();
  planner::LatticeSettings settings = latticeSettings(context, options);
  settings.progress = stageProgress(options, flightModeName(tour.mode) + " mode: building the roadmap");
  planner::LatticeRoadmap roadmap(roadmap_planner.planner->spaceInformation(), settings);
  roadmap.build(objective, tour.places_m);

  const int places = static_cast<int>(tour.places_m.size());
  const RoutesFrom routes_from = [&](int from) {
    const std::vector<std::optional<planner::RoadmapRoute>> routes = roadmap.routesFrom(from);
    std::vector<std::vector<Eigen::Vector3d>> paths(places);
    for (int to = 0; to < places; ++to) {
      if (to == from) continue;
      const Eigen::Vector3d &a = tour.places_m[from], &b = tour.places_m[to];
      std::optional<std::vector<Eigen::Vector3d>> best;
      if (routes[to]) best = planner::shortcutPath(routes[to]->waypoints, rules, objective);
      if (options.straight_when_clear && rules.isMotionValid(a, b) &&
          (!best || objective.motionCost(a, b) < objective.pathCost(*best)))
        best = std::vector<Eigen::Vector3d>{a, b};
      if (!best) {
        const std::optional<planner::Blockage> blockage = roadmap.blockage(from, to);
        throw NoPathError(flightModeName(tour.mode) + " mode: no path between " + tour.names[from] + " and " +
                          tour.names[to] + ": " +
                          (blockage ? blockage->describe() : std::string("the roadmap does not join them")));
      }
      paths[to] = std::move(*best);
    }
    return paths;
  };
  return planLegsByPlace(places, routes_from, score, options.workers,
                         stageProgress(options, flightModeName(tour.mode) + " mode: routing legs"));
}

// The visiting order and the sorties for the legs as they are.
void orderAndSplit(TourResult& tour, const PlanningContext& context, const TourOptions& options) {
  TourCosts legs;
  legs.names = tour.names;
  legs.current_at_soc = packCurrent(context.energy());
  const int places = static_cast<int>(tour.places_m.size());
  CostMatrix costs = CostMatrix::Zero(places, places);
  legs.legs.assign(places, std::vector<LegCost>(places));
  legs.dwells.assign(places, {});
  for (int i = 0; i < places; ++i)
    for (int j = 0; j < places; ++j) {
      if (i == j) continue;
      legs.legs[i][j] = legCost(tour.legs[i][j].evaluation);
      costs(i, j) = legs.legs[i][j].charge_ah;
    }
  for (int k = 1; k < places; ++k) {
    const TourStop& stop = tour.stops[k - 1];
    legs.dwells[k] = {stop.target.dwell_s, stop.viewpoint.dwell_current_a, stop.hover.propulsion_power_w};
    // The charge matrix orders by what a visit costs: the leg into a target and its dwell.
    for (int i = 0; i < places; ++i)
      if (i != k) costs(i, k) += stop.viewpoint.dwell_charge_ah;
  }
  TourOrderOptions order_options;
  order_options.seed = options.seed;
  tour.order = orderTour(costs, order_options);
  SortieOptions sortie_options;
  sortie_options.ageing_model = options.ageing_model;
  sortie_options.ageing = ageingModelOptions(options.temperature_c);
  tour.plan = planSorties(legs, tour.order.targets, context.battery(), sortie_options);
}

}  // namespace

TourResult planTour(const Mission& mission, const PlanningContext& context, FlightMode mode,
                    const TourOptions& options) {
  TourResult tour;
  tour.mode = mode;
  tour.options = options;
  tour.start_soc = context.battery().start_soc;
  tour.reserve_soc = context.battery().reserve_soc;

  // Home as the planner would check a start (the same rules in both modes).
  const PlanningContext::Mode home_mode = context.mode(mode);
  if (!home_mode.rules->isStateValid(mission.home_m))
    throw ceilplan::InputError(mission.name() + ": home " + formatPoint(mission.home_m) +
                                " is not a valid position for the vehicle (inside or too close to a structure, or "
                                "outside the map); move it into free space");

  tour.stops = chooseStops(mission, context, mode, options);
  tour.names.push_back("home");
  tour.places_m.push_back(mission.home_m);
  for (const TourStop& stop : tour.stops) {
    tour.names.push_back(stop.target.name);
    tour.places_m.push_back(stop.viewpoint.position_m);
  }

  const battery::Pack& pack = context.battery().pack;
  const LegScorer score = [&](const std::vector<Eigen::Vector3d>& waypoints) {
    return planner::evaluatePath(context.fullModel(), pack, tour.start_soc, waypoints);
  };
  const auto legPlannerFor = [&](int from, int to) {
    return legPlanner(context, mode, tour.places_m[from], tour.places_m[to]);
  };
  const int places = static_cast<int>(tour.places_m.size());
  planner::RefinementOptions refinement;
  if (planner::plannerInfo(options.planner).multiQuery()) {
    tour.legs = roadmapLegs(tour, context, mode, options, score);
    refinement.time_limit_s = kRefinementTimeGuardS;
  } else {
    refinement.time_limit_s = options.time_limit_s;
    const PairPlanner plan_pair = [&](int from, int to) {
      return searchLeg(tour, context, legPlannerFor(from, to), options, from, to);
    };
    tour.legs = planLegsByPair(places, plan_pair, score, options.workers,
                               stageProgress(options, flightModeName(tour.mode) + " mode: planning legs"));
  }

  // Order and split with the legs as they are, post-process the raw legs the plan flies, and
  // again until the plan flies post-processed legs only (each round refines at least one leg).
  const LegRefiner refine = [&](int from, int to, const std::vector<Eigen::Vector3d>& raw) {
    try {
      return legPlannerFor(from, to).planner->postProcess(raw, refinement);
    } catch (...) {
      rethrowWithContext(flightModeName(tour.mode) + " mode: leg " + legName(tour, from, to) + ": ");
    }
  };
  const auto unrefined = [&](const std::vector<std::pair<int, int>>& candidates) {
    std::vector<std::pair<int, int>> raw;
    for (const auto& [from, to] : candidates)
      if (!tour.legs[from][to].refined) raw.emplace_back(from, to);
    std::sort(raw.begin(), raw.end());
    raw.erase(std::unique(raw.begin(), raw.end()), raw.end());
    return raw;
  };
  for (;;) {
    std::vector<std::pair<int, int>> flown;
    try {
      orderAndSplit(tour, context, options);
      for (const Sortie& sortie : tour.plan.sorties)
        for (const SortieLeg& leg : sortie.legs) flown.emplace_back(leg.from, leg.to);
    } catch (const InfeasibleError&) {
      // A target no sortie can reach and return from, perhaps only on raw legs: refine the
      // legs out of home and back, then decide.
      for (int k = 1; k < places; ++k) flown.insert(flown.end(), {{0, k}, {k, 0}});
      if (unrefined(flown).empty()) throw;
    }
    const std::vector<std::pair<int, int>> raw_legs = unrefined(flown);
    if (raw_legs.empty()) break;
    refineLegs(tour.legs, raw_legs, refine, score, options.workers,
               stageProgress(options, flightModeName(tour.mode) + " mode: refining " + std::to_string(raw_legs.size()) +
                                          " legs"));
  }

  // The independent re-check of every leg flown (the planner checked them too).
  for (const Sortie& sortie : tour.plan.sorties)
    for (const SortieLeg& leg : sortie.legs)
      if (const auto violation = context.baseRules().checkPathDensely(tour.legs[leg.from][leg.to].waypoints))
        throw Error(flightModeName(tour.mode) + " mode: leg " + legName(tour, leg.from, leg.to) +
                                 " fails the dense re-check: " + *violation);

  tour.unknown_space = context.environment().index()->unknownSpace();
  tour.unknown_summary = context.environment().index()->unknownSummary();
  for (const Sortie& sortie : tour.plan.sorties)
    for (const SortieLeg& leg : sortie.legs) tour.assumed_free_m += tour.legs[leg.from][leg.to].evaluation.assumed_free_m;
  if (mode == FlightMode::Free) tour.standoff = measureTourStandoff(tour, context.environment(), context.options().standoff_m);
  tour.record = recordFlight(tour, context);
  std::vector<RouteStop> route_stops;
  for (const TourStop& stop : tour.stops) route_stops.push_back({stop.target.name, stop.target.point_m, stop.target.dwell_s});
  tour.routes = sortieRoutes(tour.plan, tour.legs, route_stops, mission);
  tour.trajectories = routeTrajectories(tour.routes, mission, context.baseRules());
  for (const char* model : {"fec", "xu", "woehler", "schmalstieg"})
    tour.wear.push_back(planWear(tour.plan, model, ageingModelOptions(options.temperature_c)));
  tour.duty = projectDuty(tour, context.battery(), options);
  return tour;
}

}  // namespace ceilplan::mission
