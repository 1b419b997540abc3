#pragma once
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "unimap/ImuSample.hpp"

namespace unimap::estimation {

// Outcome of aligning with gravity from a static period.
struct StaticAlignment {
  bool ok = false;                 // false: not static enough or too few samples (see reason)
  std::string reason;              // why not ok
  Eigen::Quaterniond q_world_body = Eigen::Quaterniond::Identity();  // roll, pitch from gravity; yaw given
  Eigen::Vector3d gyro_bias_rad_s = Eigen::Vector3d::Zero();           // mean angular rate
  double gravity_m_s2 = 0.0;       // measured specific-force magnitude
};

// Thresholds for accepting an IMU window as static.
struct StaticAlignmentOptions {
  int min_samples = 100;                  // at least this many samples (0.5 s at 200 Hz)
  double max_accel_std_m_s2 = 0.2;        // accelerometer standard deviation per axis
  double max_gyro_std_rad_s = 0.05;       // gyroscope standard deviation per axis
  double yaw_rad = 0.0;                   // heading to assume (not observable from gravity)
};

// Roll and pitch from the mean specific force f = R^T (0, 0, g) and the gyro
// bias from the mean angular rate, over samples of a body at rest.
StaticAlignment AlignFromStatic(const std::vector<ImuSample>& samples,
                                const StaticAlignmentOptions& options);

}  // namespace unimap::estimation
