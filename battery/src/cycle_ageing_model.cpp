#include "ceilplan/battery/cycle_ageing_model.hpp"

#include <algorithm>

namespace ceilplan::battery {

void CycleAgeingModel::addInterval(const AgeingSample&, const AgeingSample&) {}

void CycleAgeingModel::consume(const AgeingSample* previous, const AgeingSample* samples, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    const AgeingSample* before = i > 0 ? &samples[i - 1] : previous;
    if (before != nullptr) addInterval(*before, samples[i]);
    if (health_changes_.empty() || health_changes_.back().state_of_health != samples[i].state_of_health)
      health_changes_.push_back({counter_.samplesSeen(), samples[i].state_of_health});
    counter_.add(samples[i].soc, closed_);
    for (const RainflowCycle& cycle : closed_) addCycle(cycle);
    closed_.clear();
  }
  const std::size_t first_open = counter_.firstOpenIndex();
  while (health_changes_.size() > 1 && health_changes_[1].first_index <= first_open) health_changes_.pop_front();
}

double CycleAgeingModel::stateOfHealthAt(std::size_t index) const {
  const auto after = std::upper_bound(health_changes_.begin(), health_changes_.end(), index,
                                      [](std::size_t i, const HealthFrom& change) { return i < change.first_index; });
  return after == health_changes_.begin() ? 1.0 : std::prev(after)->state_of_health;
}

double CycleAgeingModel::stateOfHealthOf(const RainflowCycle& cycle) const { return stateOfHealthAt(cycle.end); }

}  // namespace ceilplan::battery
