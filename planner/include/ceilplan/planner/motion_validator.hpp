#pragma once
/// @file
/// OMPL's view of SafetyRules for straight motions.

#include "ceilplan/planner/safety_rules.hpp"

#include <ompl/base/MotionValidator.h>

#include <utility>

namespace ceilplan::planner {

/// OMPL motion validator under SafetyRules.
class FlightMotionValidator : public ompl::base::MotionValidator {
 public:
  /// `rules` must outlive the validator.
  FlightMotionValidator(const ompl::base::SpaceInformationPtr& si, const SafetyRules& rules);
  /// OMPL: whether the straight motion is valid.
  bool checkMotion(const ompl::base::State* from, const ompl::base::State* to) const override;
  /// Reports the last valid state found by bisection-free stepping from `from`.
  bool checkMotion(const ompl::base::State* from, const ompl::base::State* to,
                   std::pair<ompl::base::State*, double>& last_valid) const override;

 private:
  const SafetyRules& rules_;
};

}  // namespace ceilplan::planner
