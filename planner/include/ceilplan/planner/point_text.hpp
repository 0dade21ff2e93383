#pragma once
// A position as the planner's and the tour's messages print it.

#include <Eigen/Core>

#include <string>

namespace ceilplan::planner {

// "(x, y, z)" in metres, to the centimetre.
std::string pointText(const Eigen::Vector3d& point_m);

}  // namespace ceilplan::planner
