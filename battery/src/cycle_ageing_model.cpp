#include "ceilplan/battery/cycle_ageing_model.hpp"

namespace ceilplan::battery {

void CycleAgeingModel::addInterval(const AgeingSample&, const AgeingSample&) {}

void CycleAgeingModel::consume(const AgeingSample* previous, const AgeingSample* samples,
                               std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    const AgeingSample* before = i > 0 ? &samples[i - 1] : previous;
    if (before != nullptr) addInterval(*before, samples[i]);
    counter_.add(samples[i].soc, closed_);
    for (const RainflowCycle& cycle : closed_) addCycle(cycle);
    closed_.clear();
  }
}

}  // namespace ceilplan::battery
