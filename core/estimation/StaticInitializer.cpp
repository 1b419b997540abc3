#include "estimation/StaticInitializer.hpp"

#include <cmath>

#include "estimation/So3.hpp"

namespace unimap::estimation {

StaticAlignment AlignFromStatic(const std::vector<ImuSample>& samples, const StaticAlignmentOptions& options) {
  StaticAlignment out;
  if (static_cast<int>(samples.size()) < options.min_samples) {
    out.reason = "only " + std::to_string(samples.size()) + " IMU samples in the static window, need " +
                 std::to_string(options.min_samples);
    return out;
  }
  Eigen::Vector3d mean_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d mean_w = Eigen::Vector3d::Zero();
  for (const auto& s : samples) {
    mean_a += s.accel_m_s2;
    mean_w += s.gyro_rad_s;
  }
  const double n = static_cast<double>(samples.size());
  mean_a /= n;
  mean_w /= n;
  Eigen::Vector3d var_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d var_w = Eigen::Vector3d::Zero();
  for (const auto& s : samples) {
    var_a += (s.accel_m_s2 - mean_a).cwiseAbs2();
    var_w += (s.gyro_rad_s - mean_w).cwiseAbs2();
  }
  const Eigen::Vector3d std_a = (var_a / n).cwiseSqrt();
  const Eigen::Vector3d std_w = (var_w / n).cwiseSqrt();
  out.accel_std_m_s2 = std::sqrt(var_a.sum() / (3.0 * n));
  out.gyro_std_rad_s = std::sqrt(var_w.sum() / (3.0 * n));
  if (std_a.maxCoeff() > options.max_accel_std_m_s2 || std_w.maxCoeff() > options.max_gyro_std_rad_s) {
    out.reason = "IMU not static: accelerometer std " + std::to_string(std_a.maxCoeff()) + " m/s^2, gyroscope std " +
                 std::to_string(std_w.maxCoeff()) + " rad/s";
    return out;
  }
  // At rest f = R^T (0, 0, g): the body sees world up along f.
  const Eigen::Vector3d f = mean_a;
  const double roll = std::atan2(f.y(), f.z());
  const double pitch = std::atan2(-f.x(), std::sqrt(f.y() * f.y() + f.z() * f.z()));
  out.q_world_body = Eigen::AngleAxisd(options.yaw_rad, Eigen::Vector3d::UnitZ()) *
                     Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                     Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX());
  out.gyro_bias_rad_s = mean_w;
  out.gyro_bias_std_rad_s = std_w / std::sqrt(n);
  out.gravity_m_s2 = f.norm();
  out.mean_specific_force_m_s2 = f;
  out.ok = true;
  return out;
}

PoseStart PlaceAtPose(const StaticAlignment& alignment, const Eigen::Isometry3d& T_world_body,
                      InitialAttitude requested, double gravity_m_s2, double max_accel_bias_m_s2, NavState* state) {
  PoseStart out;
  state->p_world_body_m = T_world_body.translation();
  const Eigen::Matrix3d R_pose = T_world_body.linear();
  if (!alignment.ok) {
    state->q_world_body = Eigen::Quaterniond(R_pose);
    out.attitude = InitialAttitude::kPose;  // the caller reports the failed alignment
    return out;
  }
  if (requested == InitialAttitude::kPose) {
    const Eigen::Vector3d b_a =
        alignment.mean_specific_force_m_s2 - R_pose.transpose() * Eigen::Vector3d(0.0, 0.0, gravity_m_s2);
    if (b_a.norm() <= max_accel_bias_m_s2) {
      state->q_world_body = Eigen::Quaterniond(R_pose);
      state->accel_bias_m_s2 = b_a;
      out.attitude = InitialAttitude::kPose;
      return out;
    }
    out.fell_back = true;
    out.note = "its tilt disagrees with gravity (implied accelerometer bias " + std::to_string(b_a.norm()) +
               " m/s^2): roll and pitch from gravity instead";
  }
  // Heading of the pose's x axis, roll and pitch of the alignment (yaw-pitch-roll).
  const double turn = Heading(R_pose) - Heading(alignment.q_world_body.toRotationMatrix());
  state->q_world_body = Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()) * alignment.q_world_body;
  out.attitude = InitialAttitude::kGravity;
  return out;
}

}  // namespace unimap::estimation
