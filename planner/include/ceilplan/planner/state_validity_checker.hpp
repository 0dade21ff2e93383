#pragma once
/// @file
/// OMPL's view of SafetyRules for single states.

#include "ceilplan/planner/safety_rules.hpp"

#include <ompl/base/StateValidityChecker.h>

namespace ceilplan::planner {

/// OMPL state validity checker under SafetyRules.
class FlightStateValidityChecker : public ompl::base::StateValidityChecker {
 public:
  /// `rules` must outlive the checker.
  FlightStateValidityChecker(const ompl::base::SpaceInformationPtr& si, const SafetyRules& rules);
  /// OMPL: whether the vehicle may be at `state`.
  bool isValid(const ompl::base::State* state) const override;
  /// The rules it checks.
  const SafetyRules& rules() const { return rules_; }

 private:
  const SafetyRules& rules_;
};

}  // namespace ceilplan::planner
