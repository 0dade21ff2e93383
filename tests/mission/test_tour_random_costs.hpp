#pragma once
// Random tour cost matrices for tests and benchmarks: targets scattered in a 50 x 20 x 6 m box
// (index 0 home); a leg costs its length plus `climb_penalty` per metre climbed, so the matrix is
// asymmetric whenever the penalty is not zero.

#include "ceilplan/mission/tour_order.hpp"

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace ceilplan::testing {

inline mission::CostMatrix randomTourCosts(int targets, std::uint64_t seed, double climb_penalty) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> x(0, 50), y(-10, 10), z(0, 6);
  std::vector<Eigen::Vector3d> points(targets + 1);
  for (auto& p : points) p = {x(random), y(random), z(random)};
  mission::CostMatrix costs(targets + 1, targets + 1);
  for (int i = 0; i <= targets; ++i)
    for (int j = 0; j <= targets; ++j)
      costs(i, j) = (points[j] - points[i]).norm() + climb_penalty * std::max(0.0, points[j].z() - points[i].z());
  return costs;
}

}  // namespace ceilplan::testing
