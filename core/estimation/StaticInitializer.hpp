#pragma once
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "estimation/NavState.hpp"
#include "unimap/ImuSample.hpp"

namespace unimap::estimation {

// Outcome of aligning with gravity from a static period.
struct StaticAlignment {
  bool ok = false;     // false: not static enough or too few samples (see reason)
  std::string reason;  // why not ok
  Eigen::Quaterniond q_world_body = Eigen::Quaterniond::Identity();    // roll, pitch from gravity; yaw given
  Eigen::Vector3d gyro_bias_rad_s = Eigen::Vector3d::Zero();           // mean angular rate
  Eigen::Vector3d gyro_bias_std_rad_s = Eigen::Vector3d::Zero();       // its standard error (std / sqrt(samples))
  double gravity_m_s2 = 0.0;                                           // measured specific-force magnitude
  Eigen::Vector3d mean_specific_force_m_s2 = Eigen::Vector3d::Zero();  // mean accelerometer reading (body)
  double accel_std_m_s2 = 0.0;  // accelerometer scatter at rest: the root mean of the axes' variances
  double gyro_std_rad_s = 0.0;  // gyroscope scatter at rest, the same (white noise per sample)
};

// Thresholds for accepting an IMU window as static.
struct StaticAlignmentOptions {
  int min_samples = 100;             // at least this many samples (0.5 s at 200 Hz)
  double max_accel_std_m_s2 = 0.2;   // accelerometer standard deviation per axis
  double max_gyro_std_rad_s = 0.05;  // gyroscope standard deviation per axis
  double yaw_rad = 0.0;              // heading to assume (not observable from gravity)
};

// Roll and pitch from the mean specific force f = R^T (0, 0, g) and the gyro
// bias from the mean angular rate, over samples of a body at rest.
StaticAlignment AlignFromStatic(const std::vector<ImuSample>& samples, const StaticAlignmentOptions& options);

// Where the initial attitude comes from when an initial pose is given.
enum class InitialAttitude {
  kGravity,  // roll and pitch from the static start's gravity, heading from the pose
  kPose,     // the pose's attitude; the static start's mean specific force then gives the
             // accelerometer bias (b_a = f - R^T g), which gravity alignment cannot tell from tilt
};

// What PlaceAtPose did.
struct PoseStart {
  InitialAttitude attitude = InitialAttitude::kGravity;  // the source actually used
  bool fell_back = false;  // kPose was asked for but the pose's tilt disagreed with gravity
  std::string note;        // why it fell back (set only when fell_back)
};

// Places *state (time and gyro bias already set) at a given T_world_body
// after a static start. Position always comes from the pose. kPose takes the
// pose's attitude and the accelerometer bias b_a = f - R^T (0, 0, g), unless
// its norm exceeds max_accel_bias_m_s2: the pose's tilt is then taken to be
// wrong and it falls back to kGravity (roll and pitch from gravity, heading
// from the pose). Without a valid alignment the pose's attitude is used as
// is (attitude kPose, no bias).
PoseStart PlaceAtPose(const StaticAlignment& alignment, const Eigen::Isometry3d& T_world_body,
                      InitialAttitude requested, double gravity_m_s2, double max_accel_bias_m_s2, NavState* state);

}  // namespace unimap::estimation
