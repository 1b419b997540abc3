#pragma once
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "estimation/NavState.hpp"
#include "unimap/ImuSample.hpp"

namespace unimap::estimation {

// Outcome of aligning with gravity from a static period.
struct StaticAlignment {
  bool ok = false;                 // false: not static enough or too few samples (see reason)
  std::string reason;              // why not ok
  Eigen::Quaterniond q_world_body = Eigen::Quaterniond::Identity();  // roll, pitch from gravity; yaw given
  Eigen::Vector3d gyro_bias_rad_s = Eigen::Vector3d::Zero();           // mean angular rate
  double gravity_m_s2 = 0.0;       // measured specific-force magnitude
  Eigen::Vector3d mean_specific_force_m_s2 = Eigen::Vector3d::Zero();  // mean accelerometer reading (body)
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

// Places *state (time and gyro bias already set) at a given T_world_body
// after a static start. Position always comes from the pose. With
// pose_attitude the attitude does too, and the mean specific force then
// gives the accelerometer bias b_a = f - R^T (0, 0, g), unless its norm
// exceeds max_accel_bias_m_s2 (the pose's tilt is then taken to be wrong:
// *note says so). Otherwise, or after that fallback, roll and pitch come
// from gravity and the heading from the pose. Without a valid alignment
// the pose's attitude is used as is.
void PlaceAtPose(const StaticAlignment& alignment, const Eigen::Isometry3d& T_world_body, bool pose_attitude,
                 double gravity_m_s2, double max_accel_bias_m_s2, NavState* state, std::string* note);

}  // namespace unimap::estimation
