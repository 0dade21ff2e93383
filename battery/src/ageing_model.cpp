#include "ceilplan/battery/ageing_model.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

namespace ceilplan::battery {
namespace {

constexpr double kCelsiusToKelvin = 273.15;
constexpr double kLargestPlausibleCelsius = 150.0;  // above this a value is kelvin given as Celsius

bool sameWord(const std::string& a, const std::string& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const auto& word : words) text += (text.empty() ? "" : "/") + word;
  return text;
}

std::string sampleError(std::size_t index, const std::string& what) {
  return "ageing: sample " + std::to_string(index) + ": " + what;
}

}  // namespace

OperatingConditions OperatingConditions::fromCelsius(double temperature_c) {
  if (!std::isfinite(temperature_c))
    throw ceilplan::InputError("temperature must be a finite number of degrees Celsius");
  if (temperature_c > kLargestPlausibleCelsius)
    throw ceilplan::InputError("temperature " + formatNumber(temperature_c) +
                               " C is over 150 C and looks like kelvin; give it in Celsius (" +
                               formatNumber(temperature_c - kCelsiusToKelvin) + " C)");
  if (temperature_c <= -kCelsiusToKelvin)
    throw ceilplan::InputError("temperature " + formatNumber(temperature_c) +
                               " C is at or below absolute zero; give it in Celsius");
  OperatingConditions conditions;
  conditions.temperature_k = temperature_c + kCelsiusToKelvin;
  return conditions;
}

void OperatingConditions::validate() const {
  if (!std::isfinite(temperature_k) || temperature_k <= 0.0)
    throw ceilplan::InputError("temperature " + formatNumber(temperature_k) +
                               " K must be a finite number of kelvin above 0");
}

void AgeingModel::validate(const AgeingSample* samples, std::size_t count) const {
  double previous_time_s = samples_seen_ > 0 ? last_.t_s : -INFINITY;
  for (std::size_t i = 0; i < count; ++i) {
    const AgeingSample& s = samples[i];
    const std::size_t index = samples_seen_ + i;
    if (!std::isfinite(s.t_s) || !std::isfinite(s.soc) || !std::isfinite(s.current_a))
      throw ceilplan::InputError(sampleError(index, "time, SOC or current is not a finite number"));
    if (s.soc < 0.0 || s.soc > 1.0)
      throw ceilplan::InputError(
          sampleError(index, "SOC " + formatNumber(s.soc) + " is outside [0, 1]; give SOC as a fraction"));
    if (!(s.state_of_health > 0.0 && s.state_of_health <= 1.0))
      throw ceilplan::InputError(sampleError(
          index, "state of health " + formatNumber(s.state_of_health) + " is outside (0, 1]; give it as a fraction"));
    if (s.t_s < previous_time_s)
      throw ceilplan::InputError(sampleError(
          index, "time goes backwards (" + formatNumber(previous_time_s) + " s to " + formatNumber(s.t_s) + " s)"));
    previous_time_s = s.t_s;
  }
}

void AgeingModel::addSamples(const AgeingSample* samples, std::size_t count) {
  if (count == 0) return;
  validate(samples, count);
  consume(samples_seen_ > 0 ? &last_ : nullptr, samples, count);
  for (std::size_t i = 0; i < count; ++i) {
    peak_discharge_current_a_ = std::max(peak_discharge_current_a_, samples[i].current_a);
    peak_charge_current_a_ = std::max(peak_charge_current_a_, -samples[i].current_a);
  }
  last_ = samples[count - 1];
  samples_seen_ += count;
}

void AgeingModel::addSamples(const std::vector<AgeingSample>& samples) { addSamples(samples.data(), samples.size()); }

double AgeingModel::capacityLoss() const { return std::min(1.0, modelCapacityLoss()); }

ObservedCRates AgeingModel::observedCRates(double nominal_capacity_ah) const {
  if (!(nominal_capacity_ah > 0.0) || !std::isfinite(nominal_capacity_ah))
    throw ceilplan::InputError("nominal capacity " + formatNumber(nominal_capacity_ah) +
                               " Ah must be a positive number");
  return {peak_charge_current_a_ / nominal_capacity_ah, peak_discharge_current_a_ / nominal_capacity_ah};
}

std::vector<std::string> validityWarnings(const std::string& model_name, const ValidityRange& range,
                                          const OperatingConditions& conditions, const ObservedCRates& observed) {
  std::vector<std::string> warnings;
  if (!conditions.chemistry.empty() && !range.chemistries.empty() &&
      std::none_of(range.chemistries.begin(), range.chemistries.end(),
                   [&](const std::string& c) { return sameWord(c, conditions.chemistry); }))
    warnings.push_back(model_name + ": fitted on " + joined(range.chemistries) + " cells, not " + conditions.chemistry);
  const double t_c = conditions.temperature_k - kCelsiusToKelvin;
  if (conditions.temperature_k < range.min_temperature_k || conditions.temperature_k > range.max_temperature_k)
    warnings.push_back(model_name + ": temperature " + formatNumber(t_c) + " C is outside the fitted " +
                       formatNumber(range.min_temperature_k - kCelsiusToKelvin) + ".." +
                       formatNumber(range.max_temperature_k - kCelsiusToKelvin) + " C");
  if (observed.charge > range.max_charge_c_rate)
    warnings.push_back(model_name + ": charge rate " + formatNumber(observed.charge) + "C exceeds the fitted " +
                       formatNumber(range.max_charge_c_rate) + "C");
  if (observed.discharge > range.max_discharge_c_rate)
    warnings.push_back(model_name + ": discharge rate " + formatNumber(observed.discharge) + "C exceeds the fitted " +
                       formatNumber(range.max_discharge_c_rate) + "C");
  return warnings;
}

std::vector<std::string> validityWarnings(const AgeingModel& model, const OperatingConditions& conditions,
                                          double nominal_capacity_ah) {
  return validityWarnings(model.name(), model.validity(), conditions, model.observedCRates(nominal_capacity_ah));
}

}  // namespace ceilplan::battery
