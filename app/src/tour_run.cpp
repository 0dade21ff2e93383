#include "tour_run.hpp"

#include "duty_projection.hpp"
#include "errors.hpp"

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

namespace ceilplan::app {
namespace {

// The rotors stay this much farther from the surface at a viewpoint than the planner's
// minimum gap, so the leg's end passes the dense re-check with its rounding.
constexpr double kViewpointGapMarginM = 0.01;

// A leg an OMPL planner misses is searched again this many times longer, twice: BIT* finds
// long legs round the bridge's girders in a few seconds, but not always in 0.5 s.
constexpr double kRetryTimeFactors[] = {10.0, 40.0};

std::vector<TourStop> chooseStops(const MissionFile& mission, const PlanningSetup& setup, PlanningMode mode,
                                  const TourOptions& options) {
  mission::ViewpointOptions viewpoint_options;
  viewpoint_options.mode = mode == PlanningMode::Ceiling ? mission::ViewpointMode::Ceiling : mission::ViewpointMode::Free;
  viewpoint_options.min_ceiling_gap_m = setup.arguments().min_ceiling_gap_m + kViewpointGapMarginM;
  viewpoint_options.standoff_m = setup.arguments().standoff_m;
  const environment::Environment& environment = setup.environment();
  std::vector<TourStop> stops;
  for (const mission::InspectionTarget& target : mission.targets) {
    TourStop stop{target, {}};
    // A conventional planner inspects from where its standoff lets it, with a zoom lens.
    if (mode == PlanningMode::Free)
      stop.target.standoff_max_m = std::max(target.standoff_max_m, options.free_standoff_max_m);
    stop.viewpoint = mission::chooseViewpoint(stop.target, environment, setup.energy(), viewpoint_options);
    stops.push_back(stop);
  }
  return stops;
}

mission::LegCost legCost(const planner::PathEvaluation& evaluation) {
  mission::LegCost cost;
  cost.charge_ah = evaluation.charge_ah;
  cost.duration_s = evaluation.duration_s;
  cost.mean_current_a = evaluation.mean_current_a;
  for (const planner::PathSample& s : evaluation.samples) cost.current_profile.push_back({s.t_s, s.current_a});
  return cost;
}

// The sortie as flown: legs' samples end to end, a hover sample pair per dwell, SOC counted
// from the start SOC (trapezoid, usable capacity, as planSorties counts it).
std::vector<planner::PathSample> flownSamples(const TourResult& tour, const mission::Sortie& sortie,
                                              const battery::Pack& pack) {
  std::vector<planner::PathSample> samples;
  double t0 = 0.0;
  const auto append = [&](planner::PathSample s) {
    if (!samples.empty()) {
      const planner::PathSample& last = samples.back();
      const double used_ah = 0.5 * (last.current_a + s.current_a) * (s.t_s - last.t_s) / 3600.0;
      s.soc = last.soc - used_ah / pack.usableCapacityAh();
    } else {
      s.soc = tour.start_soc;
    }
    samples.push_back(s);
  };
  for (const mission::SortieLeg& leg : sortie.legs) {
    const planner::PathEvaluation& evaluation = tour.legs[leg.from][leg.to].evaluation;
    for (planner::PathSample s : evaluation.samples) {
      s.t_s += t0;
      append(s);
    }
    t0 += evaluation.duration_s;
    if (leg.to == 0) continue;
    const TourStop& stop = tour.stops[leg.to - 1];
    planner::PathSample hover = samples.back();
    hover.speed_m_s = 0.0;
    hover.current_a = stop.viewpoint.dwell_current_a;
    hover.ceiling_gap_m = stop.viewpoint.ceiling_gap_m;
    append(hover);
    hover.t_s += stop.target.dwell_s;
    t0 += stop.target.dwell_s;
    append(hover);
  }
  return samples;
}

battery::AgeingModelOptions ageingOptions(const TourOptions& options) {
  battery::AgeingModelOptions ageing;
  ageing.conditions = battery::OperatingConditions::fromCelsius(options.temperature_c);
  const energy::LipoOpenCircuitVoltage ocv;  // the energy module's cell curve, for Schmalstieg
  ageing.cell_voltage_of_soc = [ocv](double soc) { return ocv.cellVoltageV(soc); };
  return ageing;
}

battery::DutyResult projectDuty(const TourResult& tour, const mission::SortieBattery& battery,
                                const TourOptions& options) {
  battery::DutyCycle duty;
  for (const std::vector<planner::PathSample>& samples : tour.sortie_samples) {
    const battery::LoadProfile flight = dischargeProfile(samples);
    duty.mission.segments.insert(duty.mission.segments.end(), flight.begin(), flight.end());
    duty.mission.segments.push_back(
        battery::Segment::charge(battery.pack.charge_current_a, 60.0 * options.charge_max_min, battery.start_soc));
  }
  duty.mission.segments.push_back(battery::Segment::idle(60.0 * options.idle_min));
  duty.missions_per_day = options.missions_per_day;
  duty.days = options.days;
  duty.initial_soc = battery.start_soc;
  battery::DutyOptions duty_options;
  duty_options.record_first_day = false;
  return battery::simulateDuty(battery.pack, duty, duty_options);
}

// Refinement of roadmap legs stops at its evaluation budget; this time limit only guards
// against a pathological case, so refined legs do not depend on the machine's speed.
constexpr double kRefinementTimeGuardS = 30.0;

std::string legName(const TourResult& tour, int from, int to) { return tour.names[from] + " -> " + tour.names[to]; }

// The rules, cost model and planner for the legs between two places.
struct LegPlanner {
  PlanningSetup::Mode planning;
  std::unique_ptr<planner::FlightPlanner> planner;
};

planner::LatticeSettings latticeSettings(const PlanningSetup& setup, const TourOptions& options) {
  planner::LatticeSettings settings;
  settings.spacing_m = options.lattice_stride > 0
                           ? options.lattice_stride * setup.environment().grid().frame().resolution_m()
                           : options.lattice_spacing_m;
  settings.workers = options.workers;
  return settings;
}

LegPlanner legPlanner(const PlanningSetup& setup, PlanningMode mode, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  LegPlanner leg{setup.mode(mode, a, b), nullptr};
  leg.planner = std::make_unique<planner::FlightPlanner>(*leg.planning.rules, *leg.planning.model, setup.objective(a, b));
  return leg;
}

// One search between two places with a pairwise planner (OMPL's or the lattice A*), the path
// post-processed.
std::vector<Eigen::Vector3d> searchLeg(const TourResult& tour, const PlanningSetup& setup, const LegPlanner& leg,
                                       const TourOptions& options, int from, int to) {
  const Eigen::Vector3d &a = tour.places_m[from], &b = tour.places_m[to];
  planner::PlanRequest request;
  request.start_m = a;
  request.goal_m = b;
  request.planner = options.planner;
  request.time_limit_s = options.time_limit_s;
  request.refinement.time_limit_s = options.time_limit_s;
  request.lattice = latticeSettings(setup, options);
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
    } catch (const std::exception& e) {
      throw std::runtime_error(tour.mode + " mode: leg " + legName(tour, from, to) + ": " + e.what());
    }
  }
  throw NoPathError(tour.mode + " mode: no path between " + tour.names[from] + " and " + tour.names[to] + ": " +
                    failures);
}

