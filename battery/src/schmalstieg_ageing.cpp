#include "ceilplan/battery/schmalstieg_ageing.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ceilplan::battery {
namespace {

constexpr double kSecondsPerDay = 86400.0;
constexpr double kCalendarExponent = 0.75;      // t^0.75 (Schmalstieg et al. 2014)
constexpr double kCycleCapacityExponent = 0.5;  // sqrt(Q) (Schmalstieg et al. 2014)
constexpr double kLargestCellVoltage_v = 5.0;
constexpr int kSimpsonIntervals = 8;  // even; V(SOC) is smooth enough over one swing

}  // namespace

double schmalstiegCalendarCapacityRate(double v, double temperature_k, const SchmalstiegParameters& p) {
  return std::max(0.0, (p.a_cap_v * v + p.a_cap_0) * 1e6 * std::exp(p.a_cap_t_k / temperature_k));
}

double schmalstiegCycleCapacityRate(double rms_v, double depth, const SchmalstiegParameters& p) {
  return p.b_cap_v * (rms_v - p.b_cap_v0) * (rms_v - p.b_cap_v0) + p.b_cap_0 + p.b_cap_dod * depth;
}

double schmalstiegCalendarResistanceRate(double v, double temperature_k, const SchmalstiegParameters& p) {
  return std::max(0.0, (p.a_res_v * v + p.a_res_0) * 1e5 * std::exp(p.a_res_t_k / temperature_k));
}

double schmalstiegCycleResistanceRate(double rms_v, double depth, const SchmalstiegParameters& p) {
  return p.b_res_v * (rms_v - p.b_res_v0) * (rms_v - p.b_res_v0) + p.b_res_0 + p.b_res_dod * depth;
}

double advancePowerLawState(double state, double rate, double exponent, double step) {
  if (!(rate > 0.0) || !(step > 0.0)) return state;  // no stress, no progress
  const double equivalent = std::pow(state / rate, 1.0 / exponent);
  return rate * std::pow(equivalent + step, exponent);
}

SchmalstiegAgeingModel::SchmalstiegAgeingModel(const OperatingConditions& conditions,
                                               CellVoltageOfSoc cell_voltage_of_soc,
                                               const SchmalstiegParameters& parameters)
    : conditions_(conditions), cell_voltage_of_soc_(std::move(cell_voltage_of_soc)), parameters_(parameters) {
  conditions_.validate();
  if (!cell_voltage_of_soc_)
    throw ceilplan::InputError("the Schmalstieg model needs a cell voltage of SOC (the pack's per-cell OCV table)");
}

ValidityRange SchmalstiegAgeingModel::validity() const {
  // BLAST-Lite's experimental range for this model: cycling 20..40 C, 1C charge and discharge.
  return {{"NMC"}, 293.15, 313.15,
          1.0,     1.0,    "cycle terms fitted at 1C and 35 C only: no temperature or C-rate dependence"};
}

std::unique_ptr<AgeingModel> SchmalstiegAgeingModel::clone() const {
  return std::make_unique<SchmalstiegAgeingModel>(*this);
}

double SchmalstiegAgeingModel::cellVoltage(double soc) const {
  const double v = cell_voltage_of_soc_(soc);
  if (!std::isfinite(v) || v <= 0.0 || v > kLargestCellVoltage_v)
    throw ceilplan::InputError("cell voltage " + formatNumber(v) + " V at SOC " + formatNumber(soc) +
                               " is not a single cell's (0..5 V); give one cell's voltage");
  return v;
}

double SchmalstiegAgeingModel::rmsCellVoltage(double mean_soc, double depth) const {
  if (!(depth > 0.0)) return cellVoltage(mean_soc);
  const double low = mean_soc - 0.5 * depth;
  const double h = depth / kSimpsonIntervals;
  double sum = 0.0;
  for (int i = 0; i <= kSimpsonIntervals; ++i) {
    const double v = cellVoltage(std::clamp(low + i * h, 0.0, 1.0));
    const double weight = (i == 0 || i == kSimpsonIntervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    sum += weight * v * v;
  }
  return std::sqrt(sum * h / 3.0 / depth);
}

void SchmalstiegAgeingModel::advance(CycleState& state, const RainflowCycle& cycle) const {
  // The charge the cycle really moved, in nominal capacities of the fitted cell: a faded pack
  // swings its SOC further for the same charge.
  const double throughput_ah =
      2.0 * cycle.count * cycle.range * stateOfHealthOf(cycle) * parameters_.reference_cell_capacity_ah;
  if (!(throughput_ah > 0.0)) return;
  state.throughput_ah += throughput_ah;
  const double rms_v = rmsCellVoltage(cycle.mean, cycle.range);
  state.capacity_loss =
      advancePowerLawState(state.capacity_loss, schmalstiegCycleCapacityRate(rms_v, cycle.range, parameters_),
                           kCycleCapacityExponent, throughput_ah);
  state.resistance_growth += schmalstiegCycleResistanceRate(rms_v, cycle.range, parameters_) * throughput_ah;
}

void SchmalstiegAgeingModel::addCycle(const RainflowCycle& cycle) { advance(closed_cycles_, cycle); }

void SchmalstiegAgeingModel::addInterval(const AgeingSample& from, const AgeingSample& to) {
  const double t_k = conditions_.temperature_k;
  if (from.soc != last_rates_soc_) {
    const double v = cellVoltage(from.soc);
    last_capacity_rate_ = schmalstiegCalendarCapacityRate(v, t_k, parameters_);
    last_resistance_rate_ = schmalstiegCalendarResistanceRate(v, t_k, parameters_);
  }
  const double v_to = cellVoltage(to.soc);
  const double capacity_rate_to = schmalstiegCalendarCapacityRate(v_to, t_k, parameters_);
  const double resistance_rate_to = schmalstiegCalendarResistanceRate(v_to, t_k, parameters_);
  const double dt_days = (to.t_s - from.t_s) / kSecondsPerDay;
  calendar_capacity_loss_ = advancePowerLawState(
      calendar_capacity_loss_, 0.5 * (last_capacity_rate_ + capacity_rate_to), kCalendarExponent, dt_days);
  calendar_resistance_growth_ = advancePowerLawState(
      calendar_resistance_growth_, 0.5 * (last_resistance_rate_ + resistance_rate_to), kCalendarExponent, dt_days);
  last_rates_soc_ = to.soc;
  last_capacity_rate_ = capacity_rate_to;
  last_resistance_rate_ = resistance_rate_to;
}

SchmalstiegAgeingModel::CycleState SchmalstiegAgeingModel::cycleStateWith(
    const std::vector<RainflowCycle>& open) const {
  CycleState state = closed_cycles_;
  for (const RainflowCycle& cycle : open) advance(state, cycle);
  return state;
}

double SchmalstiegAgeingModel::cycleCapacityLoss() const { return cycleStateWith(rainflow().residue()).capacity_loss; }

double SchmalstiegAgeingModel::chargeThroughputAh() const { return cycleStateWith(rainflow().residue()).throughput_ah; }

double SchmalstiegAgeingModel::resistanceGrowth() const {
  return calendar_resistance_growth_ + cycleStateWith(rainflow().residue()).resistance_growth;
}

double SchmalstiegAgeingModel::capacityLossWith(const std::vector<RainflowCycle>& open) const {
  return calendar_capacity_loss_ + cycleStateWith(open).capacity_loss;
}

}  // namespace ceilplan::battery
