#pragma once
#include <Eigen/Geometry>

namespace unimap::estimation {

// Nominal state of the ESKF: the body (IMU) frame in the world frame (z up).
struct NavState {
  double time_s = 0.0;
  Eigen::Vector3d p_world_body_m = Eigen::Vector3d::Zero();  // position
  Eigen::Vector3d v_world_m_s = Eigen::Vector3d::Zero();     // velocity, world frame
  Eigen::Quaterniond q_world_body = Eigen::Quaterniond::Identity();
  Eigen::Vector3d accel_bias_m_s2 = Eigen::Vector3d::Zero();  // b_a
  Eigen::Vector3d gyro_bias_rad_s = Eigen::Vector3d::Zero();  // b_g

  Eigen::Isometry3d T_world_body() const {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = q_world_body.toRotationMatrix();
    T.translation() = p_world_body_m;
    return T;
  }
};

// Error-state layout: [dp, dv, dtheta, db_a, db_g], q_true = q * Exp(dtheta).
namespace error_index {
inline constexpr int kP = 0;
inline constexpr int kV = 3;
inline constexpr int kTheta = 6;
inline constexpr int kBa = 9;
inline constexpr int kBg = 12;
inline constexpr int kSize = 15;
}  // namespace error_index

}  // namespace unimap::estimation
