#pragma once
/// @file
/// Positions as OMPL states: a 3-D real vector space over the map's bounds.

#include "ceilplan/environment/environment.hpp"

#include <ompl/base/State.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <Eigen/Core>

#include <memory>

namespace ceilplan::planner {

/// The position of an OMPL state of ceilplan's 3-D space.
inline Eigen::Vector3d toPosition(const ompl::base::State* state) {
  const double* values = state->as<ompl::base::RealVectorStateSpace::StateType>()->values;
  return {values[0], values[1], values[2]};
}

/// Sets the position of an OMPL state of ceilplan's 3-D space.
inline void setPosition(ompl::base::State* state, const Eigen::Vector3d& position_m) {
  double* values = state->as<ompl::base::RealVectorStateSpace::StateType>()->values;
  values[0] = position_m.x();
  values[1] = position_m.y();
  values[2] = position_m.z();
}

/// The space of body positions inside the map's known-voxel box.
std::shared_ptr<ompl::base::RealVectorStateSpace> makePositionSpace(const environment::Environment& environment);

}  // namespace ceilplan::planner
