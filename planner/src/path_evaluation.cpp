#include "ceilplan/planner/path_evaluation.hpp"

#include "ceilplan/battery/simulation.hpp"
#include "ceilplan/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace ceilplan::planner {
namespace {

void requireEvaluable(const battery::Pack& pack, double start_soc, const std::vector<Eigen::Vector3d>& waypoints_m,
                      double max_speed_m_s) {
  if (waypoints_m.size() < 2) throw ceilplan::InputError("a path needs at least 2 waypoints");
  if (!(max_speed_m_s > 0.0)) throw ceilplan::InputError("the speed cap must be positive");
  if (!(start_soc > 0.0 && start_soc <= 1.0)) throw ceilplan::InputError("start SOC must lie in (0, 1]");
  pack.validate();
}

// A sample's speed, gaps and draw, moving at `velocity` in `conditions` at `soc`: what a flown
// sample and the hovering one of a path that stays put share.
void setDraw(PathSample& sample, const FlightCostModel& model, const PointConditions& conditions,
             const Velocity& velocity, double soc) {
  sample.speed_m_s = velocity.along_m_s;
  sample.ceiling_gap_m = conditions.nearest_ceiling_gap_m;
  sample.ground_gap_m = conditions.ground_gap_m;
  const energy::CurrentBreakdown terms = model.breakdown(conditions, velocity, soc);
  sample.current_a = terms.current_a;
  sample.power_w = terms.power_w;
  sample.propulsion_power_w = terms.propulsionW();
}

// A path that stays where it starts (two targets seen from the same place): nothing is flown; its
// one sample is the place, hovering, at no time.
PathSample hoveringAt(const FlightCostModel& model, const Eigen::Vector3d& place_m, double soc) {
  PathSample hovering;
  hovering.position_m = place_m;
  const PointConditions conditions = model.exactConditionsAt(place_m);
  setDraw(hovering, model, conditions, model.hoverAt(conditions), soc);
  hovering.soc = soc;
  return hovering;
}

// The one integration of a path under the full model, for evaluatePath and evaluatePathTotals:
// each segment's conditions come from `conditions_along(from, to)` (one per sample, in the order
// FlightCostModel::integrate takes them), and `keep(sample)` sees each sample once its time and
// SOC are known. The current at a sample sees the SOC reached just before it (explicit coulomb
// counting).
template <class ConditionsAlong, class Keep>
PathEvaluation integratePath(const FlightCostModel& model, const battery::Pack& pack, double start_soc,
                             const std::vector<Eigen::Vector3d>& waypoints_m, double max_speed_m_s,
                             ConditionsAlong&& conditions_along, Keep&& keep) {
  battery::CoulombCounter battery(pack, start_soc);
  PathEvaluation result;
  double energy_j = 0.0;
  for (std::size_t s = 0; s + 1 < waypoints_m.size(); ++s) {
    const Eigen::Vector3d& from = waypoints_m[s];
    const Eigen::Vector3d delta = waypoints_m[s + 1] - from;
    const double length = delta.norm();
    if (length == 0.0) continue;
    const Eigen::Vector3d direction = delta / length;
    const int intervals = model.intervalCount(from, waypoints_m[s + 1]);
    const std::vector<PointConditions> conditions = conditions_along(from, waypoints_m[s + 1]);
    PathSample previous;
    bool previous_near = false;
    for (int k = 0; k <= intervals; ++k) {
      PathSample sample;
      sample.position_m = k == intervals ? waypoints_m[s + 1] : Eigen::Vector3d(from + delta * (double(k) / intervals));
      Velocity velocity = model.velocityAt(conditions[k], direction);
      if (velocity.along_m_s > max_speed_m_s) {
        // Slower along the same track: the wind against it is the same.
        const double slower = max_speed_m_s / velocity.along_m_s;
        velocity = {max_speed_m_s, velocity.horizontal_m_s * slower, velocity.climb_m_s * slower, velocity.wind};
      }
      setDraw(sample, model, conditions[k], velocity, battery.soc());
      const bool near = model.nearCeiling(conditions[k]);
      if (k > 0) {
        // Trapezoid in distance for time; the interval draws the mean of its ends' currents.
        const double dt = 0.5 * (1.0 / previous.speed_m_s + 1.0 / sample.speed_m_s) * (length / intervals);
        battery.discharge(0.5 * (previous.current_a + sample.current_a), dt);
        battery.requireAboveFloor();
        energy_j += 0.5 * (previous.power_w + sample.power_w) * dt;
        result.duration_s += dt;
        result.time_under_ceiling_s += (previous_near && near) ? dt : (previous_near || near) ? 0.5 * dt : 0.0;
      }
      sample.t_s = result.duration_s;
      sample.soc = battery.soc();
      previous_near = near;
      previous = sample;
      keep(std::move(sample));
    }
    result.length_m += length;
  }
  result.charge_ah = battery.chargeAh();
  result.energy_wh = energy_j / 3600.0;
  result.fec = battery::fullEquivalentCycles(2.0 * result.charge_ah, pack.capacity_ah);  // and the equal recharge
  result.mean_current_a = result.duration_s > 0.0 ? 3600.0 * result.charge_ah / result.duration_s : 0.0;
  result.min_soc = battery.lowestSoc();
  return result;
}

// evaluatePathTotals: the integration on conditionsAlong (no gap lookup far from structure),
// `keep` seeing each sample, and NaN for the figures only each sample's own lookups give.
template <class Keep>
PathEvaluation integrateTotals(const FlightCostModel& model, const battery::Pack& pack, double start_soc,
                               const std::vector<Eigen::Vector3d>& waypoints_m, double max_speed_m_s, Keep&& keep) {
  requireEvaluable(pack, start_soc, waypoints_m, max_speed_m_s);
  PathEvaluation result = integratePath(
      model, pack, start_soc, waypoints_m, max_speed_m_s,
      [&](const Eigen::Vector3d& from, const Eigen::Vector3d& to) { return model.conditionsAlong(from, to); },
      std::forward<Keep>(keep));
  const double unknown = std::numeric_limits<double>::quiet_NaN();
  result.min_clearance_m = result.min_ceiling_gap_m = result.assumed_free_m = unknown;
  return result;
}

}  // namespace

