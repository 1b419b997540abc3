#include "WaypointTrajectory.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace unimap::sim {
namespace {

constexpr double kDeg = M_PI / 180.0;

// Moves of several lengths, turns, a climb, dwells and a wobble.
WaypointTrajectory TestTrajectory() {
  std::vector<Waypoint> w = {
      {Eigen::Vector3d(0, 0, 1), 0.0, 1.0},
      {Eigen::Vector3d(8, 0, 1), 90 * kDeg, 0.0},
      {Eigen::Vector3d(8, 0.5, 1.2), 90 * kDeg, 2.0},  // short: acceleration-limited
      {Eigen::Vector3d(8, 5, 2.5), 180 * kDeg, 0.0},
      {Eigen::Vector3d(8, 5, 2.5), 120 * kDeg, 1.5},  // turn in place: yaw-rate-limited
      {Eigen::Vector3d(0, 4, 1.0), 10 * kDeg, 0.0},
  };
  WaypointTrajectoryOptions o;
  o.max_speed_m_s = 1.13;
  o.max_acceleration_m_s2 = 0.6;
  o.max_yaw_rate_rad_s = 25 * kDeg;
  o.static_start_s = 2.0;
  o.wobble.roll_amplitude_rad = 2 * kDeg;
  o.wobble.pitch_amplitude_rad = 1.5 * kDeg;
  o.wobble.roll_period_s = 5.0;
  o.wobble.pitch_period_s = 7.0;
  o.wobble.ramp_s = 3.0;
  return WaypointTrajectory(w, o);
}

// Body angular velocity from the attitude alone: q(t-h)^-1 q(t+h) = exp(omega 2h).
Eigen::Vector3d NumericOmega(const Trajectory& traj, double t, double h) {
  const Eigen::AngleAxisd d(traj.At(t - h).q_world_body.conjugate() * traj.At(t + h).q_world_body);
  return d.axis() * d.angle() / (2 * h);
}

TEST(WaypointTrajectory, AnalyticDerivativesMatchNumericOnes) {
  const WaypointTrajectory traj = TestTrajectory();
  const double h = 1e-4;
  for (double t = h; t < traj.end_time_s() - h; t += 0.013) {
    const KinematicState s = traj.At(t);
    const KinematicState a = traj.At(t - h), b = traj.At(t + h);
    EXPECT_LT((s.velocity_m_s - (b.position_m - a.position_m) / (2 * h)).norm(), 1e-7) << t;
    EXPECT_LT((s.acceleration_m_s2 - (b.velocity_m_s - a.velocity_m_s) / (2 * h)).norm(), 1e-6) << t;
    EXPECT_LT((s.angular_velocity_body_rad_s - NumericOmega(traj, t, h)).norm(), 1e-7) << t;
  }
}

TEST(WaypointTrajectory, VelocityAndAccelerationContinuousAtJoinsAndDwells) {
  const WaypointTrajectory traj = TestTrajectory();
  // Every phase boundary: arrivals and the ends of dwells.
  std::vector<double> joins;
  for (std::size_t i = 0; i < traj.waypoints().size(); ++i) {
    joins.push_back(traj.ArrivalTime(i));
    joins.push_back(traj.ArrivalTime(i) + traj.waypoints()[i].dwell_s);
  }
  const double eps = 1e-7;
  for (double t : joins) {
    if (t <= eps || t >= traj.end_time_s() - eps) continue;
    const KinematicState a = traj.At(t - eps), b = traj.At(t + eps);
    // Rest-to-rest pieces: velocity and acceleration are ~0 on both sides.
    EXPECT_LT(a.velocity_m_s.norm(), 1e-9) << t;
    EXPECT_LT(b.velocity_m_s.norm(), 1e-9) << t;
    EXPECT_LT((a.acceleration_m_s2 - b.acceleration_m_s2).norm(), 1e-5) << t;
    EXPECT_LT((a.angular_velocity_body_rad_s - b.angular_velocity_body_rad_s).norm(), 1e-6) << t;
  }
}

TEST(WaypointTrajectory, LimitsAreRespectedAndReached) {
  const WaypointTrajectory traj = TestTrajectory();
  const auto& o = traj.options();
  double max_speed = 0.0, max_accel = 0.0;
  for (double t = 0.0; t <= traj.end_time_s(); t += 0.002) {
    const KinematicState s = traj.At(t);
    max_speed = std::max(max_speed, s.velocity_m_s.norm());
    max_accel = std::max(max_accel, s.acceleration_m_s2.norm());
  }
  EXPECT_LE(max_speed, o.max_speed_m_s * (1 + 1e-12));
  EXPECT_GT(max_speed, 0.999 * o.max_speed_m_s);  // the 8 m leg is speed-limited
  EXPECT_LE(max_accel, o.max_acceleration_m_s2 * (1 + 1e-9));
  EXPECT_NEAR(traj.MaxSpeed(traj.end_time_s()), max_speed, 1e-6);
}

TEST(WaypointTrajectory, StaticStartIsLevelAndAtRest) {
  const WaypointTrajectory traj = TestTrajectory();
  for (double t = 0.0; t <= 2.0; t += 0.05) {
    const KinematicState s = traj.At(t);
    EXPECT_EQ(s.position_m, Eigen::Vector3d(0, 0, 1));
    EXPECT_EQ(s.velocity_m_s, Eigen::Vector3d::Zero());
    EXPECT_EQ(s.angular_velocity_body_rad_s, Eigen::Vector3d::Zero());
    EXPECT_NEAR(s.q_world_body.angularDistance(Eigen::Quaterniond::Identity()), 0.0, 1e-15);
  }
}

TEST(WaypointTrajectory, PassesWaypointsWithTheirYawAndPathLength) {
  const WaypointTrajectory traj = TestTrajectory();
  double length = 0.0;
  for (std::size_t i = 0; i < traj.waypoints().size(); ++i) {
    const Waypoint& w = traj.waypoints()[i];
    if (i > 0) length += (w.position_m - traj.waypoints()[i - 1].position_m).norm();
    const KinematicState s = traj.At(traj.ArrivalTime(i));
    EXPECT_LT((s.position_m - w.position_m).norm(), 1e-12) << i;
    const Eigen::Vector3d x_world = s.q_world_body * Eigen::Vector3d::UnitX();
    // Heading of the body x axis (the wobble tilts it by at most ~2 deg).
    EXPECT_NEAR(std::remainder(std::atan2(x_world.y(), x_world.x()) - w.yaw_rad, 2 * M_PI), 0.0, 1e-3) << i;
    EXPECT_NEAR(traj.PathLength(traj.ArrivalTime(i)), length, 1e-9) << i;
  }
  EXPECT_NEAR(traj.PathLength(traj.end_time_s()), length, 1e-9);
  // Path length grows like the integral of speed (trapezoid rule over 0..12 s).
  double integral = 0.0;
  const int steps = 12000;
  const double dt = 12.0 / steps;
  for (int i = 0; i < steps; ++i) {
    integral += 0.5 * dt * (traj.At(i * dt).velocity_m_s.norm() + traj.At((i + 1) * dt).velocity_m_s.norm());
  }
  EXPECT_NEAR(traj.PathLength(12.0), integral, 1e-5);
}

TEST(WaypointTrajectory, RejectsBadInput) {
  WaypointTrajectoryOptions o;
  EXPECT_THROW(WaypointTrajectory({}, o), std::invalid_argument);
  EXPECT_THROW(WaypointTrajectory({{Eigen::Vector3d::Zero(), 0.0, -1.0}}, o), std::invalid_argument);
  EXPECT_THROW(WaypointTrajectory({{Eigen::Vector3d(NAN, 0, 0), 0.0, 0.0}}, o), std::invalid_argument);
  o.max_speed_m_s = 0.0;
  EXPECT_THROW(WaypointTrajectory({{Eigen::Vector3d::Zero(), 0.0, 1.0}}, o), std::invalid_argument);
}

}  // namespace
}  // namespace unimap::sim