// Every leg from one roadmap over the map: the roadmap's route from each place to every other,
// shortcut under the pair's rules, or the straight line where that is valid and cheaper. Raw:
// the legs a plan flies are refined later.
TourLegs roadmapLegs(const TourResult& tour, const PlanningSetup& setup, PlanningMode mode, const TourOptions& options,
                     const LegScorer& score) {
  const Eigen::Vector3d& home = tour.places_m.front();
  const LegPlanner roadmap_planner = legPlanner(setup, mode, home, home);
  const planner::SafetyRules& rules = *roadmap_planner.planning.rules;
  const planner::FlightObjective& objective = roadmap_planner.planner->objective();
  Progress build_progress(tour.mode + " mode: building the roadmap");
  planner::LatticeSettings settings = latticeSettings(setup, options);
  settings.progress = [&](double share) { build_progress.update(share); };
  planner::LatticeRoadmap roadmap(roadmap_planner.planner->spaceInformation(), settings);
  roadmap.build(objective, tour.places_m);
  build_progress.finish();

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
        throw NoPathError(tour.mode + " mode: no path between " + tour.names[from] + " and " + tour.names[to] + ": " +
                          (blockage ? blockage->describe() : std::string("the roadmap does not join them")));
      }
      paths[to] = std::move(*best);
    }
    return paths;
  };
  Progress progress(tour.mode + " mode: routing legs");
  return planLegsByPlace(places, routes_from, score, options.workers, progress);
}

