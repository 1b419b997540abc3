#pragma once
#include <Eigen/Geometry>

namespace unimap::sim {

// Kinematic state of the body at one time, world frame z up.
struct KinematicState {
  double time_s = 0.0;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();         // p_world_body
  Eigen::Vector3d velocity_m_s = Eigen::Vector3d::Zero();       // world frame
  Eigen::Vector3d acceleration_m_s2 = Eigen::Vector3d::Zero();  // world frame
  Eigen::Quaterniond q_world_body = Eigen::Quaterniond::Identity();
  Eigen::Vector3d angular_velocity_body_rad_s = Eigen::Vector3d::Zero();  // omega in the body frame
};

// A smooth body trajectory (continuous velocity and acceleration) with
// analytic derivatives, so simulated IMU readings agree with the poses.
class Trajectory {
 public:
  virtual ~Trajectory() = default;
  virtual double start_time_s() const = 0;
  virtual double end_time_s() const = 0;
  // State at time_s in [start_time_s, end_time_s].
  virtual KinematicState At(double time_s) const = 0;
};

}  // namespace unimap::sim
