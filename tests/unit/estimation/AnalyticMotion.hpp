#pragma once
// Analytic body motions with closed-form IMU readings, for filter tests.
#include <cmath>
#include <functional>

#include <Eigen/Geometry>

#include "estimation/So3.hpp"
#include "unimap/ImuSample.hpp"

namespace unimap::estimation::testing {

struct MotionSample {
  Eigen::Vector3d p, v, a;  // world frame
  Eigen::Matrix3d R;        // R_world_body
  Eigen::Vector3d w_body;   // angular velocity, body frame
};

using Motion = std::function<MotionSample(double)>;

inline constexpr double kGravity = 9.80665;

// Noise-free IMU reading: f = R^T (a - g), omega = w_body.
inline ImuSample PerfectImu(const Motion& motion, double t) {
  const MotionSample m = motion(t);
  ImuSample s;
  s.time_s = t;
  s.accel_m_s2 = m.R.transpose() * (m.a - Eigen::Vector3d(0, 0, -kGravity));
  s.gyro_rad_s = m.w_body;
  return s;
}

// Spinning in place about a fixed tilted axis.
inline MotionSample ConstantRotation(double t) {
  const Eigen::Vector3d w(0.3, -0.2, 0.5);
  return {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), ExpQ(w * t).toRotationMatrix(), w};
}

// A 5 m circle at 0.4 rad/s, heading along the tangent.
inline MotionSample Circle(double t) {
  const double r = 5.0, W = 0.4;
  MotionSample m;
  m.p = Eigen::Vector3d(r * std::cos(W * t), r * std::sin(W * t), 1.0);
  m.v = Eigen::Vector3d(-r * W * std::sin(W * t), r * W * std::cos(W * t), 0.0);
  m.a = Eigen::Vector3d(-r * W * W * std::cos(W * t), -r * W * W * std::sin(W * t), 0.0);
  m.R = Eigen::AngleAxisd(W * t + M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  m.w_body = Eigen::Vector3d(0, 0, W);
  return m;
}

// A 3D figure-eight while rocking about a fixed axis: theta(t) = 0.5 sin(0.7 t).
inline MotionSample FigureEight(double t) {
  const double W = 0.5;
  MotionSample m;
  m.p = Eigen::Vector3d(4 * std::sin(W * t), 2 * std::sin(2 * W * t), 0.5 * std::sin(W * t));
  m.v = Eigen::Vector3d(4 * W * std::cos(W * t), 4 * W * std::cos(2 * W * t), 0.5 * W * std::cos(W * t));
  m.a = Eigen::Vector3d(-4 * W * W * std::sin(W * t), -8 * W * W * std::sin(2 * W * t), -0.5 * W * W * std::sin(W * t));
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, 3).normalized();
  m.R = Eigen::AngleAxisd(0.5 * std::sin(0.7 * t), axis).toRotationMatrix();
  m.w_body = axis * 0.5 * 0.7 * std::cos(0.7 * t);
  return m;
}

}  // namespace unimap::estimation::testing
