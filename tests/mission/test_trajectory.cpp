// Trajectory time scaling: specifications on hand-made routes (no map). Limits are checked by
// finite differences of the positions, as an observer of the setpoints would.

#include "ceilplan/core/error.hpp"
#include "ceilplan/mission/trajectory.hpp"

#include "trajectory_checks.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ceilplan::mission {
namespace {

using testing::distanceToPolyline;
using testing::expectWithinLimits;

constexpr double kPi = 3.14159265358979323846;

// A lap in free space: out along x, a gentle bend, a climb, a right angle, a dwell, home.
SortieRoute lap() {
  SortieRoute route;
  route.home_m = {0, 0, 0.5};
  route.cruise_speed_m_s = 2.0;
  route.waypoints = {{{0, 0, 3}},   {{10, 0, 3}}, {{20, 2, 3}}, {{30, 2, 5}}, {{30, 12, 5}, 5.0, 90.0},
                     {{20, 12, 5}}, {{0, 0, 3}},  {{0, 0, 0.5}}};
  route.waypoints[2].speed_m_s = 3.0;
  return route;
}

std::vector<Eigen::Vector3d> polyline(const SortieRoute& route) {
  std::vector<Eigen::Vector3d> line{route.home_m};
  for (const RouteWaypoint& w : route.waypoints) line.push_back(w.position_m);
  return line;
}

TrajectoryOptions blendingEverywhere() {
  TrajectoryOptions options;
  options.path_is_safe = [](const std::vector<Eigen::Vector3d>&) { return true; };
  return options;
}

TEST(Trajectory, SamplesAtTheRateFromRestToRest) {
  const SortieRoute route = lap();
  const Trajectory t = timeScale(route, TrajectoryLimits{}, blendingEverywhere());
  ASSERT_GT(t.setpoints.size(), 100u);
  for (std::size_t k = 0; k < t.setpoints.size(); ++k) EXPECT_DOUBLE_EQ(t.setpoints[k].t_s, k / 20.0);
  EXPECT_LT((t.setpoints.front().position_m - route.home_m).norm(), 1e-12);
  EXPECT_LT((t.setpoints.back().position_m - route.waypoints.back().position_m).norm(), 1e-9);
  for (const auto* p : {&t.setpoints.front(), &t.setpoints.back()}) {
    EXPECT_LT(p->velocity_m_s.norm(), 1e-9);
    EXPECT_LT(p->acceleration_m_s2.norm(), 1e-9);
  }
}

TEST(Trajectory, StaysWithinEveryLimitByFiniteDifferences) {
  for (const TrajectoryLimits& limits :
       {TrajectoryLimits{}, TrajectoryLimits{0.5, 0.4, 1.0, 1.5, 20.0}, TrajectoryLimits{3.0, 2.0, 6.0, 30.0, 90.0}}) {
    for (const TrajectoryOptions& options : {TrajectoryOptions{}, blendingEverywhere()}) {
      const Trajectory t = timeScale(lap(), limits, options);
      expectWithinLimits(t, 3.0);
    }
  }
}

TEST(Trajectory, ReportedDerivativesAgreeWithThePositions) {
  const Trajectory t = timeScale(lap(), TrajectoryLimits{}, blendingEverywhere());
  const double dt = 1.0 / t.rate_hz;
  for (std::size_t k = 1; k + 1 < t.setpoints.size(); ++k) {
    const auto &a = t.setpoints[k - 1], &b = t.setpoints[k], &c = t.setpoints[k + 1];
    const Eigen::Vector3d velocity = (c.position_m - a.position_m) / (2 * dt);
    const Eigen::Vector3d acceleration = (c.position_m - 2 * b.position_m + a.position_m) / (dt * dt);
    // Central differences err by at most jerk * dt^2 / 6 (velocity) and jerk * dt / 3 (acceleration).
    EXPECT_LT((velocity - b.velocity_m_s).norm(), 4.0 * dt * dt / 6 + 1e-9) << "t " << b.t_s;
    EXPECT_LT((acceleration - b.acceleration_m_s2).norm(), 4.0 * dt / 3 + 1e-9) << "t " << b.t_s;
    const double yaw_rate = std::remainder(c.yaw_rad - a.yaw_rad, 2 * kPi) / (2 * dt);
    EXPECT_NEAR(yaw_rate, b.yaw_rate_rad_s, 0.01) << "t " << b.t_s;
  }
}

TEST(Trajectory, WithoutARecheckEveryPositionStaysOnThePolyline) {
  const SortieRoute route = lap();
  const Trajectory t = timeScale(route, TrajectoryLimits{}, TrajectoryOptions{});
  EXPECT_EQ(t.blended_corners, 0);
  EXPECT_EQ(t.stops, static_cast<int>(route.waypoints.size()));
  for (const auto& p : t.setpoints) EXPECT_LT(distanceToPolyline(p.position_m, polyline(route)), 1e-9);
  // A stop lands on a sample: every waypoint is visited exactly, at rest.
  for (const RouteWaypoint& w : route.waypoints) {
    bool visited = false;
    for (const auto& p : t.setpoints)
      visited = visited || ((p.position_m - w.position_m).norm() < 1e-9 && p.velocity_m_s.norm() < 1e-9);
    EXPECT_TRUE(visited) << w.position_m.transpose();
  }
}

TEST(Trajectory, BlendsGentleCornersWithinTheToleranceAndStopsAtSharpOnes) {
  const SortieRoute route = lap();
  TrajectoryOptions options = blendingEverywhere();
  options.corner_tolerance_m = 0.05;
  const Trajectory blended = timeScale(route, TrajectoryLimits{}, options);
  const Trajectory stopping = timeScale(route, TrajectoryLimits{}, TrajectoryOptions{});
  EXPECT_GT(blended.blended_corners, 0);
  EXPECT_LT(blended.duration_s(), stopping.duration_s());
  EXPECT_LE(blended.max_corner_deviation_m, 0.05 + 1e-12);
  double furthest = 0;
  for (const auto& p : blended.setpoints)
    furthest = std::max(furthest, distanceToPolyline(p.position_m, polyline(route)));
  EXPECT_LE(furthest, 0.05 + 1e-9);
  EXPECT_GT(furthest, 0.001);  // it did cut a corner
  // The right angle at (30, 2, 5) and the dwell at (30, 12, 5) are stops.
  for (const Eigen::Vector3d& corner : {Eigen::Vector3d(30, 2, 5), Eigen::Vector3d(30, 12, 5)}) {
    bool stopped = false;
    for (const auto& p : blended.setpoints)
      stopped = stopped || ((p.position_m - corner).norm() < 1e-9 && p.velocity_m_s.norm() < 1e-9);
    EXPECT_TRUE(stopped) << corner.transpose();
  }
}

TEST(Trajectory, ACornerTheRecheckRefusesBecomesAStop) {
  const SortieRoute route = lap();
  TrajectoryOptions options;
  int checks = 0;
  options.path_is_safe = [&](const std::vector<Eigen::Vector3d>& positions) {
    ++checks;
    // Refuse anything near (10, 0, 3).
    for (const auto& p : positions)
      if ((p - Eigen::Vector3d(10, 0, 3)).norm() < 1.0) return false;
    return true;
  };
  const Trajectory t = timeScale(route, TrajectoryLimits{}, options);
  EXPECT_GT(checks, 0);
  bool stopped = false;
  for (const auto& p : t.setpoints)
    stopped = stopped || ((p.position_m - Eigen::Vector3d(10, 0, 3)).norm() < 1e-9 && p.velocity_m_s.norm() < 1e-9);
  EXPECT_TRUE(stopped);
  EXPECT_GT(t.blended_corners, 0);  // the others still blend
}

TEST(Trajectory, HoldsAtDwellPointsForTheDwell) {
  const SortieRoute route = lap();
  const Trajectory t = timeScale(route, TrajectoryLimits{}, blendingEverywhere());
  double held = 0;
  for (std::size_t k = 1; k < t.setpoints.size(); ++k)
    if ((t.setpoints[k].position_m - Eigen::Vector3d(30, 12, 5)).norm() < 1e-9 &&
        (t.setpoints[k - 1].position_m - Eigen::Vector3d(30, 12, 5)).norm() < 1e-9)
      held += 1.0 / t.rate_hz;
  EXPECT_GE(held, 5.0 - 1e-9);
  EXPECT_LT(held, 5.0 + 3.0);  // plus the turn in place, if any
}

TEST(Trajectory, FacesEachHeadingOnArrivalWithinTheYawRate) {
  SortieRoute route = lap();
  route.waypoints[4].yaw_deg = 270.0;  // west, a half turn from the east-bound start
  TrajectoryLimits limits;
  limits.max_yaw_rate_deg_s = 10.0;  // slow enough to need a turn in place
  const Trajectory t = timeScale(route, limits, blendingEverywhere());
  expectWithinLimits(t, 3.0);
  // At rest at the dwell point the heading is west: ENU yaw pi.
  bool faced = false;
  for (const auto& p : t.setpoints)
    if ((p.position_m - Eigen::Vector3d(30, 12, 5)).norm() < 1e-9 && std::abs(p.yaw_rate_rad_s) < 1e-12)
      faced = faced || std::abs(std::remainder(p.yaw_rad - kPi, 2 * kPi)) < 1e-9;
  EXPECT_TRUE(faced);
  // The start faces the first horizontal motion: east, ENU yaw 0.
  EXPECT_NEAR(t.setpoints.front().yaw_rad, 0.0, 1e-12);
}

TEST(Trajectory, PhotosAtTheirWaypointsAndEveryTriggerDistance) {
  SortieRoute route = lap();
  route.waypoints[4].take_photo = true;
  route.waypoints[4].gimbal_pitch_deg = 90.0;
  const Trajectory one = timeScale(route, TrajectoryLimits{}, blendingEverywhere());
  ASSERT_EQ(one.photos, 1);
  for (const auto& p : one.setpoints)
    if (p.trigger) {
      EXPECT_LT((p.position_m - Eigen::Vector3d(30, 12, 5)).norm(), 1e-9);
      EXPECT_DOUBLE_EQ(p.gimbal_pitch_deg, 90.0);
    }
  EXPECT_DOUBLE_EQ(one.setpoints.front().gimbal_pitch_deg, 0.0);

  route.waypoints[4].take_photo = false;
  route.waypoints[0].trigger_distance_m = 2.0;  // from (0, 0, 3) ...
  route.waypoints[3].trigger_distance_m = 0.0;  // ... to (30, 2, 5): about 32 m
  const Trajectory passes = timeScale(route, TrajectoryLimits{}, blendingEverywhere());
  EXPECT_GE(passes.photos, 16);
  EXPECT_LE(passes.photos, 18);
  double flown = 0, last = -1;
  for (std::size_t k = 1; k < passes.setpoints.size(); ++k) {
    flown += (passes.setpoints[k].position_m - passes.setpoints[k - 1].position_m).norm();
    if (!passes.setpoints[k].trigger) continue;
    if (last >= 0) {
      EXPECT_NEAR(flown - last, 2.0, 0.2);
    }
    last = flown;
  }
}

TEST(Trajectory, RefusesBadInputNamingIt) {
  const auto refuses = [](const SortieRoute& route, const TrajectoryLimits& limits, const TrajectoryOptions& options,
                          const std::string& words) {
    try {
      timeScale(route, limits, options);
      ADD_FAILURE() << "expected an error about " << words;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  TrajectoryLimits limits;
  limits.max_jerk_m_s3 = 0;
  refuses(lap(), limits, {}, "max_jerk_m_s3");
  limits = {};
  limits.climb_m_s = std::nan("");
  refuses(lap(), limits, {}, "climb_m_s");
  TrajectoryOptions options;
  options.rate_hz = 0;
  refuses(lap(), {}, options, "rate_hz");
  options = {};
  options.stop_turn_deg = 120;
  refuses(lap(), {}, options, "stop_turn_deg");
  SortieRoute route = lap();
  route.waypoints[2].speed_m_s = -1;
  refuses(route, {}, {}, "waypoint 3: speed");
  route = lap();
  route.waypoints.clear();
  refuses(route, {}, {}, "no waypoints");
}

TEST(SortieRoute, HeadingsAndAims) {
  SortieRoute route = lap();
  EXPECT_DOUBLE_EQ(initialHeading_deg(route), 90.0);  // the first horizontal motion goes east
  route.waypoints[2].yaw_deg = -90.0;
  const std::vector<double> headings = headingsInEffect_deg(route);
  EXPECT_DOUBLE_EQ(headings[1], 90.0);
  EXPECT_DOUBLE_EQ(headings[2], 270.0);
  EXPECT_DOUBLE_EQ(headings[3], 270.0);  // kept until the next heading given
  EXPECT_DOUBLE_EQ(headings[4], 90.0);
  EXPECT_DOUBLE_EQ(headings.back(), 90.0);
  const CameraAim up = aimAt({0, 0, 5}, {0, 0, 6});
  EXPECT_FALSE(up.yaw_deg);
  EXPECT_DOUBLE_EQ(up.gimbal_pitch_deg, 90.0);
  const CameraAim north_east = aimAt({0, 0, 5}, {1, 1, 5});
  EXPECT_NEAR(*north_east.yaw_deg, 45.0, 1e-12);
  EXPECT_NEAR(north_east.gimbal_pitch_deg, 0.0, 1e-12);
  EXPECT_NEAR(enuYawFromHeading_rad(0.0), kPi / 2, 1e-12);
  EXPECT_NEAR(enuYawFromHeading_rad(270.0), kPi, 1e-12);
  EXPECT_NEAR(headingFromEnuYaw_deg(-kPi / 2), 180.0, 1e-12);
}

}  // namespace
}  // namespace ceilplan::mission
