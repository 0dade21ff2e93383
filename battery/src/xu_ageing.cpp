#include "ceilplan/battery/xu_ageing.hpp"

#include <algorithm>
#include <cmath>

namespace ceilplan::battery {

double xuDepthStress(double depth, const XuParameters& p) {
  const double d = std::min(depth, 1.0);
  if (!(d > 0.0)) return 0.0;
  return 1.0 / (p.k_d1 * std::pow(d, p.k_d2) + p.k_d3);
}

double xuSocStress(double soc, const XuParameters& p) { return std::exp(p.k_s * (soc - p.soc_ref)); }

double xuTemperatureStress(double temperature_k, const XuParameters& p) {
  return std::exp(p.k_t_per_k * (temperature_k - p.t_ref_k) * p.t_ref_k / temperature_k);
}

double xuCapacityLoss(double damage, const XuParameters& p) {
  return 1.0 - p.a_sei * std::exp(-p.b_sei * damage) - (1.0 - p.a_sei) * std::exp(-damage);
}

XuAgeingModel::XuAgeingModel(const OperatingConditions& conditions, const XuParameters& parameters)
    : parameters_(parameters) {
  conditions.validate();
  temperature_stress_ = xuTemperatureStress(conditions.temperature_k, parameters_);
}

ValidityRange XuAgeingModel::validity() const {
  // Chemistry, temperature and C-rate ranges are [open] defaults (docs/ageing.md): the fit is
  // labelled LMO by the implementations, and the law has no C-rate term.
  return {{"LMO"}, 288.15, 318.15, 1.0, 1.0, "no C-rate term; depth clamped to 1"};
}

std::unique_ptr<AgeingModel> XuAgeingModel::clone() const { return std::make_unique<XuAgeingModel>(*this); }

double XuAgeingModel::cycleStress(const RainflowCycle& cycle) const {
  return cycle.count * xuDepthStress(cycle.range, parameters_) * xuSocStress(cycle.mean, parameters_) *
         temperature_stress_;
}

void XuAgeingModel::addCycle(const RainflowCycle& cycle) { closed_cycle_damage_ += cycleStress(cycle); }

void XuAgeingModel::addInterval(const AgeingSample& from, const AgeingSample& to) {
  const double dt_s = to.t_s - from.t_s;
  elapsed_s_ += dt_s;
  soc_time_integral_s_ += 0.5 * (from.soc + to.soc) * dt_s;
}

double XuAgeingModel::cycleDamageWith(const std::vector<RainflowCycle>& open) const {
  double damage = closed_cycle_damage_;
  for (const RainflowCycle& cycle : open) damage += cycleStress(cycle);
  return damage;
}

double XuAgeingModel::cycleDamage() const { return cycleDamageWith(rainflow().residue()); }

double XuAgeingModel::calendarDamage() const {
  if (!(elapsed_s_ > 0.0)) return 0.0;
  const double mean_soc = soc_time_integral_s_ / elapsed_s_;
  return parameters_.k_calendar_per_s * elapsed_s_ * xuSocStress(mean_soc, parameters_) * temperature_stress_;
}

double XuAgeingModel::capacityLossWith(const std::vector<RainflowCycle>& open) const {
  return xuCapacityLoss(cycleDamageWith(open) + calendarDamage(), parameters_);
}

}  // namespace ceilplan::battery
