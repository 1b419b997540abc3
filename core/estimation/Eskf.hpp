#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "estimation/EskfOptions.hpp"
#include "estimation/NavState.hpp"
#include "unimap/ImuSample.hpp"

namespace unimap::estimation {

// 15x15 error-state covariance and 6-D pose blocks.
using ErrorCovariance = Eigen::Matrix<double, 15, 15>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

// The covariance Eskf::Initialize(state) starts from: the options' initial
// sigmas, uncorrelated.
ErrorCovariance InitialCovariance(const EskfOptions& options);

// Outcome of one pose update.
struct PoseUpdateResult {
  bool applied = false;                          // false: the innovation covariance was not positive definite
  Vector6d error_correction = Vector6d::Zero();  // [dp, dtheta] injected into the nominal state
  double mahalanobis_sq = 0.0;                   // innovation' S^-1 innovation
  Matrix6d pose_covariance_before_reset = Matrix6d::Zero();  // posterior [dp, dtheta] covariance
};

// Error-state Kalman filter driven by the IMU (Sola 2017, section 5):
// nominal p, v, q, b_a, b_g; 15-D error state [dp, dv, dtheta, db_a, db_g]
// with q_true = q * Exp(dtheta) (local attitude error).
class Eskf {
 public:
  explicit Eskf(EskfOptions options);

  // Sets the nominal state and a covariance from the options' initial sigmas.
  void Initialize(const NavState& state);
  // Sets the nominal state and covariance explicitly.
  void Initialize(const NavState& state, const ErrorCovariance& covariance);
  bool initialized() const { return initialized_; }

  // Integrates from the previous IMU sample to `sample` (trapezoidal in the
  // world-frame acceleration, midpoint angular rate); the first call after
  // Initialize only records the sample. Returns false (state untouched) for
  // a sample not after the last one or a gap above max_imu_gap_s.
  bool Propagate(const ImuSample& sample);
  // Predicts with the last IMU sample held up to time_s (>= state time).
  void PropagateTo(double time_s);
  // Bridges a gap in the IMU stream: holds the last sample up to
  // sample.time_s, then continues from `sample`. For samples Propagate refused
  // as a gap; the covariance grows over the gap.
  void RestartImu(const ImuSample& sample);

  // Prediction without an IMU (a MotionPrior): moves the nominal pose by the
  // body-frame increment T_prev_next (p += R dp, q = q dq), sets the time and
  // the velocity to the increment's mean, and propagates the covariance with
  // F (dp' = dp - R [dp_inc]x dtheta, dtheta' = dR^T dtheta) plus the
  // increment's covariance (position block rotated into the world frame).
  void PredictPose(double time_s, const Eigen::Isometry3d& T_prev_next, const Matrix6d& covariance);

  // Pose update in error coordinates relative to the current nominal state:
  // z = [dp, dtheta] measured, R its covariance (linear update, Joseph form).
  PoseUpdateResult UpdatePoseError(const Vector6d& z, const Matrix6d& R);
  // Pose update from an absolute pose T_world_body with covariance R on
  // [dp, dtheta] (dtheta local): z = [p_z - p, Log(q^-1 q_z)].
  PoseUpdateResult UpdatePose(const Eigen::Isometry3d& T_world_body_measured, const Matrix6d& R);

  // Scales the position, velocity and attitude uncertainty (and their
  // correlations) by factor >= 1, biases unchanged: the prediction proved
  // worse than the filter believed (pipeline::Reacquirer), so the next
  // update may move the state as far as the evidence says.
  void InflateMotionCovariance(double factor);
  // Replaces the IMU's white noise (options().sigma_accel_m_s2 and
  // sigma_gyro_rad_s; both > 0) for the predictions from now on.
  void SetImuNoise(double sigma_accel_m_s2, double sigma_gyro_rad_s);

  const NavState& state() const { return state_; }
  const ErrorCovariance& covariance() const { return P_; }
  // Marginal covariance of [dp, dtheta].
  Matrix6d PoseCovariance() const;
  // PoseCovariance() less what the initial pose's uncertainty (the position
  // and attitude blocks of the covariance given to Initialize) still
  // contributes to it, each variance at least 0. The map's frame is the
  // first pose's: an error of that pose is shared by the map built from it
  // and by every pose matched against that map, so it does not move a
  // point relative to the map. The contribution is A P0 A', A the product
  // of every transition, update and reset since Initialize (the covariance
  // is linear in P0 given the gains): it fades as updates replace the prior.
  Matrix6d PoseCovarianceRelativeToStart() const;
  const EskfOptions& options() const { return options_; }

 private:
  void Step(const ImuSample& from, const ImuSample& to);
  void InjectAndReset(const Eigen::Matrix<double, 15, 1>& dx);

  EskfOptions options_;
  bool initialized_ = false;
  bool has_last_imu_ = false;
  ImuSample last_imu_;
  NavState state_;
  ErrorCovariance P_ = ErrorCovariance::Identity();
  // Initial pose covariance (position and attitude blocks of Initialize's,
  // the rest zero) and how it has been carried into P_ since (see
  // PoseCovarianceRelativeToStart).
  ErrorCovariance initial_pose_P_ = ErrorCovariance::Zero();
  ErrorCovariance start_transfer_ = ErrorCovariance::Identity();
};

}  // namespace unimap::estimation
