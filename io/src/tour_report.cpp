#include "ceilplan/io/tour_report.hpp"

#include "ceilplan/core/format.hpp"
#include "reduction.hpp"

namespace ceilplan::io {

ReportPlan tourReportPlan(const mission::TourResult& tour) {
  ReportPlan plan;
  plan.name = mission::flightModeName(tour.mode);
  for (std::size_t k = 0; k < tour.record.sorties.size(); ++k) {
    const mission::SortieRecord& sortie = tour.record.sorties[k];
    for (const planner::PathSample& s : sortie.samples)
      plan.samples.push_back({sortie.takeoff_s + s.t_s, s.position_m, s.current_a, s.soc, static_cast<int>(k) + 1});
  }
  for (const mission::TourStop& stop : tour.stops)
    plan.targets.push_back({stop.target.name, stop.target.point_m, stop.viewpoint.position_m});
  int visited = 0;
  for (const mission::Sortie& sortie : tour.plan.sorties) visited += static_cast<int>(sortie.targets.size());
  plan.summary = {{"targets", std::to_string(visited) + " of " + std::to_string(tour.stops.size())},
                  {"sorties", std::to_string(tour.plan.sorties.size())},
                  {"charge", formatFixed(tour.plan.charge_ah, 4) + " Ah"},
                  {"in the air", formatFixed(tour.plan.flight_s, 1) + " s"},
                  {"FEC", formatNumber(tour.plan.fec, 5)},
                  {"lowest SOC", formatFixed(100 * tour.plan.min_soc, 1) + " %"}};
  // With a calibrated vehicle: the least likely sortie's odds of landing above the reserve.
  std::optional<mission::LandingOdds> worst;
  for (const mission::Sortie& sortie : tour.plan.sorties)
    if (sortie.landing && (!worst || sortie.landing->p_land_above_reserve < worst->p_land_above_reserve))
      worst = sortie.landing;
  if (worst) {
    plan.summary.emplace_back("P(land above reserve), least sortie", formatNumber(worst->p_land_above_reserve, 4));
    plan.summary.emplace_back("its 1st-percentile landing SOC", formatFixed(100 * worst->soc_p01, 1) + " %");
  }
  return plan;
}

ReportModel tourReport(const std::vector<const mission::TourResult*>& tours, const mission::Mission& mission,
                       const environment::Environment& environment, const std::string& title) {
  ReportModel model;
  model.title = title;
  model.home_m = mission.home_m;
  model.reserve_soc = mission.battery.reserve_soc;
  std::vector<Eigen::Vector3d> route;
  for (const mission::TourResult* tour : tours) {
    model.plans.push_back(tourReportPlan(*tour));
    for (const ReportSample& s : model.plans.back().samples) route.push_back(s.position_m);
  }
  model.structure = structureNear(environment.grid(), route, 3.0);
  if (tours.size() == 2) {
    const mission::TourResult &c = *tours[0], &f = *tours[1];
    model.comparison_header = {"", "ceiling", "free", "reduction %"};
    const auto row = [&](const std::string& label, double ceiling, double free, int decimals, bool reduction) {
      model.comparison_rows.push_back({label, formatFixed(ceiling, decimals), formatFixed(free, decimals),
                                       reduction ? formatFixed(reductionPct(ceiling, free), 2) : ""});
    };
    row("charge [Ah]", c.plan.charge_ah, f.plan.charge_ah, 4, true);
    row("flight time [s]", c.plan.flight_s, f.plan.flight_s, 1, true);
    row("FEC", c.plan.fec, f.plan.fec, 5, true);
    row("lowest SOC [%]", 100 * c.plan.min_soc, 100 * f.plan.min_soc, 1, false);
    for (std::size_t m = 0; m < c.wear.size() && m < f.wear.size(); ++m)
      row(c.wear[m].model + " capacity loss [%]", 100 * c.wear[m].capacity_loss, 100 * f.wear[m].capacity_loss, 5,
          true);
  }
  return model;
}

}  // namespace ceilplan::io
