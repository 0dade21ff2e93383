#include "ceilplan/io/tour_files.hpp"

#include "ceilplan/core/format.hpp"
#include "ceilplan/core/install_paths.hpp"
#include "ceilplan/io/atomic_file.hpp"
#include "ceilplan/io/coverage_output.hpp"
#include "ceilplan/io/dji_wpml.hpp"
#include "ceilplan/io/geo_export.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/map_views.hpp"
#include "ceilplan/io/plan_files.hpp"
#include "ceilplan/io/report_html.hpp"
#include "ceilplan/io/tour_report.hpp"
#include "ceilplan/io/trajectory_file.hpp"
#include "ceilplan/io/unknown_space_report.hpp"
#include "reduction.hpp"

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>

namespace ceilplan::io {
namespace {

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

// "a 8.0 m/s wind from 090 deg": how the outputs name the wind a tour was planned in.
std::string windText(const energy::Wind& wind) {
  char text[96];
  std::snprintf(text, sizeof text, "a %.1f m/s wind from %03.0f deg", wind.speed_m_s, wind.from_deg);
  return text;
}

// Whether ceiling mode still draws less charge than free mode in the wind given (none: still air).
std::string windVerdict(const mission::TourResult& ceiling, const mission::TourResult& free) {
  const energy::Wind& wind = ceiling.planning.wind;
  if (wind.calm()) return "";
  const double saved_ah = free.plan.charge_ah - ceiling.plan.charge_ah;
  const double saved_pct = reductionPct(ceiling.plan.charge_ah, free.plan.charge_ah);
  char line[200];
  if (saved_ah > 0.0)
    std::snprintf(line, sizeof line, "ceiling mode saves %.4f Ah (%.2f %%) against free mode in %s\n", saved_ah,
                  saved_pct, windText(wind).c_str());
  else
    std::snprintf(line, sizeof line,
                  "ceiling mode's advantage does not survive %s: it draws %.4f Ah (%.2f %%) more than free mode\n",
                  windText(wind).c_str(), -saved_ah, -saved_pct);
  return line;
}

const char* phaseName(mission::FlightPhase phase) { return phase == mission::FlightPhase::Leg ? "leg" : "dwell"; }

nlohmann::json dutyJson(const mission::DutyProjection& duty, const mission::TourOptions& options) {
  nlohmann::json json = {{"missions_per_day", duty.missions_per_day},
                         {"days", duty.days},
                         {"idle_min", options.idle_min},
                         {"charge_max_min", options.charge_max_min},
                         {"mission_min", duty.mission_min},
                         {"projected", duty.result.has_value()}};
  if (duty.result) {
    json["fec_per_mission"] = duty.result->fecPerMission();
    json["fec_total"] = duty.result->fecTotal();
    json["min_soc"] = duty.result->minSoc();
  } else {
    json["note"] = duty.note;
  }
  return json;
}

// A target's standoff range, "0.3-1.5 m".
std::string rangeText(const mission::InspectionTarget& target) {
  return formatNumber(target.standoff_min_m) + "-" + formatNumber(target.standoff_max_m) + " m";
}

// Free mode: the point targets whose standoff range keeps less than the conventional standoff.
std::vector<const mission::TourStop*> standoffLimitedStops(const mission::TourResult& tour) {
  std::vector<const mission::TourStop*> stops;
  for (const mission::TourStop& stop : tour.stops)
    if (stop.standoff_limited) stops.push_back(&stop);
  return stops;
}

// Where free mode saw a standoff-limited target from: "seen from 1.50 m, within its range
// 0.3-1.5 m, with the airframe's bounding sphere 0.97 m from the nearest structure".
std::string seenFromText(const mission::TourStop& stop) {
  return "seen from " + formatFixed(stop.viewpoint.distance_m, 2) + " m, " +
         (stop.beyond_standoff_range ? "beyond its range " + rangeText(stop.target) + " (--free-standoff-max-m)"
                                     : "within its range " + rangeText(stop.target)) +
         ", with " + standoffText(stop.viewpoint.standoff_m);
}

// Why free mode's viewpoint of a target keeps less than the conventional standoff, and where it
// saw the target from instead.
std::string standoffLimitReason(const mission::TourStop& stop, double standoff_m) {
  return "no viewpoint within its standoff range keeps " + formatNumber(standoff_m) + " m from every structure; " +
         seenFromText(stop);
}

// Free mode: where the tour kept less than the standoff, by leg and viewpoint, and the targets
// whose standoff range did not allow it.
nlohmann::json tourStandoffJson(const mission::TourResult& tour, const mission::TourStandoff& standoff) {
  nlohmann::json legs = nlohmann::json::array(), viewpoints = nlohmann::json::array();
  for (const mission::NarrowedLeg& leg : standoff.legs) {
    const nlohmann::json report = standoffJson(leg.report);
    for (const nlohmann::json& span : report["narrowed"]) {
      nlohmann::json entry = {{"sortie", leg.sortie}, {"leg", tour.names[leg.from] + " -> " + tour.names[leg.to]}};
      entry.update(span);
      legs.push_back(entry);
    }
  }
  for (int k : standoff.narrowed_stops)
    viewpoints.push_back({{"target", tour.stops[k].target.name}, {"standoff_m", tour.stops[k].viewpoint.standoff_m}});
  nlohmann::json limited = nlohmann::json::array();
  for (const mission::TourStop* stop : standoffLimitedStops(tour))
    limited.push_back({{"target", stop->target.name},
                       {"standoff_range_m", {stop->target.standoff_min_m, stop->target.standoff_max_m}},
                       {"distance_m", stop->viewpoint.distance_m},
                       {"viewpoint_standoff_m", stop->viewpoint.standoff_m},
                       {"beyond_standoff_range", stop->beyond_standoff_range},
                       {"reason", standoffLimitReason(*stop, standoff.standoff_m)}});
  return {{"standoff_m", standoff.standoff_m},
          {"length_m", standoff.length_m},
          {"narrowed_m", standoff.narrowed_m},
          {"min_standoff_m", standoff.min_standoff_m},
          {"narrowest", waypointsJson({standoff.narrowest_m})[0]},
          {"narrowed", legs},
          {"narrowed_viewpoints", viewpoints},
          {"limited_targets", limited},
          {"standoff_measures", kStandoffMeasures}};
}

std::vector<Eigen::Vector3d> flownRoute(const mission::TourResult& tour) {
  std::vector<Eigen::Vector3d> route;
  for (const mission::SortieRecord& sortie : tour.record.sorties)
    for (const planner::PathSample& s : sortie.samples) route.push_back(s.position_m);
  return route;
}

}  // namespace

Provenance tourProvenance(Provenance provenance, const mission::Mission& mission, std::uint64_t seed) {
  provenance.input("mission", mission.file).input("map", mission.map_file).input("vehicle", mission.vehicle_file);
  provenance.seed = seed;
  return provenance;
}

std::vector<std::string> geodeticExportsSkipped(const mission::Mission& mission) {
  if (mission.origin) return {};
  return {"mission.plan", "mission.waypoints", "mission.kmz", "routes.kml", "routes.geojson"};
}

std::string geodeticExportsSkippedLine(const mission::Mission& mission) {
  std::string files;
  for (const std::string& file : geodeticExportsSkipped(mission)) files += (files.empty() ? "" : ", ") + file;
  return "geodetic exports skipped (" + files + "): " + mission.name() +
         " has no 'origin:' ({lat, lon, alt} of the map frame); every local-frame output was written";
}

namespace {

// The KMZ's problem and its clamps from one generation of every sortie's WPML (a tour's outputs
// ask for both, and the documents of thousands of waypoints are not free to build).
struct DjiExport {
  std::optional<std::string> problem;
  std::vector<DjiClamp> clamps;  // none when there is a problem
};

DjiExport djiExport(const mission::TourResult& tour, const mission::Mission& mission) {
  DjiExport result;
  if (!mission.origin) {
    result.problem = "no geodetic origin";
    return result;
  }
  const DjiWpmlOptions options = djiWpmlOptions(mission.dji);
  for (const mission::SortieRoute& route : tour.routes) {
    try {
      const std::vector<DjiClamp> sortie = djiWpml(route, *mission.origin, options).clamps;
      result.clamps.insert(result.clamps.end(), sortie.begin(), sortie.end());
    } catch (const InputError& e) {
      result.problem =
          "sortie " + std::to_string(route.sortie) + ": " + e.what() + " (dji: " + mission.dji.payload + " on the " +
          mission.dji.payload_position + " mount of the " + mission.dji.drone +
          "; a payload on the upper mount of an M300 or M350 RTK looks up: dji: {payload_position: upper})";
      result.clamps.clear();
      return result;
    }
  }
  return result;
}

}  // namespace

std::optional<std::string> djiExportProblem(const mission::TourResult& tour, const mission::Mission& mission) {
  return djiExport(tour, mission).problem;
}

std::vector<DjiClamp> djiClamps(const mission::TourResult& tour, const mission::Mission& mission) {
  return djiExport(tour, mission).clamps;
}

std::string exportNotes(const mission::TourResult& tour, const mission::Mission& mission) {
  if (!mission.origin) return "";  // tourFilesLine names every geodetic export skipped, once
  const DjiExport dji = djiExport(tour, mission);
  if (dji.problem) return "  DJI KMZ not written: " + *dji.problem + "\n";
  const std::vector<DjiClamp>& clamps = dji.clamps;
  if (clamps.empty()) return "";
  std::map<std::string, std::vector<const DjiClamp*>> by_element;
  for (const DjiClamp& c : clamps) by_element[c.element].push_back(&c);
  std::string text = "  DJI KMZ: values outside DJI's ranges written as the nearest allowed (tour.json: dji_clamps):";
  for (const auto& [element, list] : by_element) {
    double lowest = list.front()->planned, written = list.front()->written;
    for (const DjiClamp* c : list)
      if (c->planned < lowest) std::tie(lowest, written) = std::make_tuple(c->planned, c->written);
    text += " " + element + " " + std::to_string(list.size()) + "x (e.g. planned " + formatNumber(lowest) +
            ", written " + formatNumber(written) + ");";
  }
  text.back() = '\n';
  return text;
}

StopCounts stopCounts(const mission::TourResult& tour) {
  StopCounts counts;
  const auto count = [&](std::size_t stop, int& targets, int& contact, int& photos) {
    if (tour.stops[stop].photo) {
      ++photos;
    } else if (tour.stops[stop].contact) {
      ++contact;
    } else {
      ++targets;
    }
  };
  for (std::size_t k = 0; k < tour.stops.size(); ++k) count(k, counts.targets, counts.contact_readings, counts.photos);
  for (const mission::Sortie& sortie : tour.plan.sorties)
    for (int place : sortie.targets)
      count(static_cast<std::size_t>(place - 1), counts.targets_visited, counts.contact_readings_taken,
            counts.photos_taken);
  return counts;
}

nlohmann::json tourSortiesJson(const mission::TourResult& tour) {
  nlohmann::json sorties = nlohmann::json::array();
  for (std::size_t k = 0; k < tour.plan.sorties.size(); ++k) {
    const mission::Sortie& sortie = tour.plan.sorties[k];
    nlohmann::json names = nlohmann::json::array(), legs = nlohmann::json::array();
    for (int target : sortie.targets) names.push_back(tour.names[target]);
    for (const mission::SortieLeg& leg : sortie.legs) {
      const mission::TourLeg& flown = tour.legs[leg.from][leg.to];
      legs.push_back({{"from", tour.names[leg.from]},
                      {"to", tour.names[leg.to]},
                      {"charge_ah", leg.charge_ah},
                      {"duration_s", leg.duration_s},
                      {"length_m", flown.evaluation.length_m},
                      {"waypoints", waypointsJson(flown.waypoints)}});
    }
    const mission::SortieRoute& route = tour.routes[k];
    sorties.push_back(
        {{"targets", names},
         {"legs", legs},
         {"takeoff_height_m", route.takeoffHeight_m()},
         {"landing_height_m", route.endsAtHome() ? nlohmann::json(route.landingHeight_m()) : nlohmann::json()},
         {"takeoff_s", tour.record.sorties[k].takeoff_s},
         {"charge_ah", sortie.charge_ah},
         {"duration_s", sortie.flight_s},
         {"recharge_s", sortie.recharge_s},
         {"turnaround_s", sortie.turnaround_s},
         {"fec", sortie.fec},
         {"dod", sortie.dod},
         {"min_soc", sortie.lowest_soc},
         {"wear", sortie.wear},
         {"reason", sortie.reason}});
    if (sortie.landing) {
      nlohmann::json& entry = sorties.back();
      entry["p_land_above_reserve"] = sortie.landing->p_land_above_reserve;
      entry["soc_p01"] = sortie.landing->soc_p01;
      entry["landing_soc_std"] = sortie.landing->soc_std;
      if (const auto& sampled = sortie.sampled_landing)
        entry["sampled_landing"] = {{"draws", sampled->draws},
                                    {"seed", sampled->seed},
                                    {"p_land_above_reserve", sampled->p_land_above_reserve},
                                    {"standard_error", sampled->standardError()},
                                    {"soc_p01", sampled->soc_p01}};
    }
  }
  return sorties;
}

namespace {

// The counts, totals, wear and duty of a tour, which tour.json and comparison.json share. Point
// targets, contact readings and photos are counted apart: a photo is no target.
void addTourFigures(nlohmann::json& json, const mission::TourResult& tour) {
  const StopCounts counts = stopCounts(tour);
  json["targets_total"] = counts.targets;
  json["targets_visited"] = counts.targets_visited;
  json["contact_readings_total"] = counts.contact_readings;
  json["contact_readings_taken"] = counts.contact_readings_taken;
  json["photos_total"] = counts.photos;
  json["photos_taken"] = counts.photos_taken;
  json["charge_ah"] = tour.plan.charge_ah;
  json["flight_s"] = tour.plan.flight_s;
  json["duration_s"] = tour.plan.duration_s;
  json["fec"] = tour.plan.fec;
  json["min_soc"] = tour.plan.min_soc;
  nlohmann::json wear;
  for (const mission::PlanWear& w : tour.wear)
    wear[w.model] = {{"wear_name", w.wear_name}, {"cycle_wear", w.cycle_wear}, {"capacity_loss", w.capacity_loss}};
  json["wear"] = std::move(wear);
  json["duty"] = dutyJson(tour.duty, tour.options);
}

}  // namespace

nlohmann::json tourJson(const mission::TourResult& tour, const mission::Mission& mission,
                        const Provenance& provenance) {
  nlohmann::json json;
  json["mission"] = mission.name();
  json["map"] = mission.map_file.string();
  json["vehicle"] = mission.vehicle_file.empty() ? "built-in: " + mission.vehicle.name : mission.vehicle_file.string();
  json["mode"] = mission::flightModeName(tour.mode);
  json["seed"] = tour.planning.seed;
  if (!tour.planning.wind.calm())  // still air leaves tour.json as it was
    json["wind"] = {{"speed_m_s", tour.planning.wind.speed_m_s},
                    {"from_deg", tour.planning.wind.from_deg},
                    {"gust_m_s", tour.planning.wind.gust_m_s},
                    {"sheltered_fraction", tour.planning.wind.sheltered_fraction}};
  json["planner"] = tour.options.planner;
  json["ageing_model"] = tour.plan.ageing_model;
  json["order_method"] = tour.order.method;
  json["between_sorties"] = mission.battery.between_sorties == mission::Turnaround::Swap ? "swap" : "recharge";
  json["unknown_space"] = unknownSpaceJson(tour.unknown_space, tour.unknown_summary);
  json["assumed_free_m"] = tour.assumed_free_m;
  json["stops_rechosen"] = tour.stops_rechosen;
  const DjiExport dji = djiExport(tour, mission);
  json["dji_kmz"] = dji.problem ? "not written: " + *dji.problem : "written";
  if (!mission.origin)
    json["geodetic_exports_skipped"] = {{"files", geodeticExportsSkipped(mission)},
                                        {"reason", "the mission has no 'origin:' ({lat, lon, alt} of the map frame)"}};
  if (!dji.problem) {
    nlohmann::json clamps = nlohmann::json::array();
    for (const DjiClamp& c : dji.clamps)
      clamps.push_back({{"sortie", c.sortie},
                        {"waypoint", c.waypoint},
                        {"element", c.element},
                        {"planned", c.planned},
                        {"written", c.written}});
    json["dji_clamps"] = clamps;
  }
  addTourFigures(json, tour);
  nlohmann::json targets = nlohmann::json::array();
  for (const mission::TourStop& stop : tour.stops) {
    const mission::Viewpoint& v = stop.viewpoint;
    targets.push_back({{"name", stop.target.name},
                       {"point", waypointsJson({stop.target.point_m})[0]},
                       {"viewpoint", waypointsJson({v.position_m})[0]},
                       {"distance_m", v.distance_m},
                       {"standoff_m", {stop.target.standoff_min_m, stop.target.standoff_max_m}},
                       {"ceiling_gap_m", finiteOrNull(v.ceiling_gap_m)},
                       {"viewpoint_standoff_m", v.standoff_m},
                       {"dwell_s", stop.target.dwell_s},
                       {"hover_power_w", stop.hover.propulsion_power_w}});
    if (stop.given_point_m) {
      targets.back()["given_point"] = waypointsJson({*stop.given_point_m})[0];
      targets.back()["moved_onto_surface_m"] = (*stop.given_point_m - stop.target.point_m).norm();
    }
  }
  json["targets"] = targets;
  json["target_figures"] = {
      {"distance_m", "from the viewpoint (the body centre) to the target point"},
      {"standoff_m", "the target's standoff range [min, max] from the mission: distance_m's bounds"},
      {"ceiling_gap_m", "from the rotor plane up to the nearest surface above (null: none)"},
      {"moved_onto_surface_m", "from given_point, inside a structure, to point, on its surface (only where moved)"},
      {"viewpoint_standoff_m", kStandoffMeasures}};
  if (tour.standoff) json["standoff"] = tourStandoffJson(tour, *tour.standoff);
  json["sorties"] = tourSortiesJson(tour);
  json["start_soc"] = tour.start_soc;
  json["reserve_soc"] = tour.reserve_soc;
  if (tour.coverage) json["coverage"] = coverageSummaryJson(tour);
  json["provenance"] = provenance.json();
  return json;
}

std::vector<TourPathRow> tourPathRows(const mission::TourResult& tour) {
  std::vector<TourPathRow> rows;
  for (std::size_t k = 0; k < tour.record.sorties.size(); ++k) {
    const mission::SortieRecord& sortie = tour.record.sorties[k];
    const int number = static_cast<int>(k) + 1;
    for (std::size_t i = 0; i < sortie.samples.size(); ++i) {
      const planner::PathSample& s = sortie.samples[i];
      rows.push_back({sortie.takeoff_s + s.t_s, s.position_m, s.speed_m_s, s.ceiling_gap_m, s.current_a, s.soc, number,
                      s.ground_gap_m, phaseName(sortie.phases[i]), s.assumed_free});
    }
    // The pack's recharge to the start SOC, on its own clock: where the wear models see it.
    const planner::PathSample& landed = sortie.samples.back();
    rows.push_back({sortie.takeoff_s + landed.t_s + sortie.recharge_s, landed.position_m, 0.0,
                    std::numeric_limits<double>::infinity(),
                    -tour.plan.sorties[k].charge_ah * 3600.0 / std::max(sortie.recharge_s, 1e-9), tour.start_soc,
                    number, std::numeric_limits<double>::infinity(), "recharge", false});
  }
  return rows;
}

void writeTourPathCsv(const std::filesystem::path& file, const mission::TourResult& tour,
                      const Provenance& provenance) {
  // Twelve significant digits, as a stream with that precision wrote them, formatted into one
  // string: a long tour has a row every few centimetres.
  constexpr int kDigits = 12;
  const std::vector<TourPathRow> rows = tourPathRows(tour);
  std::string text = provenance.csvComment() + "\n" +
                     "t_s,x,y,z,speed_m_s,ceiling_gap_m,current_a,soc,sortie,ground_gap_m,phase,assumed_free\n";
  text.reserve(text.size() + rows.size() * 12 * 14);
  for (const TourPathRow& row : rows) {
    for (const double value : {row.t_s, row.position_m.x(), row.position_m.y(), row.position_m.z(), row.speed_m_s}) {
      appendNumber(text, value, kDigits);
      text += ',';
    }
    if (std::isfinite(row.ceiling_gap_m)) appendNumber(text, row.ceiling_gap_m, kDigits);
    text += ',';
    appendNumber(text, row.current_a, kDigits);
    text += ',';
    appendNumber(text, row.soc, kDigits);
    text += ',' + std::to_string(row.sortie) + ',';
    if (std::isfinite(row.ground_gap_m)) appendNumber(text, row.ground_gap_m, kDigits);
    text += ',';
    text += row.phase;
    text += row.assumed_free ? ",1\n" : ",0\n";
  }
  writeTextAtomically(file, [&](std::ostream& out) { out << text; });
}

std::vector<AutopilotMission> autopilotMissions(const mission::TourResult& tour, const mission::Mission& mission,
                                                Autopilot autopilot) {
  const mission::GeodeticOrigin& origin = mission.requireOrigin();
  std::vector<AutopilotMission> missions;
  for (const mission::SortieRoute& route : tour.routes) {
    missions.push_back(autopilotMission(route, origin, autopilot));
    missions.back().hover_speed_m_s = mission.planning.speeds.inspection_m_s;
  }
  return missions;
}

void writeTourDirectory(const std::filesystem::path& dir, const mission::TourResult& tour,
                        const mission::Mission& mission, const environment::Environment& environment,
                        std::optional<Autopilot> autopilot, const Provenance& provenance) {
  writeJsonFile(dir / "tour.json", tourJson(tour, mission, provenance));
  writeTourPathCsv(dir / "path.csv", tour, provenance);
  writeMapViews(dir, environment, flownRoute(tour), provenance);
  if (tour.coverage) writeCoverageFiles(dir, tour, provenance);  // photos.csv, coverage.json, coverage_elements.csv
  const int count = static_cast<int>(tour.trajectories.size());
  const TrajectoryFrame frame = mission.trajectory_ned ? TrajectoryFrame::Ned : TrajectoryFrame::Enu;
  for (int k = 0; k < count; ++k) {
    writeTrajectoryCsv(sortieFileName(dir / "trajectory.csv", k + 1, count), tour.trajectories[k], frame, provenance);
    writeTrajectoryJson(sortieFileName(dir / "trajectory.json", k + 1, count), tour.trajectories[k], frame,
                        mission.origin, provenance);
  }
  writeReportHtml(
      dir / "report.html",
      tourReport({&tour}, mission, environment, mission.name() + ": " + mission::flightModeName(tour.mode) + " mode"));
  if (!autopilot || !mission.origin) return;  // the local frame's outputs need no origin, the rest are skipped
  const std::vector<AutopilotMission> missions = autopilotMissions(tour, mission, *autopilot);
  for (int k = 0; k < count; ++k) {
    writeQgcPlan(sortieFileName(dir / "mission.plan", k + 1, count), missions[k]);
    writeQgcWpl(sortieFileName(dir / "mission.waypoints", k + 1, count), missions[k]);
  }
  // DJI's payloads look up only so far: a tour that looks straight up at a soffit cannot be
  // flown with the default one, and tour.json's dji_kmz says so instead of a wrong photo angle.
  if (!djiExportProblem(tour, mission)) {
    const DjiWpmlOptions options = djiWpmlOptions(mission.dji);
    for (int k = 0; k < count; ++k)
      writeDjiKmz(sortieFileName(dir / "mission.kmz", k + 1, count), tour.routes[k], *mission.origin, options);
  }
  writeRoutesKml(dir / "routes.kml", tour.routes, *mission.origin, mission.name());
  writeRoutesGeoJson(dir / "routes.geojson", tour.routes, *mission.origin);
}

std::string comparisonTable(const mission::TourResult& ceiling, const mission::TourResult& free) {
  std::ostringstream out;
  char line[400];
  const auto row = [&](const std::string& label, double c, double f, const char* pattern, bool with_reduction) {
    std::snprintf(line, sizeof line, "%-40s %14s %14s %12s\n", label.c_str(), format(pattern, c).c_str(),
                  format(pattern, f).c_str(), with_reduction ? format("%.2f", reductionPct(c, f)).c_str() : "");
    out << line;
  };
  std::snprintf(line, sizeof line, "%-40s %14s %14s %12s\n", "", "ceiling", "free", "reduction %");
  out << line;
  const StopCounts c_counts = stopCounts(ceiling), f_counts = stopCounts(free);
  row("targets visited", c_counts.targets_visited, f_counts.targets_visited, "%.0f", false);
  if (c_counts.contact_readings + f_counts.contact_readings > 0)
    row("contact readings taken", c_counts.contact_readings_taken, f_counts.contact_readings_taken, "%.0f", false);
  row("sorties", static_cast<double>(ceiling.plan.sorties.size()), static_cast<double>(free.plan.sorties.size()),
      "%.0f", false);
  row("charge [Ah]", ceiling.plan.charge_ah, free.plan.charge_ah, "%.4f", true);
  row("flight time [s]", ceiling.plan.flight_s, free.plan.flight_s, "%.1f", true);
  if (ceiling.plan.sorties.size() > 1 || free.plan.sorties.size() > 1)
    row("duration with turnarounds [s]", ceiling.plan.duration_s, free.plan.duration_s, "%.1f", true);
  row("FEC (flights + recharges)", ceiling.plan.fec, free.plan.fec, "%.5f", true);
  row("lowest SOC [%]", 100.0 * ceiling.plan.min_soc, 100.0 * free.plan.min_soc, "%.2f", false);
  for (std::size_t m = 0; m < ceiling.wear.size() && m < free.wear.size(); ++m) {
    const mission::PlanWear &c = ceiling.wear[m], &f = free.wear[m];
    row(c.model + ": " + c.wear_name, c.cycle_wear, f.cycle_wear, "%.4e", true);
    row(c.model + ": capacity loss [%]", 100.0 * c.capacity_loss, 100.0 * f.capacity_loss, "%.5f", true);
  }
  if (ceiling.coverage && free.coverage) {
    const CoverageSummary c = coverageSummary(ceiling), f = coverageSummary(free);
    row("photos", static_cast<double>(c.photos), static_cast<double>(f.photos), "%.0f", true);
    row("route length [m]", c.route_m, f.route_m, "%.1f", true);
    row("covered, of the reachable surface [%]", c.covered_reachable_pct, f.covered_reachable_pct, "%.2f", false);
    row("mean GSD [mm/px]", c.mean_gsd_mm_px, f.mean_gsd_mm_px, "%.3f", false);
  }
  if (ceiling.duty.result && free.duty.result) {
    std::snprintf(line, sizeof line, "duty projection: the tour %d times a day for %d days\n",
                  ceiling.duty.missions_per_day, ceiling.duty.days);
    out << line;
    row("FEC over the study", ceiling.duty.result->fecTotal(), free.duty.result->fecTotal(), "%.2f", true);
  } else {
    for (const mission::TourResult* tour : {&ceiling, &free})
      if (!tour->duty.result)
        out << "duty projection, " << mission::flightModeName(tour->mode) << " mode: " << tour->duty.note << '\n';
  }
  out << windVerdict(ceiling, free);
  return out.str();
}

nlohmann::json comparisonJson(const mission::TourResult& ceiling, const mission::TourResult& free,
                              const Provenance& provenance) {
  nlohmann::json json;
  for (const mission::TourResult* tour : {&ceiling, &free}) {
    nlohmann::json figures;
    addTourFigures(figures, *tour);
    nlohmann::json entry;
    for (const char* key : {"targets_total", "targets_visited", "contact_readings_taken", "photos_taken", "charge_ah",
                            "flight_s", "duration_s", "fec", "min_soc", "wear", "duty"})
      entry[key] = std::move(figures[key]);
    entry["sorties"] = tour->plan.sorties.size();
    json[mission::flightModeName(tour->mode)] = entry;
  }
  nlohmann::json reduction = {{"charge", reductionPct(ceiling.plan.charge_ah, free.plan.charge_ah)},
                              {"flight_time", reductionPct(ceiling.plan.flight_s, free.plan.flight_s)},
                              {"duration", reductionPct(ceiling.plan.duration_s, free.plan.duration_s)},
                              {"fec", reductionPct(ceiling.plan.fec, free.plan.fec)}};
  if (ceiling.duty.result && free.duty.result)
    reduction["fec_total"] = reductionPct(ceiling.duty.result->fecTotal(), free.duty.result->fecTotal());
  for (std::size_t m = 0; m < ceiling.wear.size() && m < free.wear.size(); ++m) {
    reduction["wear_" + ceiling.wear[m].model] = reductionPct(ceiling.wear[m].cycle_wear, free.wear[m].cycle_wear);
    reduction["capacity_loss_" + ceiling.wear[m].model] =
        reductionPct(ceiling.wear[m].capacity_loss, free.wear[m].capacity_loss);
  }
  json["reduction_pct"] = reduction;
  if (ceiling.coverage && free.coverage) json["coverage"] = coverageComparisonJson(ceiling, free);
  json["provenance"] = provenance.json();
  return json;
}

void writeTourComparison(const std::filesystem::path& dir, const mission::TourResult& ceiling,
                         const mission::TourResult& free, const mission::Mission& mission,
                         const environment::Environment& environment, const Provenance& provenance) {
  std::vector<Eigen::Vector3d> routes = flownRoute(ceiling);
  const std::vector<Eigen::Vector3d> free_route = flownRoute(free);
  routes.insert(routes.end(), free_route.begin(), free_route.end());
  writeMapViews(dir, environment, routes, provenance);
  writeTextAtomically(dir / "comparison.txt", [&](std::ostream& stream) { stream << comparisonTable(ceiling, free); });
  writeReportHtml(dir / "report.html",
                  tourReport({&ceiling, &free}, mission, environment, mission.name() + ": both modes"));
  writeJsonFile(dir / "comparison.json", comparisonJson(ceiling, free, provenance));
}

std::string standoffLine(const mission::TourResult& tour) {
  const mission::TourStandoff& standoff = *tour.standoff;
  std::string line = "standoff " + formatNumber(standoff.standoff_m) + " m: ";
  if (standoff.legs.empty()) {
    line += "kept over the whole " + formatFixed(standoff.length_m, 1) + " m flown";
  } else {
    line += "kept over " + formatFixed(standoff.length_m - standoff.narrowed_m, 1) + " of " +
            formatFixed(standoff.length_m, 1) + " m flown, narrowed over " + formatFixed(standoff.narrowed_m, 1) +
            " m on " + std::to_string(standoff.legs.size()) + (standoff.legs.size() == 1 ? " leg" : " legs");
  }
  line += "; " + std::to_string(standoff.narrowed_stops.size()) + " of " + std::to_string(tour.stops.size()) +
          " viewpoints keep less";
  if (std::isfinite(standoff.min_standoff_m) && standoff.min_standoff_m < standoff.standoff_m)
    line += "; closest: " + standoffText(standoff.min_standoff_m) + " at " + formatPoint(standoff.narrowest_m);
  return line + " (tour.json: standoff)";
}

std::optional<std::string> movedOntoSurfaceLine(const mission::TourResult& tour) {
  std::string moved;
  int count = 0;
  for (const mission::TourStop& stop : tour.stops) {
    if (!stop.given_point_m) continue;
    moved += std::string(count++ ? "; '" : " '") + stop.target.name + "' by " +
             formatFixed((*stop.given_point_m - stop.target.point_m).norm(), 2) + " m, from " +
             formatPoint(*stop.given_point_m) + " to " + formatPoint(stop.target.point_m);
  }
  if (count == 0) return std::nullopt;
  return std::to_string(count) + " target(s) given inside a structure moved onto its surface:" + moved +
         " (tour.json: targets[].moved_onto_surface_m)";
}

std::optional<std::string> standoffLimitedLine(const mission::TourResult& tour) {
  const std::vector<const mission::TourStop*> stops = standoffLimitedStops(tour);
  if (stops.empty() || !tour.standoff) return std::nullopt;
  std::string line = std::to_string(stops.size()) + " target(s) keep less than the " +
                     formatNumber(tour.standoff->standoff_m) +
                     " m standoff, as no viewpoint in their standoff range keeps it:";
  for (const mission::TourStop* stop : stops) line += " '" + stop->target.name + "' " + seenFromText(*stop) + ";";
  line.back() = ' ';
  return line + "(tour.json: standoff.limited_targets)";
}

std::string tourHeadline(const mission::Mission& mission, const std::string& mode, const mission::TourOptions& options,
                         const mission::PlanningOptions& settings) {
  std::string inspects = std::to_string(mission.targets.size()) + " targets";
  if (mission.isCoverage())
    inspects += ", " + std::to_string(mission.surfaces.size()) + " surface(s), " +
                std::to_string(mission.contact_grids.size()) + " contact grid(s)";
  const std::string wind = settings.wind.calm() ? "" : ", in " + windText(settings.wind);
  return "tour of " + mission.file.string() + ": " + inspects + ", mode " + mode + ", planner " + options.planner +
         ", seed " + std::to_string(settings.seed) + ", split for least " + settings.ageing_model + " wear" + wind +
         "\n";
}

std::string tourFilesLine(const std::filesystem::path& dir, const mission::Mission& mission,
                          const std::vector<mission::TourResult>& tours, std::optional<Autopilot> autopilot) {
  std::string text;
  for (const mission::TourResult& tour : tours) {
    const std::filesystem::path at = tours.size() > 1 ? dir / mission::flightModeName(tour.mode) : dir;
    std::string files = "tour.json, path.csv, trajectory.csv, trajectory.json, report.html, map_top.csv, map_side.csv";
    if (!mission.surfaces.empty()) files += ", photos.csv, coverage.json, coverage_elements.csv";
    if (autopilot && mission.origin) {
      files += ", mission.plan, mission.waypoints";
      if (!djiExportProblem(tour, mission)) files += ", mission.kmz";
      files += ", routes.kml, routes.geojson";
    }
    if (tour.routes.size() > 1) files += " (one trajectory, .plan, .waypoints and .kmz per sortie: NAME_sortieN)";
    text += "wrote " + at.string() + ": " + files + "\n";
  }
  if (tours.size() > 1)
    text += "wrote " + dir.string() + ": comparison.txt, comparison.json, report.html, map_top.csv, map_side.csv\n";
  if (!autopilot) {
    text += "no autopilot files (--no-export)\n";
  } else if (!mission.origin) {
    text += geodeticExportsSkippedLine(mission) + "\n";
  }
  return text + "figures: " + plotCommand("plot-tour") + " " + dir.string() + "\n";
}

namespace {

// "lands above the reserve with probability 0.9993 (landing SOC 1st percentile 31.2 %; sampled:
// 0.999 +- 0.001 over 1000 draws, seed 1)", and a warning when the sampled odds are lower than
// the computed ones beyond 3 standard errors and the 0.002 the tests allow for curvature.
std::string landingLine(const mission::Sortie& s) {
  std::string line = "lands above the reserve with probability " + formatNumber(s.landing->p_land_above_reserve, 4) +
                     " (landing SOC 1st percentile " + formatFixed(100.0 * s.landing->soc_p01, 1) + " %";
  if (!s.sampled_landing) return line + ")";
  const mission::SampledLanding& sampled = *s.sampled_landing;
  line += "; sampled: " + formatNumber(sampled.p_land_above_reserve, 4) + " +- " +
          formatNumber(sampled.standardError(), 2) + " over " + std::to_string(sampled.draws) + " draws, seed " +
          std::to_string(sampled.seed) + ")";
  if (sampled.p_land_above_reserve + 3.0 * sampled.standardError() + 0.002 < s.landing->p_land_above_reserve)
    line +=
        "; warning: the sampled odds are below the computed ones beyond their sampling error, so trust the "
        "sampled figure and plan with a larger reserve (docs/models.md, \"Landing confidence\")";
  return line;
}

}  // namespace

std::string tourSummary(const mission::TourResult& tour) {
  std::ostringstream out;
  char line[600];
  std::snprintf(line, sizeof line, "%s mode: %zu targets, order by %s, %zu sortie(s) split for least %s wear\n",
                mission::flightModeName(tour.mode).c_str(), tour.stops.size(), tour.order.method.c_str(),
                tour.plan.sorties.size(), tour.plan.ageing_model.c_str());
  out << line;
  for (std::size_t k = 0; k < tour.plan.sorties.size(); ++k) {
    const mission::Sortie& s = tour.plan.sorties[k];
    std::snprintf(line, sizeof line, "  sortie %zu: %zu targets, %.4f Ah, %.1f s, DoD %.1f %%, lands at %.1f %%: %s\n",
                  k + 1, s.targets.size(), s.charge_ah, s.flight_s, 100.0 * s.dod, 100.0 * s.lowest_soc,
                  s.reason.c_str());
    out << line;
    if (s.landing) out << "    " << landingLine(s) << '\n';
  }
  std::snprintf(line, sizeof line, "  total %.4f Ah, %.1f s in the air", tour.plan.charge_ah, tour.plan.flight_s);
  out << line;
  if (tour.plan.sorties.size() > 1) out << " (" << formatFixed(tour.plan.duration_s, 1) << " s with turnarounds)";
  std::snprintf(line, sizeof line, ", FEC %.5f, lowest SOC %.1f %% (reserve %.0f %%)\n", tour.plan.fec,
                100.0 * tour.plan.min_soc, 100.0 * tour.reserve_soc);
  out << line;
  if (const std::optional<std::string> moved = movedOntoSurfaceLine(tour)) out << "  " << *moved << '\n';
  if (tour.standoff) {
    out << "  " << standoffLine(tour) << '\n';
    if (const std::optional<std::string> limited = standoffLimitedLine(tour)) out << "  " << *limited << '\n';
  }
  for (const mission::SortieRoute& route : tour.routes) {
    out << "  sortie " << route.sortie << " takes off straight up to " << formatFixed(route.takeoffHeight_m(), 2)
        << " m above home";
    if (route.endsAtHome()) out << " and lands straight down from " << formatFixed(route.landingHeight_m(), 2) << " m";
    out << '\n';
  }
  if (tour.stops_rechosen)
    out << "  stops chosen again among the places a route from home reaches (the first choice left one where none "
           "did)\n";
  if (!tour.duty.result) out << "  duty projection " << tour.duty.note << '\n';
  const mission::TourTimes& t = tour.times;
  std::snprintf(
      line, sizeof line,
      "  phases: stops %.1f s, legs %.1f s, order and split %.1f s, routing %.1f s, refining %.1f s, record %.1f s",
      t.stops_s, t.legs_s, t.order_s, t.routing_s, t.refining_s, t.record_s);
  out << line;
  if (tour.coverage) out << ", coverage re-check " << formatFixed(t.coverage_check_s, 1) << " s";
  out << " (" << t.rounds << " rounds)\n";
  if (!tour.coverage_check) return out.str();
  out << "  " << tour.photos.size() << " photos, route " << formatFixed(routeLength_m(tour), 1) << " m\n";
  // What the photos flown cover, by the independent re-check.
  for (std::size_t r = 0; r < tour.coverage_check->regions.size(); ++r) {
    const mission::RegionCoverageCheck& region = tour.coverage_check->regions[r];
    std::snprintf(line, sizeof line,
                  "  '%s': %.2f m2, %.2f %% of the reachable %.2f m2 covered at or below %s mm/px (re-check), mean GSD "
                  "%.3f mm/px, %.2f m2 unreachable\n",
                  region.name.c_str(), region.area_m2, 100.0 * region.coveredReachableShare(), region.reachable_area_m2,
                  formatNumber(tour.coverage->regions[r].region.gsd_mm_px).c_str(), region.mean_gsd_mm_px,
                  region.unreachable_area_m2);
    out << line;
  }
  return out.str();
}

}  // namespace ceilplan::io
