#include "ceilplan/io/tour_files.hpp"

#include "ceilplan/io/map_views.hpp"
#include "ceilplan/io/atomic_file.hpp"
#include "ceilplan/io/plan_files.hpp"

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>

namespace ceilplan::io {
namespace {

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

double reductionPct(double with, double without) { return without != 0.0 ? 100.0 * (1.0 - with / without) : 0.0; }

double tourDuration_s(const mission::TourResult& tour) { return tour.plan.flight_s; }

}  // namespace

nlohmann::json tourJson(const mission::TourResult& tour) {
  nlohmann::json json;
  json["mode"] = mission::flightModeName(tour.mode);
  json["seed"] = tour.options.seed;
  json["planner"] = tour.options.planner;
  json["ageing_model"] = tour.plan.ageing_model;
  json["order_method"] = tour.order.method;
  json["targets_total"] = tour.stops.size();
  int visited = 0;
  for (const mission::Sortie& sortie : tour.plan.sorties) visited += static_cast<int>(sortie.targets.size());
  json["targets_visited"] = visited;
  nlohmann::json targets = nlohmann::json::array();
  for (const mission::TourStop& stop : tour.stops) {
    const mission::Viewpoint& v = stop.viewpoint;
    targets.push_back({{"name", stop.target.name},
                       {"point", waypointsJson({stop.target.point_m})[0]},
                       {"viewpoint", waypointsJson({v.position_m})[0]},
                       {"distance_m", v.distance_m},
                       {"standoff_m", {stop.target.standoff_min_m, stop.target.standoff_max_m}},
                       {"ceiling_gap_m", std::isfinite(v.ceiling_gap_m) ? nlohmann::json(v.ceiling_gap_m) : nlohmann::json()},
                       {"dwell_s", stop.target.dwell_s},
                       {"dwell_current_a", v.dwell_current_a},
                       {"dwell_charge_ah", v.dwell_charge_ah}});
  }
  json["targets"] = targets;
  nlohmann::json sorties = nlohmann::json::array();
  for (const mission::Sortie& sortie : tour.plan.sorties) {
    nlohmann::json names = nlohmann::json::array(), legs = nlohmann::json::array();
    for (int k : sortie.targets) names.push_back(tour.names[k]);
    for (const mission::SortieLeg& leg : sortie.legs) {
      const mission::TourLeg& flown = tour.legs[leg.from][leg.to];
      legs.push_back({{"from", tour.names[leg.from]},
                      {"to", tour.names[leg.to]},
                      {"charge_ah", leg.charge_ah},
                      {"duration_s", leg.duration_s},
                      {"length_m", flown.evaluation.length_m},
                      {"waypoints", waypointsJson(flown.waypoints)}});
    }
    sorties.push_back({{"targets", names},
                       {"legs", legs},
                       {"charge_ah", sortie.charge_ah},
                       {"duration_s", sortie.flight_s},
                       {"recharge_s", sortie.recharge_s},
                       {"fec", sortie.fec},
                       {"dod", sortie.dod},
                       {"min_soc", sortie.lowest_soc},
                       {"wear", sortie.wear},
                       {"reason", sortie.reason}});
  }
  json["sorties"] = sorties;
  json["charge_ah"] = tour.plan.charge_ah;
  json["duration_s"] = tourDuration_s(tour);
  json["fec"] = tour.plan.fec;
  json["min_soc"] = tour.plan.min_soc;
  json["start_soc"] = tour.start_soc;
  json["reserve_soc"] = tour.reserve_soc;
  nlohmann::json wear;
  for (const mission::PlanWear& w : tour.wear)
    wear[w.model] = {{"wear_name", w.wear_name}, {"cycle_wear", w.cycle_wear}, {"capacity_loss", w.capacity_loss}};
  json["wear"] = wear;
  json["duty"] = {{"missions_per_day", tour.options.missions_per_day},
                  {"days", tour.options.days},
                  {"idle_min", tour.options.idle_min},
                  {"fec_per_mission", tour.duty.fecPerMission()},
                  {"fec_total", tour.duty.fecTotal()},
                  {"min_soc", tour.duty.minSoc()}};
  return json;
}

void writeTourPathCsv(const std::filesystem::path& file, const mission::TourResult& tour) {
  writeTextAtomically(file, [&](std::ostream& out) {
    out << "t_s,x,y,z,speed_m_s,ceiling_gap_m,current_a,soc,sortie\n" << std::setprecision(9);
    double t0 = 0.0;
    for (std::size_t k = 0; k < tour.sortie_samples.size(); ++k) {
      for (const planner::PathSample& s : tour.sortie_samples[k]) {
        out << t0 + s.t_s << ',' << s.position_m.x() << ',' << s.position_m.y() << ',' << s.position_m.z() << ','
            << s.speed_m_s << ',';
        if (std::isfinite(s.ceiling_gap_m)) out << s.ceiling_gap_m;
        out << ',' << s.current_a << ',' << s.soc << ',' << k + 1 << '\n';
      }
      t0 += tour.plan.sorties[k].flight_s + tour.plan.sorties[k].recharge_s;
    }
  });
}

std::vector<AutopilotMission> autopilotMissions(const mission::TourResult& tour, const mission::Mission& mission, Autopilot autopilot) {
  const mission::GeodeticOrigin& origin = mission.requireOrigin();
  std::vector<AutopilotMission> missions;
  for (const mission::Sortie& sortie : tour.plan.sorties) {
    AutopilotMission m;
    m.home_m = mission.home_m;
    m.origin = origin;
    m.autopilot = autopilot;
    m.cruise_speed_m_s = mission.speeds.cruise_m_s;
    m.hover_speed_m_s = mission.speeds.inspection_m_s;
    for (const mission::SortieLeg& leg : sortie.legs) {
      const std::vector<Eigen::Vector3d>& waypoints = tour.legs[leg.from][leg.to].waypoints;
      for (std::size_t i = 1; i < waypoints.size(); ++i) m.waypoints.push_back({waypoints[i], 0.0, std::nullopt});
      if (leg.to != 0) m.waypoints.back().hold_s = tour.stops[leg.to - 1].target.dwell_s;
    }
    missions.push_back(std::move(m));
  }
  return missions;
}

void writeTourDirectory(const std::filesystem::path& dir, const mission::TourResult& tour, const mission::Mission& mission,
                        const environment::Environment& environment, std::optional<Autopilot> autopilot) {
  writeTextAtomically(dir / "tour.json", [&](std::ostream& out) { out << std::setw(2) << tourJson(tour) << '\n'; });
  writeTourPathCsv(dir / "path.csv", tour);
  std::vector<Eigen::Vector3d> route;
  for (const std::vector<planner::PathSample>& samples : tour.sortie_samples)
    for (const planner::PathSample& s : samples) route.push_back(s.position_m);
  writeMapViews(dir, environment, route);
  if (!autopilot) return;
  const std::vector<AutopilotMission> missions = autopilotMissions(tour, mission, *autopilot);
  const int count = static_cast<int>(missions.size());
  for (int k = 0; k < count; ++k) {
    writeQgcPlan(sortieFileName(dir / "mission.plan", k + 1, count), missions[k]);
    writeQgcWpl(sortieFileName(dir / "mission.waypoints", k + 1, count), missions[k]);
  }
}

std::string comparisonTable(const mission::TourResult& ceiling, const mission::TourResult& free) {
  std::ostringstream out;
  char line[200];
  const auto row = [&](const std::string& label, double c, double f, const char* pattern, bool with_reduction) {
    std::snprintf(line, sizeof line, "%-40s %14s %14s %12s\n", label.c_str(), format(pattern, c).c_str(),
                  format(pattern, f).c_str(), with_reduction ? format("%.2f", reductionPct(c, f)).c_str() : "");
    out << line;
  };
  std::snprintf(line, sizeof line, "%-40s %14s %14s %12s\n", "", "ceiling", "free", "reduction %");
  out << line;
  row("targets visited", static_cast<double>(ceiling.stops.size()), static_cast<double>(free.stops.size()), "%.0f", false);
  row("sorties", static_cast<double>(ceiling.plan.sorties.size()), static_cast<double>(free.plan.sorties.size()), "%.0f",
      false);
  row("charge [Ah]", ceiling.plan.charge_ah, free.plan.charge_ah, "%.4f", true);
  row("flight time [s]", tourDuration_s(ceiling), tourDuration_s(free), "%.1f", true);
  row("FEC (flights + recharges)", ceiling.plan.fec, free.plan.fec, "%.5f", true);
  row("lowest SOC [%]", 100.0 * ceiling.plan.min_soc, 100.0 * free.plan.min_soc, "%.2f", false);
  for (std::size_t m = 0; m < ceiling.wear.size() && m < free.wear.size(); ++m) {
    const mission::PlanWear &c = ceiling.wear[m], &f = free.wear[m];
    row(c.model + ": " + c.wear_name, c.cycle_wear, f.cycle_wear, "%.4e", true);
    row(c.model + ": capacity loss [%]", 100.0 * c.capacity_loss, 100.0 * f.capacity_loss, "%.5f", true);
  }
  std::snprintf(line, sizeof line, "duty projection: the tour %d times a day for %d days\n",
                ceiling.options.missions_per_day, ceiling.options.days);
  out << line;
  row("FEC over the study", ceiling.duty.fecTotal(), free.duty.fecTotal(), "%.2f", true);
  return out.str();
}

nlohmann::json comparisonJson(const mission::TourResult& ceiling, const mission::TourResult& free) {
  nlohmann::json json;
  for (const mission::TourResult* tour : {&ceiling, &free}) {
    const nlohmann::json full = tourJson(*tour);
    nlohmann::json entry;
    for (const char* key : {"targets_total", "targets_visited", "charge_ah", "duration_s", "fec", "min_soc", "wear", "duty"})
      entry[key] = full[key];
    entry["sorties"] = tour->plan.sorties.size();
    json[mission::flightModeName(tour->mode)] = entry;
  }
  nlohmann::json reduction = {{"charge", reductionPct(ceiling.plan.charge_ah, free.plan.charge_ah)},
                              {"duration", reductionPct(tourDuration_s(ceiling), tourDuration_s(free))},
                              {"fec", reductionPct(ceiling.plan.fec, free.plan.fec)},
                              {"fec_total", reductionPct(ceiling.duty.fecTotal(), free.duty.fecTotal())}};
  for (std::size_t m = 0; m < ceiling.wear.size() && m < free.wear.size(); ++m) {
    reduction["wear_" + ceiling.wear[m].model] = reductionPct(ceiling.wear[m].cycle_wear, free.wear[m].cycle_wear);
    reduction["capacity_loss_" + ceiling.wear[m].model] =
        reductionPct(ceiling.wear[m].capacity_loss, free.wear[m].capacity_loss);
  }
  json["reduction_pct"] = reduction;
  return json;
}

void writeTourComparison(const std::filesystem::path& dir, const mission::TourResult& ceiling,
                         const mission::TourResult& free, const environment::Environment& environment) {
  std::vector<Eigen::Vector3d> routes;
  for (const mission::TourResult* tour : {&ceiling, &free})
    for (const auto& samples : tour->sortie_samples)
      for (const planner::PathSample& sample : samples) routes.push_back(sample.position_m);
  writeMapViews(dir, environment, routes);
  writeTextAtomically(dir / "comparison.txt", [&](std::ostream& stream) { stream << comparisonTable(ceiling, free); });
  writeTextAtomically(dir / "comparison.json",
                      [&](std::ostream& stream) { stream << std::setw(2) << comparisonJson(ceiling, free) << '\n'; });
}

std::string tourSummary(const mission::TourResult& tour) {
  std::ostringstream out;
  char line[400];
  std::snprintf(line, sizeof line, "%s mode: %zu targets, order by %s (seed %llu), %zu sortie(s) split for least %s wear\n",
                mission::flightModeName(tour.mode).c_str(), tour.stops.size(), tour.order.method.c_str(),
                static_cast<unsigned long long>(tour.order.seed), tour.plan.sorties.size(), tour.plan.ageing_model.c_str());
  out << line;
  for (std::size_t k = 0; k < tour.plan.sorties.size(); ++k) {
    const mission::Sortie& s = tour.plan.sorties[k];
    std::snprintf(line, sizeof line, "  sortie %zu: %zu targets, %.4f Ah, %.1f s, DoD %.1f %%, lands at %.1f %%: %s\n",
                  k + 1, s.targets.size(), s.charge_ah, s.flight_s, 100.0 * s.dod, 100.0 * s.lowest_soc,
                  s.reason.c_str());
    out << line;
  }
  std::snprintf(line, sizeof line, "  total %.4f Ah, %.1f s in the air, FEC %.5f, lowest SOC %.1f %% (reserve %.0f %%)\n",
                tour.plan.charge_ah, tour.plan.flight_s, tour.plan.fec, 100.0 * tour.plan.min_soc,
                100.0 * tour.reserve_soc);
  out << line;
  return out.str();
}

}  // namespace ceilplan::io
