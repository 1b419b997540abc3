#pragma once
#include <Eigen/Geometry>

namespace unimap {

// One wheel-odometry reading: the body pose in the odometry frame.
struct OdometrySample {
  double time_s = 0.0;
  Eigen::Isometry3d T_odom_body = Eigen::Isometry3d::Identity();
};

}  // namespace unimap
