#include "tour_run.hpp"

#include "duty_projection.hpp"
#include "errors.hpp"

#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/energy/lipo_open_circuit_voltage.hpp"
#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/path_refinement.hpp"

#include <cstdio>
#include <iterator>
#include <stdexcept>

namespace ceilplan::app {
namespace {

std::string pointText(const Eigen::Vector3d& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.2f, %.2f, %.2f)", p.x(), p.y(), p.z());
  return text;
}

// The rotors stay this much farther from the surface at a viewpoint than the planner's
// minimum gap, so the leg's end passes the dense re-check with its rounding.
constexpr double kViewpointGapMarginM = 0.01;

// A leg an OMPL planner misses is searched again this many times longer, twice: BIT* finds the
// free-mode bridge's long legs through the standoff environment in a few seconds, but not
// always in 0.5 s.
constexpr double kRetryTimeFactors[] = {10.0, 40.0};

std::vector<TourStop> chooseStops(const MissionFile& mission, const PlanningSetup& setup, PlanningMode mode,
                                  const TourOptions& options) {
  planner::ViewpointOptions viewpoint_options;
  viewpoint_options.mode = mode == PlanningMode::Ceiling ? planner::ViewpointMode::Ceiling : planner::ViewpointMode::Free;
  viewpoint_options.min_ceiling_gap_m = setup.arguments().min_ceiling_gap_m + kViewpointGapMarginM;
  const environment::Environment& environment =
      mode == PlanningMode::Ceiling ? setup.environment() : setup.standoffEnvironment();
  std::vector<TourStop> stops;
  for (const planner::InspectionTarget& target : mission.targets) {
    TourStop stop{target, {}};
    // A conventional planner inspects from where its standoff lets it, with a zoom lens.
    if (mode == PlanningMode::Free)
      stop.target.standoff_max_m = std::max(target.standoff_max_m, options.free_standoff_max_m);
    stop.viewpoint = planner::chooseViewpoint(stop.target, environment, setup.energy(), viewpoint_options);
    stops.push_back(stop);
  }
  return stops;
}

planner::LegCost legCost(const planner::PathEvaluation& evaluation) {
  planner::LegCost cost;
  cost.charge_ah = evaluation.charge_ah;
  cost.duration_s = evaluation.duration_s;
  cost.mean_current_a = evaluation.mean_current_a;
  for (const planner::PathSample& s : evaluation.samples) cost.current_profile.push_back({s.t_s, s.current_a});
  return cost;
}

// The sortie as flown: legs' samples end to end, a hover sample pair per dwell, SOC counted
// from the start SOC (trapezoid, usable capacity, as planSorties counts it).
std::vector<planner::PathSample> flownSamples(const TourResult& tour, const planner::Sortie& sortie,
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
  for (const planner::SortieLeg& leg : sortie.legs) {
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

battery::DutyResult projectDuty(const TourResult& tour, const planner::SortieBattery& battery,
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

  // Home as the planner would check a start: in free mode the approach zone around it exempts
  // it from the standoff, so a home near the ground is accepted.
  const PlanningSetup::Mode home_mode = setup.mode(mode, mission.home_m, mission.home_m);
  if (!home_mode.rules->isStateValid(mission.home_m))
    throw std::invalid_argument(mission.file.string() + ": home " + pointText(mission.home_m) +
                                " is not a valid position for the vehicle (inside or too close to a structure, or "
                                "outside the map); move it into free space");

  tour.stops = chooseStops(mission, setup, mode, options);
  tour.names.push_back("home");
  tour.places_m.push_back(mission.home_m);
  for (const TourStop& stop : tour.stops) {
    tour.names.push_back(stop.target.name);
    tour.places_m.push_back(stop.viewpoint.position_m);
  }

  const LegPathPlanner plan_leg = [&](int from, int to) {
    const Eigen::Vector3d &a = tour.places_m[from], &b = tour.places_m[to];
    const PlanningSetup::Mode planning = setup.mode(mode, a, b);
    const planner::FlightPlanner flight_planner(*planning.rules, *planning.model, setup.objective(a, b));
    planner::PlanRequest request;
    request.start_m = a;
    request.goal_m = b;
    request.planner = options.planner;
    request.time_limit_s = options.time_limit_s;
    request.refinement.time_limit_s = options.time_limit_s;
    request.lattice.stride_voxels = options.lattice_stride;
    // A clear straight line needs no search: the refinement bends it where that saves charge
    // (up towards a ceiling), and the dense re-check still applies.
    if (options.straight_when_clear && planning.rules->isMotionValid(a, b)) {
      const double pieces = static_cast<double>(request.refinement.max_waypoints - 1);
      return flight_planner.postProcess(planner::subdivide({a, b}, (b - a).norm() / pieces + 1e-9),
                                        request.refinement);
    }
    // An anytime planner may miss a narrow passage in a short search: search again, longer.
    std::string failures;
    const int attempts = options.planner == "lattice" ? 1 : static_cast<int>(std::size(kRetryTimeFactors)) + 1;
    for (int attempt = 0; attempt < attempts; ++attempt) {
      if (attempt > 0) request.time_limit_s = kRetryTimeFactors[attempt - 1] * options.time_limit_s;
      try {
        return flight_planner.plan(request).waypoints;
      } catch (const planner::NoPathFound& e) {
        failures += std::string(failures.empty() ? "" : "; ") + e.what();
      } catch (const std::exception& e) {
        throw std::runtime_error(tour.mode + " mode: leg " + tour.names[from] + " -> " + tour.names[to] + ": " +
                                 e.what());
      }
    }
    throw NoPathError(tour.mode + " mode: no path between " + tour.names[from] + " and " + tour.names[to] + ": " +
                      failures);
  };
  const battery::Pack& pack = mission.battery.pack;
  const LegScorer score = [&](const std::vector<Eigen::Vector3d>& waypoints) {
    return planner::evaluatePath(setup.fullModel(), pack, tour.start_soc, waypoints);
  };
  Progress progress(tour.mode + " mode: planning legs");
  tour.legs = planTourLegs(static_cast<int>(tour.places_m.size()), plan_leg, score, options.workers, progress);

  // The independent re-check of every leg (the planner checked them too).
  for (std::size_t i = 0; i < tour.legs.size(); ++i)
    for (std::size_t j = 0; j < tour.legs.size(); ++j) {
      if (i == j) continue;
      if (const auto violation = setup.baseRules().checkPathDensely(tour.legs[i][j].waypoints))
        throw std::runtime_error(tour.mode + " mode: leg " + tour.names[i] + " -> " + tour.names[j] +
                                 " fails the dense re-check: " + *violation);
    }

  planner::TourLegs legs;
  legs.names = tour.names;
  const int places = static_cast<int>(tour.places_m.size());
  planner::CostMatrix costs = planner::CostMatrix::Zero(places, places);
  legs.legs.assign(places, std::vector<planner::LegCost>(places));
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

  planner::TourOrderOptions order_options;
  order_options.seed = options.seed;
  tour.order = planner::orderTour(costs, order_options);
  planner::SortieOptions sortie_options;
  sortie_options.ageing_model = options.ageing_model;
  sortie_options.ageing = ageingOptions(options);
  tour.plan = planner::planSorties(legs, tour.order.targets, mission.battery, sortie_options);

  for (const planner::Sortie& sortie : tour.plan.sorties) tour.sortie_samples.push_back(flownSamples(tour, sortie, pack));
  for (const char* model : {"fec", "xu", "woehler", "schmalstieg"})
    tour.wear.push_back(planner::planWear(tour.plan, model, sortie_options.ageing));
  tour.duty = projectDuty(tour, mission.battery, options);
  return tour;
}

}  // namespace ceilplan::app