// The visiting order and the sorties for the legs as they are.
void orderAndSplit(TourResult& tour, const MissionFile& mission, const TourOptions& options) {
  mission::TourLegs legs;
  legs.names = tour.names;
  const int places = static_cast<int>(tour.places_m.size());
  mission::CostMatrix costs = mission::CostMatrix::Zero(places, places);
  legs.legs.assign(places, std::vector<mission::LegCost>(places));
  legs.dwells.assign(places, {});
  for (int i = 0; i < places; ++i)
    for (int j = 0; j < places; ++j) {
      if (i == j) continue;
      legs.legs[i][j] = legCost(tour.legs[i][j].evaluation);
      costs(i, j) = legs.legs[i][j].charge_ah;
    }
  for (int k = 1; k < places; ++k) {
    const TourStop& stop = tour.stops[k - 1];
    legs.dwells[k] = {stop.target.dwell_s, stop.viewpoint.dwell_current_a};
    // The charge matrix orders by what a visit costs: the leg into a target and its dwell.
    for (int i = 0; i < places; ++i)
      if (i != k) costs(i, k) += stop.viewpoint.dwell_charge_ah;
  }
  mission::TourOrderOptions order_options;
  order_options.seed = options.seed;
  tour.order = mission::orderTour(costs, order_options);
  mission::SortieOptions sortie_options;
  sortie_options.ageing_model = options.ageing_model;
  sortie_options.ageing = ageingOptions(options);
  tour.plan = mission::planSorties(legs, tour.order.targets, mission.battery, sortie_options);
}

}  // namespace

PlanningArguments planningArguments(const MissionFile& mission) {
  PlanningArguments arguments;
  arguments.map = mission.map.string();
  arguments.vehicle = mission.vehicle.string();
  arguments.battery = mission.file.string();  // readBatteryFile reads its `battery:` section
  arguments.objective = "charge";
  arguments.speeds.cruise_m_s = mission.speeds.cruise_m_s;
  arguments.speeds.climb_m_s = mission.speeds.climb_m_s;
  arguments.speeds.descent_m_s = mission.speeds.descent_m_s;
  arguments.speeds.near_ceiling_m_s = std::min(arguments.speeds.near_ceiling_m_s, mission.speeds.cruise_m_s);
  return arguments;
}

