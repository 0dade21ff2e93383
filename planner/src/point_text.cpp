#include "ceilplan/planner/point_text.hpp"

#include <cstdio>

namespace ceilplan::planner {

std::string pointText(const Eigen::Vector3d& point_m) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.2f, %.2f, %.2f)", point_m.x(), point_m.y(), point_m.z());
  return text;
}

}  // namespace ceilplan::planner
