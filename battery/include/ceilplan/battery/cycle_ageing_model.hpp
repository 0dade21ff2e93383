#pragma once
/// @file
/// Base of the ageing models that weigh rainflow cycles of the SOC history (Xu, Schmalstieg,
/// Woehler): it counts the cycles as the samples stream in and hands each closed one over.

#include "ceilplan/battery/ageing_model.hpp"
#include "ceilplan/battery/rainflow.hpp"

#include <deque>
#include <vector>

namespace ceilplan::battery {

/// An ageing model whose cycle terms come from a rainflow count of the SOC history: subclasses add each closed cycle's
/// damage.
class CycleAgeingModel : public AgeingModel {
 public:
  /// The rainflow count of the SOC history so far (for inspection and reports).
  const RainflowCounter& rainflow() const { return counter_; }

 protected:
  /// A cycle that has closed: it is final, add its damage.
  virtual void addCycle(const RainflowCycle& cycle) = 0;
  /// Time passing between two consecutive samples (calendar ageing); nothing by default.
  virtual void addInterval(const AgeingSample& from, const AgeingSample& to);
  double modelCapacityLoss() const final { return capacityLossWith(counter_.residue()); }
  /// The loss so far if the still-open ranges `open` (half cycles) closed now.
  virtual double capacityLossWith(const std::vector<RainflowCycle>& open) const = 0;
  /// The state of health a cycle happened at: that of the swing reaching its later turning point
  /// (exact for the half cycles of missions flown at one SOH each; within a mission's fade step
  /// for full cycles). A cycle's SOC range times this is its range in nominal capacities.
  double stateOfHealthOf(const RainflowCycle& cycle) const;

 private:
  /// The state of health from sample `first_index` on, until the next change.
  struct HealthFrom {
    std::size_t first_index;
    double state_of_health;
  };

  void consume(const AgeingSample* previous, const AgeingSample* samples, std::size_t count) final;
  double stateOfHealthAt(std::size_t index) const;

  RainflowCounter counter_;
  std::vector<RainflowCycle> closed_;  ///< scratch, reused between samples
  /// Changes of state of health still needed by an open turning point (a few at most: older
  /// ones are dropped as the rainflow count lets go of their samples).
  std::deque<HealthFrom> health_changes_;
};

}  // namespace ceilplan::battery
