#include "ceilplan/mission/coverage_passes.hpp"

#include "ceilplan/mission/tour_order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

namespace ceilplan::mission {
namespace {

constexpr double kDegree = M_PI / 180.0;
constexpr double kSteepPitchDeg = 60.0;
constexpr int kGenericRestarts = 20;
constexpr std::size_t kGenericRestartLimit = 200;      // beyond, local search from nearest neighbour only
constexpr std::size_t kGenericLocalSearchLimit = 250;  // beyond, the nearest-neighbour tour alone

Eigen::Vector3d headingVector(double yaw_deg) {
  return {std::sin(yaw_deg * kDegree), std::cos(yaw_deg * kDegree), 0.0};
}

// A family of views flown in lanes: `along` runs along each lane, `lane` orders the lanes.
struct Family {
  Eigen::Vector3d along;
  Eigen::Vector3d lane;
  std::vector<std::uint32_t> views;
};

double closedRoute(const std::vector<Eigen::Vector3d>& points, const std::vector<std::uint32_t>& order) {
  double length = 0.0;
  for (std::size_t k = 0; k < order.size(); ++k)
    length += (points[order[(k + 1) % order.size()]] - points[order[k]]).norm();
  return length;
}

}  // namespace

PassPlan orderIntoPasses(const std::vector<CameraPose>& poses, const std::vector<Eigen::Vector3d>& camera_m,
                         double heading_deg, double lane_width_m, const std::vector<std::uint8_t>& in_lanes) {
  PassPlan plan;
  if (poses.empty()) return plan;
  const Eigen::Vector3d heading = headingVector(heading_deg);
  const Eigen::Vector3d across(heading.y(), -heading.x(), 0.0);
  // Family 0: views up or down; 1-4: sideways views by the quarter of the compass they face
  // (relative to the heading).
  std::map<int, Family> families;
  std::vector<std::uint32_t> others;
  for (std::uint32_t v = 0; v < poses.size(); ++v) {
    if (!in_lanes.empty() && !in_lanes[v]) {
      others.push_back(v);
      continue;
    }
    int key = 0;
    Family family{heading, across, {}};
    if (std::abs(poses[v].gimbal_pitch_deg) < kSteepPitchDeg) {
      const int quarter = static_cast<int>(std::lround((poses[v].yaw_deg - heading_deg) / 90.0)) & 3;
      key = 1 + quarter;
      const Eigen::Vector3d facing = headingVector(heading_deg + 90.0 * quarter);
      family = {Eigen::Vector3d(facing.y(), -facing.x(), 0.0), Eigen::Vector3d::UnitZ(), {}};
    }
    families.emplace(key, family).first->second.views.push_back(v);
  }

  std::vector<std::uint32_t> order;
  for (auto& [key, family] : families) {
    std::vector<std::uint32_t>& views = family.views;
    // Lanes at a fixed pitch from the lowest lane coordinate; each view joins the nearest.
    double lowest = std::numeric_limits<double>::infinity();
    for (const std::uint32_t v : views) lowest = std::min(lowest, camera_m[v].dot(family.lane));
    std::map<long, std::vector<std::uint32_t>> lanes;
    for (const std::uint32_t v : views)
      lanes[std::lround((camera_m[v].dot(family.lane) - lowest) / lane_width_m)].push_back(v);
    bool forward = true;
    for (auto& [lane, members] : lanes) {
      ViewPass pass;
      pass.views = std::move(members);
      // C++17 lambdas cannot capture a structured binding (clang refuses): capture the direction.
      const Eigen::Vector3d along = family.along;
      std::stable_sort(pass.views.begin(), pass.views.end(), [&](std::uint32_t a, std::uint32_t b) {
        return forward ? camera_m[a].dot(along) < camera_m[b].dot(along)
                       : camera_m[a].dot(along) > camera_m[b].dot(along);
      });
      pass.direction = forward ? family.along : Eigen::Vector3d(-family.along);
      for (std::size_t k = 1; k < pass.views.size(); ++k)
        pass.length_m += (camera_m[pass.views[k]] - camera_m[pass.views[k - 1]]).norm();
      order.insert(order.end(), pass.views.begin(), pass.views.end());
      plan.passes.push_back(std::move(pass));
      forward = !forward;
    }
  }
  // The other views, each where it lengthens the open route through the passes least.
  std::vector<std::size_t> pass_of;
  for (std::size_t p = 0; p < plan.passes.size(); ++p) pass_of.insert(pass_of.end(), plan.passes[p].views.size(), p);
  for (const std::uint32_t v : others) {
    std::size_t best = order.size();  // insert before order[best]; order.size(): at the end
    double best_cost = order.empty() ? 0.0 : (camera_m[v] - camera_m[order.back()]).norm();
    if (!order.empty() && (camera_m[v] - camera_m[order.front()]).norm() < best_cost) {
      best = 0;
      best_cost = (camera_m[v] - camera_m[order.front()]).norm();
    }
    for (std::size_t k = 1; k < order.size(); ++k) {
      const double cost = (camera_m[v] - camera_m[order[k - 1]]).norm() + (camera_m[v] - camera_m[order[k]]).norm() -
                          (camera_m[order[k]] - camera_m[order[k - 1]]).norm();
      if (cost < best_cost) {
        best_cost = cost;
        best = k;
      }
    }
    if (plan.passes.empty()) plan.passes.emplace_back();
    const std::size_t pass = best == 0 ? 0 : pass_of[best - 1];
    order.insert(order.begin() + static_cast<std::ptrdiff_t>(best), v);
    pass_of.insert(pass_of.begin() + static_cast<std::ptrdiff_t>(best), pass);
  }
  for (ViewPass& pass : plan.passes) pass.views.clear();
  for (std::size_t k = 0; k < order.size(); ++k) plan.passes[pass_of[k]].views.push_back(order[k]);
  for (ViewPass& pass : plan.passes) {
    pass.length_m = 0.0;
    for (std::size_t k = 1; k < pass.views.size(); ++k)
      pass.length_m += (camera_m[pass.views[k]] - camera_m[pass.views[k - 1]]).norm();
  }
  plan.route_m = closedRoute(camera_m, order);

  if (order.size() < 3) {
    plan.generic_route_m = plan.route_m;
    plan.generic_method = "all orders";
  } else if (order.size() <= kGenericLocalSearchLimit) {
    CostMatrix costs(order.size(), order.size());
    for (std::size_t i = 0; i < order.size(); ++i)
      for (std::size_t j = 0; j < order.size(); ++j) costs(i, j) = (camera_m[order[i]] - camera_m[order[j]]).norm();
    const int restarts = order.size() > kGenericRestartLimit ? 0 : kGenericRestarts;
    plan.generic_route_m = heuristicTour(costs, 1, restarts).cost;
    plan.generic_method = "nearest neighbour, 2-opt and Or-opt, " + std::to_string(restarts) + " restarts";
  } else {
    std::vector<std::uint8_t> visited(camera_m.size(), 0);
    std::uint32_t at = order.front();
    visited[at] = 1;
    for (std::size_t step = 1; step < order.size(); ++step) {
      std::uint32_t next = at;
      double nearest = INFINITY;
      for (const std::uint32_t v : order)
        if (!visited[v] && (camera_m[v] - camera_m[at]).norm() < nearest) {
          nearest = (camera_m[v] - camera_m[at]).norm();
          next = v;
        }
      plan.generic_route_m += nearest;
      visited[next] = 1;
      at = next;
    }
    plan.generic_route_m += (camera_m[order.front()] - camera_m[at]).norm();
    plan.generic_method = "nearest neighbour";
  }
  plan.passes_win = plan.route_m <= plan.generic_route_m;
  return plan;
}

}  // namespace ceilplan::mission
