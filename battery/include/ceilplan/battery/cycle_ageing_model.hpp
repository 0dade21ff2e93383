#pragma once
// Base of the ageing models that weigh rainflow cycles of the SOC history (Xu, Schmalstieg,
// Woehler): it counts the cycles as the samples stream in and hands each closed one over.

#include "ceilplan/battery/ageing_model.hpp"
#include "ceilplan/battery/rainflow.hpp"

#include <vector>

namespace ceilplan::battery {

class CycleAgeingModel : public AgeingModel {
 public:
  // The rainflow count of the SOC history so far (for inspection and reports).
  const RainflowCounter& rainflow() const { return counter_; }

 protected:
  // A cycle that has closed: it is final, add its damage.
  virtual void addCycle(const RainflowCycle& cycle) = 0;
  // Time passing between two consecutive samples (calendar ageing); nothing by default.
  virtual void addInterval(const AgeingSample& from, const AgeingSample& to);
  double modelCapacityLoss() const final { return capacityLossWith(counter_.residue()); }
  // The loss so far if the still-open ranges `open` (half cycles) closed now.
  virtual double capacityLossWith(const std::vector<RainflowCycle>& open) const = 0;

 private:
  void consume(const AgeingSample* previous, const AgeingSample* samples,
               std::size_t count) final;

  RainflowCounter counter_;
  std::vector<RainflowCycle> closed_;  // scratch, reused between samples
};

}  // namespace ceilplan::battery
