// Thin OMPL adapters: the position space, the state validity checker and the motion validator.

#include "ceilplan/planner/motion_validator.hpp"
#include "ceilplan/planner/ompl_state.hpp"
#include "ceilplan/planner/state_validity_checker.hpp"

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateProjections.h>

#include <algorithm>
#include <cmath>

namespace ceilplan::planner {
namespace {

// Projects onto the position itself. OMPL's default projection of a 3-D real vector space is a
// random matrix (ProjectionMatrix::ComputeRandom) that Debian's libompl 1.5.2 frees in a way
// AddressSanitizer reports as a bad free, which stopped every planning command under ASan; the
// identity needs no random draw and suits projection-based planners as well.
class PositionStateSpace : public ompl::base::RealVectorStateSpace {
 public:
  PositionStateSpace() : RealVectorStateSpace(3) {}
  void registerProjections() override {
    registerDefaultProjection(std::make_shared<ompl::base::RealVectorIdentityProjectionEvaluator>(this));
  }
};

}  // namespace

std::shared_ptr<ompl::base::RealVectorStateSpace> makePositionSpace(const environment::Environment& environment) {
  auto space = std::make_shared<PositionStateSpace>();
  const Eigen::AlignedBox3d box = environment.grid().frame().bounds();
  ompl::base::RealVectorBounds bounds(3);
  for (int axis = 0; axis < 3; ++axis) {
    bounds.setLow(axis, box.min()[axis]);
    bounds.setHigh(axis, box.max()[axis]);
  }
  space->setBounds(bounds);
  return space;
}

FlightStateValidityChecker::FlightStateValidityChecker(const ompl::base::SpaceInformationPtr& si,
                                                       const SafetyRules& rules)
    : ompl::base::StateValidityChecker(si), rules_(rules) {}

bool FlightStateValidityChecker::isValid(const ompl::base::State* state) const {
  return rules_.isStateValid(toPosition(state));
}

FlightMotionValidator::FlightMotionValidator(const ompl::base::SpaceInformationPtr& si, const SafetyRules& rules)
    : ompl::base::MotionValidator(si), rules_(rules) {}

bool FlightMotionValidator::checkMotion(const ompl::base::State* from, const ompl::base::State* to) const {
  const bool valid = rules_.isMotionValid(toPosition(from), toPosition(to));
  if (valid)
    ++valid_;
  else
    ++invalid_;
  return valid;
}

bool FlightMotionValidator::checkMotion(const ompl::base::State* from, const ompl::base::State* to,
                                        std::pair<ompl::base::State*, double>& last_valid) const {
  const Eigen::Vector3d a = toPosition(from), b = toPosition(to);
  if (rules_.isMotionValid(a, b)) {
    ++valid_;
    return true;
  }
  ++invalid_;
  const double step_m = rules_.environment().denseStep_m();
  const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() / step_m)));
  int last = 0;
  for (int k = 1; k <= steps && rules_.isStateValid(a + (b - a) * (double(k) / steps)); ++k) last = k;
  last_valid.second = double(last) / steps;
  if (last_valid.first) setPosition(last_valid.first, a + (b - a) * last_valid.second);
  return false;
}

}  // namespace ceilplan::planner
