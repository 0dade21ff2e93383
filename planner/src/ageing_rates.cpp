#include "ceilplan/planner/ageing_rates.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace ceilplan::planner {
namespace {

constexpr double kSampleStepS = 10.0;
constexpr double kCalendarWindowS = 86400.0;

// Appends samples every kSampleStepS while the SOC moves linearly to `to_soc` over `duration_s`.
void appendRamp(std::vector<battery::AgeingSample>& history, double to_soc, double duration_s, double current_a) {
  const battery::AgeingSample start = history.back();
  const int steps = std::max(1, static_cast<int>(std::ceil(duration_s / kSampleStepS)));
  for (int k = 1; k <= steps; ++k) {
    const double f = double(k) / steps;
    history.push_back({start.t_s + f * duration_s, start.soc + f * (to_soc - start.soc), current_a});
  }
}

double lossOf(const std::string& name, const battery::AgeingModelOptions& options,
              const std::vector<battery::AgeingSample>& history) {
  const auto model = battery::makeAgeingModel(name, options);
  model->addSamples(history);
  return model->capacityLoss();
}

}  // namespace

AgeingRates measureAgeingRates(const std::string& model_name, const battery::AgeingModelOptions& options,
                               const battery::Pack& pack, double start_soc, double depth_of_discharge,
                               double discharge_current_a) {
  pack.validate();
  if (!(depth_of_discharge > 0.0 && depth_of_discharge <= start_soc - pack.soc_min + 1e-12))
    throw ceilplan::InputError("ageing objective: depth of discharge must lie in (0, start SOC - minimum SOC], got " +
                               formatNumber(depth_of_discharge));
  if (!(discharge_current_a > 0.0)) throw ceilplan::InputError("ageing objective: discharge current must be > 0 A");
  const double discharged_ah = depth_of_discharge * pack.usableCapacityAh();
  const double discharge_s = 3600.0 * discharged_ah / discharge_current_a;
  const double charge_s = 3600.0 * discharged_ah / pack.charge_current_a;

  std::vector<battery::AgeingSample> cycle{{0.0, start_soc, 0.0}};
  appendRamp(cycle, start_soc - depth_of_discharge, discharge_s, discharge_current_a);
  appendRamp(cycle, start_soc, charge_s, -pack.charge_current_a);
  std::vector<battery::AgeingSample> rest{{0.0, start_soc, 0.0}};
  appendRamp(rest, start_soc, discharge_s + charge_s, 0.0);
  std::vector<battery::AgeingSample> day{{0.0, start_soc, 0.0}};
  appendRamp(day, start_soc, kCalendarWindowS, 0.0);

  AgeingRates rates;
  rates.model = model_name;
  rates.depth_of_discharge = depth_of_discharge;
  rates.loss_per_ah =
      std::max(0.0, lossOf(model_name, options, cycle) - lossOf(model_name, options, rest)) / discharged_ah;
  rates.loss_per_s = lossOf(model_name, options, day) / kCalendarWindowS;
  if (!(rates.loss_per_ah > 0.0 || rates.loss_per_s > 0.0))
    throw ceilplan::Error("ageing model '" + model_name + "' predicts no wear for a " +
                          formatNumber(depth_of_discharge) + " depth-of-discharge cycle: choose another objective");
  return rates;
}

}  // namespace ceilplan::planner
