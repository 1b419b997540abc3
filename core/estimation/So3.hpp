#pragma once
// SO(3) helpers: skew matrix, exponential and logarithm maps on unit
// quaternions (Sola, "Quaternion kinematics for the error-state Kalman
// filter", eqs. 101 and 105).
#include <cmath>

#include <Eigen/Geometry>

namespace unimap::estimation {

// [v]x such that [v]x w = v x w.
inline Eigen::Matrix3d Skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

// Exp: rotation vector (rad) -> unit quaternion.
inline Eigen::Quaterniond ExpQ(const Eigen::Vector3d& theta) {
  const double angle = theta.norm();
  if (angle < 1e-12) {
    return Eigen::Quaterniond(1.0, 0.5 * theta.x(), 0.5 * theta.y(), 0.5 * theta.z()).normalized();
  }
  const Eigen::Vector3d axis = theta / angle;
  const double s = std::sin(0.5 * angle);
  return Eigen::Quaterniond(std::cos(0.5 * angle), s * axis.x(), s * axis.y(), s * axis.z());
}

// Log: unit quaternion -> rotation vector (rad), angle in [0, pi].
inline Eigen::Vector3d LogQ(const Eigen::Quaterniond& q_in) {
  Eigen::Quaterniond q = q_in.normalized();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  const Eigen::Vector3d v = q.vec();
  const double s = v.norm();
  if (s < 1e-12) return 2.0 * v;
  return 2.0 * std::atan2(s, q.w()) * v / s;
}

// Heading of a rotation: the angle of its x axis projected on the world x-y
// plane (the yaw of a yaw-pitch-roll decomposition).
inline double Heading(const Eigen::Matrix3d& R_world_body) {
  return std::atan2(R_world_body(1, 0), R_world_body(0, 0));
}

// A pose moved by an error e = [dp, dtheta]: (p + dp, R Exp(dtheta)), the
// ESKF's error convention (Sola eq. 283, with the local rotation error).
inline Eigen::Isometry3d ApplyPoseError(const Eigen::Isometry3d& T, const Eigen::Matrix<double, 6, 1>& e) {
  Eigen::Isometry3d out = T;
  out.translation() += e.head<3>();
  out.linear() = T.linear() * ExpQ(e.tail<3>()).toRotationMatrix();
  return out;
}

// The pose a fraction s of the way from a to b: position linearly
// interpolated, rotation slerped along the shorter arc.
inline Eigen::Isometry3d InterpolatePose(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, double s) {
  const Eigen::Quaterniond qa(a.linear());
  const Eigen::Quaterniond qb(b.linear());
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = (1.0 - s) * a.translation() + s * b.translation();
  T.linear() = qa.slerp(s, qb).normalized().toRotationMatrix();
  return T;
}

}  // namespace unimap::estimation
