#include "plan_output.hpp"

#include "json_values.hpp"
#include "output.hpp"

#include <cmath>
#include <cstdio>
#include <iomanip>

namespace ceilplan::app {

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
          {"time_under_ceiling_s", e.time_under_ceiling_s}};
}

nlohmann::json waypointsJson(const std::vector<Eigen::Vector3d>& waypoints_m) {
  nlohmann::json list = nlohmann::json::array();
  for (const Eigen::Vector3d& p : waypoints_m) list.push_back({p.x(), p.y(), p.z()});
  return list;
}

void writePathCsv(const std::filesystem::path& file, const planner::PathEvaluation& evaluation) {
  writeTextAtomically(file, [&](std::ostream& out) {
    out << "t_s,x,y,z,speed_m_s,ceiling_gap_m,current_a,soc\n" << std::setprecision(9);
    for (const planner::PathSample& s : evaluation.samples) {
      out << s.t_s << ',' << s.position_m.x() << ',' << s.position_m.y() << ',' << s.position_m.z() << ','
          << s.speed_m_s << ',';
      if (std::isfinite(s.ceiling_gap_m)) out << s.ceiling_gap_m;
      out << ',' << s.current_a << ',' << s.soc << '\n';
    }
  });
}

void writePlanDirectory(const std::filesystem::path& dir, const planner::PlanResult& plan,
                        const planner::PathEvaluation& evaluation, const nlohmann::json& extra) {
  nlohmann::json json = figuresJson(evaluation);
  json["waypoints"] = waypointsJson(plan.waypoints);
  json["planner"] = plan.planner;
  json["cost"] = plan.cost;
  json["search_cost"] = plan.search_cost;
  json["search_time_s"] = plan.search_time_s;
  json["total_time_s"] = plan.total_time_s;
  json.update(extra);
  writeTextAtomically(dir / "plan.json", [&](std::ostream& stream) { stream << std::setw(2) << json << '\n'; });
  writePathCsv(dir / "path.csv", evaluation);
}

std::string figuresLine(const planner::PathEvaluation& e) {
  char line[320];
  std::snprintf(line, sizeof line,
                "length %.2f m, %.1f s, %.5f Ah, %.3f Wh, FEC %.6f, mean %.3f A, lowest SOC %.2f %%, "
                "%.1f s under the ceiling",
                e.length_m, e.duration_s, e.charge_ah, e.energy_wh, e.fec, e.mean_current_a, 100.0 * e.min_soc,
                e.time_under_ceiling_s);
  return line;
}

}  // namespace ceilplan::app
