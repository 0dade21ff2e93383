#pragma once
// Checks a trajectory against its limits by finite differences of the positions alone, as an
// independent observer would: speed, climb and descent from first differences, acceleration from
// second, jerk from third, yaw rate from the unwrapped yaw. The divided differences of a motion
// with continuous acceleration and bounded jerk are weighted means of the derivative, so none
// may exceed its limit.

#include "ceilplan/mission/trajectory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace ceilplan::testing {

struct FiniteDifferenceMaxima {
  double speed_m_s = 0.0;
  double climb_m_s = 0.0;    // largest upward rate
  double descent_m_s = 0.0;  // largest downward rate
  double acceleration_m_s2 = 0.0;
  double jerk_m_s3 = 0.0;
  double yaw_rate_deg_s = 0.0;
};

inline FiniteDifferenceMaxima finiteDifferenceMaxima(const std::vector<mission::TrajectorySetpoint>& points,
                                                     double rate_hz) {
  constexpr double kPi = 3.14159265358979323846;
  FiniteDifferenceMaxima m;
  const double dt = 1.0 / rate_hz;
  std::vector<Eigen::Vector3d> p;
  for (const auto& s : points) p.push_back(s.position_m);
  for (std::size_t k = 1; k < p.size(); ++k) {
    const Eigen::Vector3d v = (p[k] - p[k - 1]) / dt;
    m.speed_m_s = std::max(m.speed_m_s, v.norm());
    m.climb_m_s = std::max(m.climb_m_s, v.z());
    m.descent_m_s = std::max(m.descent_m_s, -v.z());
    const double yaw_step = std::remainder(points[k].yaw_rad - points[k - 1].yaw_rad, 2.0 * kPi);
    m.yaw_rate_deg_s = std::max(m.yaw_rate_deg_s, std::abs(yaw_step) / dt * 180.0 / kPi);
  }
  for (std::size_t k = 2; k < p.size(); ++k)
    m.acceleration_m_s2 = std::max(m.acceleration_m_s2, ((p[k] - 2.0 * p[k - 1] + p[k - 2]) / (dt * dt)).norm());
  for (std::size_t k = 3; k < p.size(); ++k)
    m.jerk_m_s3 = std::max(m.jerk_m_s3, ((p[k] - 3.0 * p[k - 1] + 3.0 * p[k - 2] - p[k - 3]) / (dt * dt * dt)).norm());
  return m;
}

// Every limit met, with `slack` (relative) for rounding; `max_speed_m_s` is the fastest the
// route allows anywhere.
inline void expectWithinLimits(const mission::Trajectory& trajectory, double max_speed_m_s, double slack = 1e-6) {
  const FiniteDifferenceMaxima m = finiteDifferenceMaxima(trajectory.setpoints, trajectory.rate_hz);
  const mission::TrajectoryLimits& l = trajectory.limits;
  EXPECT_LE(m.speed_m_s, max_speed_m_s * (1 + slack));
  EXPECT_LE(m.climb_m_s, l.climb_m_s * (1 + slack));
  EXPECT_LE(m.descent_m_s, l.descent_m_s * (1 + slack));
  EXPECT_LE(m.acceleration_m_s2, l.max_acceleration_m_s2 * (1 + slack));
  EXPECT_LE(m.jerk_m_s3, l.max_jerk_m_s3 * (1 + slack));
  EXPECT_LE(m.yaw_rate_deg_s, l.max_yaw_rate_deg_s * (1 + slack));
}

// Distance from a point to a polyline.
inline double distanceToPolyline(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& line) {
  double best = (p - line.front()).norm();
  for (std::size_t k = 0; k + 1 < line.size(); ++k) {
    const Eigen::Vector3d d = line[k + 1] - line[k];
    const double u = std::clamp(d.squaredNorm() > 0 ? (p - line[k]).dot(d) / d.squaredNorm() : 0.0, 0.0, 1.0);
    best = std::min(best, (p - (line[k] + u * d)).norm());
  }
  return best;
}

}  // namespace ceilplan::testing
