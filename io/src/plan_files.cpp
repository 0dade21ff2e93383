#include "ceilplan/io/plan_files.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/io/atomic_file.hpp"
#include "ceilplan/io/csv_columns.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/map_views.hpp"
#include "ceilplan/io/unknown_space_report.hpp"

#include "ceilplan/core/format.hpp"
#include "reduction.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>

namespace ceilplan::io {

nlohmann::json figuresJson(const planner::PathEvaluation& e) {
  return {{"length_m", e.length_m},
          {"duration_s", e.duration_s},
          {"charge_ah", e.charge_ah},
          {"energy_wh", e.energy_wh},
          {"fec", e.fec},
          {"mean_current_a", e.mean_current_a},
          {"min_soc", e.min_soc},
          {"min_clearance_m", finiteOrNull(e.min_clearance_m)},
          {"min_ceiling_gap_m", finiteOrNull(e.min_ceiling_gap_m)},
          {"time_under_ceiling_s", e.time_under_ceiling_s},
          {"assumed_free_m", e.assumed_free_m}};
}

nlohmann::json waypointsJson(const std::vector<Eigen::Vector3d>& waypoints_m) {
  nlohmann::json list = nlohmann::json::array();
  for (const Eigen::Vector3d& p : waypoints_m) list.push_back({p.x(), p.y(), p.z()});
  return list;
}

void writePathCsv(const std::filesystem::path& file, const planner::PathEvaluation& evaluation,
                  const Provenance& provenance) {
  writeTextAtomically(file, [&](std::ostream& out) {
    out << provenance.csvComment() << '\n'
        << "t_s,x,y,z,speed_m_s,ceiling_gap_m,current_a,soc,ground_gap_m,assumed_free\n"
        << std::setprecision(12);
    for (const planner::PathSample& s : evaluation.samples) {
      out << s.t_s << ',' << s.position_m.x() << ',' << s.position_m.y() << ',' << s.position_m.z() << ','
          << s.speed_m_s << ',';
      if (std::isfinite(s.ceiling_gap_m)) out << s.ceiling_gap_m;
      out << ',' << s.current_a << ',' << s.soc << ',';
      if (std::isfinite(s.ground_gap_m)) out << s.ground_gap_m;
      out << ',' << (s.assumed_free ? 1 : 0) << '\n';
    }
  });
}

void writePlanDirectory(const std::filesystem::path& dir, const planner::PlanResult& plan,
                        const planner::PathEvaluation& evaluation, const nlohmann::json& extra,
                        const Provenance& provenance) {
  nlohmann::json json = figuresJson(evaluation);
  json["waypoints"] = waypointsJson(plan.waypoints);
  json["planner"] = plan.planner;
  json["cost"] = plan.cost;
  json["search_cost"] = plan.search_cost;
  json["search_time_s"] = plan.search_time_s;
  json["total_time_s"] = plan.total_time_s;
  json.update(extra);
  json["provenance"] = provenance.json();
  writeJsonFile(dir / "plan.json", json);
  writePathCsv(dir / "path.csv", evaluation, provenance);
}

nlohmann::json routePlanJson(const mission::RoutePlan& route, const mission::PlanningContext& context,
                             const std::string& map_file, std::uint64_t seed) {
  nlohmann::json json{{"seed", seed},
                      {"objective", route.objective.name},
                      {"cost_unit", route.cost_unit},
                      {"mode", mission::flightModeName(route.mode)},
                      {"map", map_file},
                      {"vehicle", context.vehicle().name},
                      {"battery", context.battery().description},
                      {"start_soc", context.battery().start_soc},
                      {"unknown_space", unknownSpaceJson(context.environment())}};
  if (route.standoff) json["standoff"] = standoffJson(*route.standoff);
  if (route.objective.name == "ageing") {
    const planner::AgeingRates& ageing = route.objective.ageing;
    json["ageing"] = {{"model", ageing.model},
                      {"depth_of_discharge", ageing.depth_of_discharge},
                      {"loss_per_ah", ageing.loss_per_ah},
                      {"loss_per_s", ageing.loss_per_s}};
  }
  return json;
}

void writeRoutePlan(const std::filesystem::path& dir, const mission::RoutePlan& route,
                    const mission::PlanningContext& context, const std::string& map_file, std::uint64_t seed,
                    const Provenance& provenance) {
  writePlanDirectory(dir, route.plan, route.evaluation, routePlanJson(route, context, map_file, seed), provenance);
}

nlohmann::json routeCheckJson(const mission::RouteCheck& check, const std::vector<Eigen::Vector3d>& waypoints_m,
                              const mission::PlanningContext& context, const Provenance& provenance) {
  nlohmann::json json = figuresJson(check.evaluation);
  json["valid"] = !check.violation;
  json["violation"] = check.violation ? nlohmann::json(*check.violation) : nlohmann::json(nullptr);
  json["objective"] = context.options().objective;
  json["cost"] = check.cost;
  json["cost_unit"] = check.cost_unit;
  json["waypoints"] = waypointsJson(waypoints_m);
  json["unknown_space"] = unknownSpaceJson(context.environment());
  json["provenance"] = provenance.json();
  return json;
}

std::vector<Eigen::Vector3d> readPathWaypoints(const std::filesystem::path& file) {
  const CsvColumns table = CsvColumns::read(file, {}, {"x", "y", "z", "x_m", "y_m", "z_m"});
  const std::string suffix = table.hasColumn("x") ? "" : "_m";
  const std::vector<std::string>& names = table.columnNames();
  if (!table.hasColumn("x" + suffix) && std::find(names.begin(), names.end(), "north_m") != names.end())
    throw InputError(file.string() +
                     " is in the NED frame (north_m, east_m, down_m); a path is read in the map frame: "
                     "write the trajectory in ENU (x_m, y_m, z_m)");
  for (const char* axis : {"x", "y", "z"})
    if (!table.hasColumn(axis + suffix))
      throw InputError(file.string() + " has neither x, y, z (path.csv) nor x_m, y_m, z_m (trajectory.csv) columns");
  const std::vector<double>&x = table.column("x" + suffix), &y = table.column("y" + suffix),
        &z = table.column("z" + suffix);
  std::vector<Eigen::Vector3d> points;
  for (std::size_t row = 0; row < table.rowCount(); ++row) points.emplace_back(x[row], y[row], z[row]);
  try {
    return mission::distinctWaypoints(points);
  } catch (const InputError&) {
    rethrowWithContext(file.string() + ": ");
  }
}

std::string figuresLine(const planner::PathEvaluation& e) {
  char line[320];
  std::snprintf(line, sizeof line,
                "length %.2f m, %.1f s, %.5f Ah, %.3f Wh, FEC %.6f, mean %.3f A, lowest SOC %.2f %%, "
                "%.1f s under the ceiling",
                e.length_m, e.duration_s, e.charge_ah, e.energy_wh, e.fec, e.mean_current_a, 100.0 * e.min_soc,
                e.time_under_ceiling_s);
  std::string text = line;
  if (e.assumed_free_m > 0.0) text += ", " + formatFixed(e.assumed_free_m, 2) + " m through space assumed free";
  return text;
}

std::string ageingObjectiveLine(const planner::AgeingRates& ageing) {
  char line[320];
  std::snprintf(line, sizeof line,
                "ageing objective: %s model at %.1f %% depth of discharge: %.4g per Ah, %.4g per s of capacity",
                ageing.model.c_str(), 100 * ageing.depth_of_discharge, ageing.loss_per_ah, ageing.loss_per_s);
  return line;
}

std::string routePlanText(const mission::RoutePlan& route) {
  char line[320];
  std::snprintf(line, sizeof line, "%zu waypoints; cost %.6g %s (search %.6g) after %.2f s\n",
                route.plan.waypoints.size(), route.plan.cost, route.cost_unit.c_str(), route.plan.search_cost,
                route.plan.total_time_s);
  std::string text = line + figuresLine(route.evaluation) + '\n';
  if (route.standoff) text += standoffLine(*route.standoff) + '\n';
  return text;
}

std::string routeCheckText(const mission::RouteCheck& check, std::size_t points,
                           const mission::PlanningContext& context) {
  char lines[640];
  std::snprintf(lines, sizeof lines, "%zu points: %s\n%s cost %.6g %s\nvalid: %s\n", points,
                figuresLine(check.evaluation).c_str(), context.options().objective.c_str(), check.cost,
                check.cost_unit.c_str(), check.violation ? "false" : "true");
  std::string text = lines;
  if (check.violation) text += "violation: " + *check.violation + '\n';
  return text + "unknown space: " + unknownSpaceLine(context.environment()) + '\n';
}

std::string standoffText(double standoff_m) {
  if (standoff_m >= 0.0)
    return "the airframe's bounding sphere " + formatFixed(standoff_m, 2) + " m from the nearest structure";
  return "the airframe's bounding sphere " + formatFixed(-standoff_m, 2) +
         " m into the nearest structure (the sphere overlaps it; the airframe itself keeps its clearance)";
}

nlohmann::json standoffJson(const planner::StandoffReport& report) {
  nlohmann::json spans = nlohmann::json::array();
  for (const planner::NarrowedSpan& span : report.spans)
    spans.push_back({{"from_m", span.from_m},
                     {"to_m", span.to_m},
                     {"min_standoff_m", span.min_standoff_m},
                     {"at", waypointsJson({span.narrowest_m})[0]}});
  return {{"standoff_m", report.standoff_m},
          {"length_m", report.length_m},
          {"narrowed_m", report.narrowed_m},
          {"min_standoff_m", finiteOrNull(report.min_standoff_m)},
          {"narrowed", spans},
          {"standoff_measures", kStandoffMeasures}};
}

std::string standoffLine(const planner::StandoffReport& report) {
  std::string line = "standoff " + formatNumber(report.standoff_m) + " m: ";
  if (report.spans.empty()) return line + "kept over the whole " + formatFixed(report.length_m, 2) + " m";
  const auto narrowest = std::min_element(report.spans.begin(), report.spans.end(), [](const auto& a, const auto& b) {
    return a.min_standoff_m < b.min_standoff_m;
  });
  return line + "kept over " + formatFixed(report.length_m - report.narrowed_m, 2) + " of " +
         formatFixed(report.length_m, 2) + " m, narrowed over " + formatFixed(report.narrowed_m, 2) + " m in " +
         std::to_string(report.spans.size()) + (report.spans.size() == 1 ? " place" : " places") +
         "; closest: " + standoffText(narrowest->min_standoff_m) + " at " + formatPoint(narrowest->narrowest_m);
}

std::string routeComparisonTable(const mission::RouteComparison& comparison, const mission::DutyOptions& duty,
                                 const mission::BatterySpec& battery) {
  const planner::PathEvaluation &c = comparison.ceiling.evaluation, &f = comparison.free.evaluation;
  std::string out;
  char line[256];
  const auto row = [&](const char* label, double ceiling, double free, int decimals, bool with_reduction) {
    std::snprintf(line, sizeof line, "%-34s %14s %14s %12s\n", label, formatFixed(ceiling, decimals).c_str(),
                  formatFixed(free, decimals).c_str(),
                  with_reduction ? formatFixed(reductionPct(ceiling, free), 2).c_str() : "");
    out += line;
  };
  std::snprintf(line, sizeof line, "both plans scored with the full model (start SOC %.0f %%)\n%-34s %14s %14s %12s\n",
                100.0 * battery.start_soc, "", "ceiling", "free", "reduction %");
  out += line;
  row("length [m]", c.length_m, f.length_m, 2, false);
  row("time [s]", c.duration_s, f.duration_s, 1, true);
  row("charge [Ah]", c.charge_ah, f.charge_ah, 5, true);
  row("energy [Wh]", c.energy_wh, f.energy_wh, 3, true);
  row("mean current [A]", c.mean_current_a, f.mean_current_a, 3, true);
  row("FEC (flight + recharge)", c.fec, f.fec, 6, true);
  row("lowest SOC [%]", 100 * c.min_soc, 100 * f.min_soc, 2, false);
  row("time under the ceiling [s]", c.time_under_ceiling_s, f.time_under_ceiling_s, 1, false);
  std::snprintf(line, sizeof line,
                "\nduty projection: each mission flies the route %d times (the slower plan fills %.0f min), idles "
                "%.0f min, charges back at %.1f A; %d missions a day for %d days\n",
                comparison.repeats, duty.flight_min, duty.idle_min, battery.pack.charge_current_a,
                duty.missions_per_day, duty.days);
  out += line;
  const battery::DutyResult &cd = comparison.ceiling_duty, &fd = comparison.free_duty;
  row("FEC per mission", cd.fecPerMission(), fd.fecPerMission(), 4, true);
  row("FEC over the study", cd.fecTotal(), fd.fecTotal(), 2, true);
  row("lowest SOC over the study [%]", 100 * cd.minSoc(), 100 * fd.minSoc(), 1, false);
  return out;
}

nlohmann::json routeComparisonJson(const mission::RouteComparison& comparison, const mission::DutyOptions& duty,
                                   const nlohmann::json& extra) {
  nlohmann::json json = extra;
  json["duty"] = {{"flight_min", duty.flight_min},
                  {"idle_min", duty.idle_min},
                  {"charge_max_min", duty.charge_max_min},
                  {"missions_per_day", duty.missions_per_day},
                  {"days", duty.days}};
  const auto entry = [&](const mission::RoutePlan& route, const battery::DutyResult& result) {
    nlohmann::json figures = figuresJson(route.evaluation);
    figures["cost"] = route.plan.cost;
    figures["repeats_per_mission"] = comparison.repeats;
    figures["fec_per_mission"] = result.fecPerMission();
    figures["fec_total"] = result.fecTotal();
    figures["duty_min_soc"] = result.minSoc();
    if (route.standoff) figures["standoff"] = standoffJson(*route.standoff);
    return figures;
  };
  json["ceiling"] = entry(comparison.ceiling, comparison.ceiling_duty);
  json["free"] = entry(comparison.free, comparison.free_duty);
  const planner::PathEvaluation &c = comparison.ceiling.evaluation, &f = comparison.free.evaluation;
  json["reduction_pct"] = {
      {"charge", reductionPct(c.charge_ah, f.charge_ah)},
      {"energy", reductionPct(c.energy_wh, f.energy_wh)},
      {"fec_total", reductionPct(comparison.ceiling_duty.fecTotal(), comparison.free_duty.fecTotal())}};
  return json;
}

void writeRouteComparison(const std::filesystem::path& dir, const mission::RouteComparison& comparison,
                          const mission::DutyOptions& duty, const mission::PlanningContext& context,
                          const std::string& planner, std::uint64_t seed, const Provenance& provenance) {
  const nlohmann::json extra{{"objective", context.options().objective},
                             {"seed", seed},
                             {"planner", planner},
                             {"unknown_space", unknownSpaceJson(context.environment())}};
  for (const mission::RoutePlan* route : {&comparison.ceiling, &comparison.free}) {
    const std::string mode = mission::flightModeName(route->mode);
    nlohmann::json plan_extra = extra;
    plan_extra["mode"] = mode;
    if (route->standoff) plan_extra["standoff"] = standoffJson(*route->standoff);
    writePlanDirectory(dir / mode, route->plan, route->evaluation, plan_extra, provenance);
  }
  writeJsonFile(dir / "compare.json", withProvenance(routeComparisonJson(comparison, duty, extra), provenance));
  std::vector<Eigen::Vector3d> routes = comparison.ceiling.plan.waypoints;
  routes.insert(routes.end(), comparison.free.plan.waypoints.begin(), comparison.free.plan.waypoints.end());
  writeMapViews(dir, context.environment(), routes, provenance);
}

}  // namespace ceilplan::io