TourResult planTour(const MissionFile& mission, const PlanningSetup& setup, PlanningMode mode,
                    const TourOptions& options) {
  TourResult tour;
  tour.mode = modeName(mode);
  tour.options = options;
  tour.start_soc = mission.battery.start_soc;
  tour.reserve_soc = mission.battery.reserve_soc;

  // Home as the planner would check a start (the same rules in both modes).
  const PlanningSetup::Mode home_mode = setup.mode(mode, mission.home_m, mission.home_m);
  if (!home_mode.rules->isStateValid(mission.home_m))
    throw ceilplan::InputError(mission.file.string() + ": home " + formatPoint(mission.home_m) +
                                " is not a valid position for the vehicle (inside or too close to a structure, or "
                                "outside the map); move it into free space");

  tour.stops = chooseStops(mission, setup, mode, options);
  tour.names.push_back("home");
  tour.places_m.push_back(mission.home_m);
  for (const TourStop& stop : tour.stops) {
    tour.names.push_back(stop.target.name);
    tour.places_m.push_back(stop.viewpoint.position_m);
  }

  const battery::Pack& pack = mission.battery.pack;
  const LegScorer score = [&](const std::vector<Eigen::Vector3d>& waypoints) {
    return planner::evaluatePath(setup.fullModel(), pack, tour.start_soc, waypoints);
  };
  const auto legPlannerFor = [&](int from, int to) {
    return legPlanner(setup, mode, tour.places_m[from], tour.places_m[to]);
  };
  const int places = static_cast<int>(tour.places_m.size());
  planner::RefinementOptions refinement;
  if (planner::plannerInfo(options.planner).multiQuery()) {
    tour.legs = roadmapLegs(tour, setup, mode, options, score);
    refinement.time_limit_s = kRefinementTimeGuardS;
  } else {
    refinement.time_limit_s = options.time_limit_s;
    const PairPlanner plan_pair = [&](int from, int to) {
      return searchLeg(tour, setup, legPlannerFor(from, to), options, from, to);
    };
    Progress progress(tour.mode + " mode: planning legs");
    tour.legs = planLegsByPair(places, plan_pair, score, options.workers, progress);
  }

  // Order and split with the legs as they are, post-process the raw legs the plan flies, and
  // again until the plan flies post-processed legs only (each round refines at least one leg).
  const LegRefiner refine = [&](int from, int to, const std::vector<Eigen::Vector3d>& raw) {
    try {
      return legPlannerFor(from, to).planner->postProcess(raw, refinement);
    } catch (const std::exception& e) {
      throw std::runtime_error(tour.mode + " mode: leg " + legName(tour, from, to) + ": " + e.what());
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
      orderAndSplit(tour, mission, options);
      for (const mission::Sortie& sortie : tour.plan.sorties)
        for (const mission::SortieLeg& leg : sortie.legs) flown.emplace_back(leg.from, leg.to);
    } catch (const ceilplan::InputError&) {
      // A target no sortie can reach and return from, perhaps only on raw legs: refine the
      // legs out of home and back, then decide.
      for (int k = 1; k < places; ++k) flown.insert(flown.end(), {{0, k}, {k, 0}});
      if (unrefined(flown).empty()) throw;
    }
    const std::vector<std::pair<int, int>> raw_legs = unrefined(flown);
    if (raw_legs.empty()) break;
    Progress progress(tour.mode + " mode: refining " + std::to_string(raw_legs.size()) + " legs");
    refineLegs(tour.legs, raw_legs, refine, score, options.workers, progress);
  }

  // The independent re-check of every leg flown (the planner checked them too).
  for (const mission::Sortie& sortie : tour.plan.sorties)
    for (const mission::SortieLeg& leg : sortie.legs)
      if (const auto violation = setup.baseRules().checkPathDensely(tour.legs[leg.from][leg.to].waypoints))
        throw std::runtime_error(tour.mode + " mode: leg " + legName(tour, leg.from, leg.to) +
                                 " fails the dense re-check: " + *violation);

  for (const mission::Sortie& sortie : tour.plan.sorties) tour.sortie_samples.push_back(flownSamples(tour, sortie, pack));
  for (const char* model : {"fec", "xu", "woehler", "schmalstieg"})
    tour.wear.push_back(mission::planWear(tour.plan, model, ageingOptions(options)));
  tour.duty = projectDuty(tour, mission.battery, options);
  return tour;
}

}  // namespace ceilplan::app
