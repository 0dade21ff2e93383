#pragma once
/// @file
/// OMPL's view of SafetyRules for single states.

#include "ceilplan/planner/safety_rules.hpp"

#include <ompl/base/StateValidityChecker.h>

namespace ceilplan::planner {

class FlightStateValidityChecker : public ompl::base::StateValidityChecker {
 public:
  /// `rules` must outlive the checker.
  FlightStateValidityChecker(const ompl::base::SpaceInformationPtr& si, const SafetyRules& rules);
  bool isValid(const ompl::base::State* state) const override;
  const SafetyRules& rules() const { return rules_; }

 private:
  const SafetyRules& rules_;
};

}  // namespace ceilplan::planner