PathEvaluation evaluatePath(const FlightCostModel& model, const battery::Pack& pack, double start_soc,
                            const std::vector<Eigen::Vector3d>& waypoints_m, double max_speed_m_s) {
  requireEvaluable(pack, start_soc, waypoints_m, max_speed_m_s);
  const environment::Environment& environment = model.environment();
  std::vector<PathSample> samples;
  PathEvaluation result = integratePath(
      model, pack, start_soc, waypoints_m, max_speed_m_s,
      [&](const Eigen::Vector3d& from, const Eigen::Vector3d& to) { return model.exactConditionsAlong(from, to); },
      [&](PathSample&& sample) {
        sample.clearance_m = environment.clearance_m(sample.position_m);
        sample.assumed_free = environment.assumesFree(sample.position_m);
        samples.push_back(std::move(sample));
      });
  result.samples = std::move(samples);
  if (result.samples.empty()) {
    PathSample hovering = hoveringAt(model, waypoints_m.front(), start_soc);
    hovering.clearance_m = environment.clearance_m(hovering.position_m);
    hovering.assumed_free = environment.assumesFree(hovering.position_m);
    result.samples.push_back(hovering);
  }
  result.min_clearance_m = std::numeric_limits<double>::infinity();
  result.min_ceiling_gap_m = std::numeric_limits<double>::infinity();
  for (const PathSample& sample : result.samples) {
    result.min_clearance_m = std::min(result.min_clearance_m, sample.clearance_m);
    result.min_ceiling_gap_m = std::min(result.min_ceiling_gap_m, sample.ceiling_gap_m);
  }
  result.assumed_free_m = environment.assumedFreeAlong(waypoints_m).length_m;
  return result;
}

PathEvaluation evaluatePathTotals(const FlightCostModel& model, const battery::Pack& pack, double start_soc,
                                  const std::vector<Eigen::Vector3d>& waypoints_m, double max_speed_m_s) {
  return integrateTotals(model, pack, start_soc, waypoints_m, max_speed_m_s, [](PathSample&&) {});
}

PathEvaluation evaluatePathTotals(const FlightCostModel& model, const battery::Pack& pack, double start_soc,
                                  const std::vector<Eigen::Vector3d>& waypoints_m, double max_speed_m_s,
                                  std::vector<PathDraw>& draws) {
  draws.clear();
  PathEvaluation result = integrateTotals(model, pack, start_soc, waypoints_m, max_speed_m_s, [&](PathSample&& sample) {
    draws.push_back({sample.t_s, sample.propulsion_power_w});
  });
  if (draws.empty()) draws.push_back({0.0, hoveringAt(model, waypoints_m.front(), start_soc).propulsion_power_w});
  return result;
}

}  // namespace ceilplan::planner
