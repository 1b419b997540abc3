#pragma once
#include <Eigen/Core>

namespace unimap {

// One IMU reading in the body frame (the body frame is the IMU frame).
struct ImuSample {
  double time_s = 0.0;
  Eigen::Vector3d accel_m_s2 = Eigen::Vector3d::Zero();  // specific force
  Eigen::Vector3d gyro_rad_s = Eigen::Vector3d::Zero();  // angular rate
};

}  // namespace unimap
