#include "estimation/Eskf.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>

#include "estimation/So3.hpp"

namespace unimap::estimation {
namespace {

using namespace error_index;
using Matrix15d = Eigen::Matrix<double, 15, 15>;
using Vector15d = Eigen::Matrix<double, 15, 1>;
using Matrix15x3d = Eigen::Matrix<double, 15, 3>;

const int kPoseRows[6] = {kP, kP + 1, kP + 2, kTheta, kTheta + 1, kTheta + 2};

}  // namespace

ErrorCovariance InitialCovariance(const EskfOptions& o) {
  Vector15d sigma;
  sigma << Eigen::Vector3d::Constant(o.initial_sigma_position_m),
      Eigen::Vector3d::Constant(o.initial_sigma_velocity_m_s), Eigen::Vector3d::Constant(o.initial_sigma_attitude_rad),
      Eigen::Vector3d::Constant(o.initial_sigma_accel_bias_m_s2),
      Eigen::Vector3d::Constant(o.initial_sigma_gyro_bias_rad_s);
  return sigma.array().square().matrix().asDiagonal();
}

Eskf::Eskf(EskfOptions options) : options_(options) {
  std::string why;
  if (!options_.IsValid(&why)) throw std::invalid_argument("EskfOptions: " + why);
}

void Eskf::Initialize(const NavState& state) { Initialize(state, InitialCovariance(options_)); }

void Eskf::Initialize(const NavState& state, const ErrorCovariance& covariance) {
  state_ = state;
  state_.q_world_body.normalize();
  P_ = covariance;
  initial_pose_P_.setZero();
  for (const int r : kPoseRows) {
    for (const int c : kPoseRows) initial_pose_P_(r, c) = covariance(r, c);
  }
  start_transfer_.setIdentity();
  initialized_ = true;
  has_last_imu_ = false;
}

bool Eskf::Propagate(const ImuSample& sample) {
  assert(initialized_);
  if (!has_last_imu_) {
    last_imu_ = sample;
    has_last_imu_ = true;
    state_.time_s = sample.time_s;
    return true;
  }
  const double dt = sample.time_s - last_imu_.time_s;
  if (!(dt > 0.0) || dt > options_.max_imu_gap_s) return false;
  Step(last_imu_, sample);
  last_imu_ = sample;
  return true;
}

void Eskf::PropagateTo(double time_s) {
  assert(initialized_ && has_last_imu_);
  if (!(time_s > state_.time_s)) return;
  ImuSample held = last_imu_;
  held.time_s = time_s;
  ImuSample from = last_imu_;
  from.time_s = state_.time_s;
  Step(from, held);
  last_imu_ = held;
}

void Eskf::RestartImu(const ImuSample& sample) {
  assert(initialized_ && has_last_imu_);
  PropagateTo(sample.time_s);
  last_imu_ = sample;
}

void Eskf::Step(const ImuSample& from, const ImuSample& to) {
  const double dt = to.time_s - from.time_s;
  const Eigen::Vector3d g(0.0, 0.0, -options_.gravity_m_s2);
  const Eigen::Vector3d& ba = state_.accel_bias_m_s2;
  const Eigen::Vector3d& bg = state_.gyro_bias_rad_s;

  // Nominal kinematics (Sola eq. 260): midpoint angular rate, trapezoidal
  // world-frame acceleration (exact for linearly varying acceleration).
  const Eigen::Vector3d omega = 0.5 * (from.gyro_rad_s + to.gyro_rad_s) - bg;
  const Eigen::Matrix3d R0 = state_.q_world_body.toRotationMatrix();
  const Eigen::Quaterniond q1 = (state_.q_world_body * ExpQ(omega * dt)).normalized();
  const Eigen::Matrix3d R1 = q1.toRotationMatrix();
  const Eigen::Vector3d a0 = R0 * (from.accel_m_s2 - ba) + g;
  const Eigen::Vector3d a1 = R1 * (to.accel_m_s2 - ba) + g;
  state_.p_world_body_m += state_.v_world_m_s * dt + dt * dt / 6.0 * (2.0 * a0 + a1);
  state_.v_world_m_s += 0.5 * (a0 + a1) * dt;
  state_.q_world_body = q1;
  state_.time_s = to.time_s;

  // Error-state transition (Sola eq. 269), evaluated at the interval's mean.
  const Eigen::Vector3d a_body = 0.5 * (from.accel_m_s2 + to.accel_m_s2) - ba;
  const Eigen::Matrix3d R = R0;
  Matrix15d F = Matrix15d::Identity();
  F.block<3, 3>(kP, kV) = Eigen::Matrix3d::Identity() * dt;
  F.block<3, 3>(kP, kTheta) = -0.5 * R * Skew(a_body) * dt * dt;
  F.block<3, 3>(kP, kBa) = -0.5 * R * dt * dt;
  F.block<3, 3>(kV, kTheta) = -R * Skew(a_body) * dt;
  F.block<3, 3>(kV, kBa) = -R * dt;
  F.block<3, 3>(kTheta, kTheta) = ExpQ(omega * dt).toRotationMatrix().transpose();
  F.block<3, 3>(kTheta, kBg) = -Eigen::Matrix3d::Identity() * dt;

  // Process noise: white accelerometer / gyroscope noise per sample and bias random walks.
  Matrix15x3d Ga = Matrix15x3d::Zero();
  Ga.block<3, 3>(kP, 0) = -0.5 * R * dt * dt;
  Ga.block<3, 3>(kV, 0) = -R * dt;
  const double sa2 = options_.sigma_accel_m_s2 * options_.sigma_accel_m_s2;
  const double sg2 = options_.sigma_gyro_rad_s * options_.sigma_gyro_rad_s;
  const double wa2 = options_.accel_bias_walk_m_s2_sqrt_s * options_.accel_bias_walk_m_s2_sqrt_s;
  const double wg2 = options_.gyro_bias_walk_rad_s_sqrt_s * options_.gyro_bias_walk_rad_s_sqrt_s;
  Matrix15d Q = sa2 * Ga * Ga.transpose();
  Q.block<3, 3>(kTheta, kTheta) += sg2 * dt * dt * Eigen::Matrix3d::Identity();
  Q.block<3, 3>(kBa, kBa) += wa2 * dt * Eigen::Matrix3d::Identity();
  Q.block<3, 3>(kBg, kBg) += wg2 * dt * Eigen::Matrix3d::Identity();
  P_ = F * P_ * F.transpose() + Q;
  P_ = 0.5 * (P_ + P_.transpose());
  start_transfer_ = F * start_transfer_;
}

PoseUpdateResult Eskf::UpdatePoseError(const Vector6d& z, const Matrix6d& R) {
  assert(initialized_);
  PoseUpdateResult result;
  Eigen::Matrix<double, 6, 15> H = Eigen::Matrix<double, 6, 15>::Zero();
  for (int i = 0; i < 6; ++i) H(i, kPoseRows[i]) = 1.0;
  const Matrix6d S = H * P_ * H.transpose() + R;
  const Eigen::LLT<Matrix6d> llt(S);
  if (llt.info() != Eigen::Success) return result;
  // K = P H' S^-1; dx = K z (the error state's prior mean is zero).
  const Eigen::Matrix<double, 15, 6> K = llt.solve(H * P_).transpose();
  const Vector15d dx = K * z;
  const Matrix15d I_KH = Matrix15d::Identity() - K * H;
  P_ = I_KH * P_ * I_KH.transpose() + K * R * K.transpose();  // Joseph form
  P_ = 0.5 * (P_ + P_.transpose());
  start_transfer_ = I_KH * start_transfer_;
  result.pose_covariance_before_reset = PoseCovariance();
  result.applied = true;
  result.mahalanobis_sq = z.dot(llt.solve(z));
  for (int i = 0; i < 6; ++i) result.error_correction(i) = dx(kPoseRows[i]);
  InjectAndReset(dx);
  return result;
}

PoseUpdateResult Eskf::UpdatePose(const Eigen::Isometry3d& T_world_body_measured, const Matrix6d& R) {
  Vector6d z;
  z.head<3>() = T_world_body_measured.translation() - state_.p_world_body_m;
  const Eigen::Quaterniond q_measured(T_world_body_measured.linear());
  z.tail<3>() = LogQ(state_.q_world_body.conjugate() * q_measured);
  return UpdatePoseError(z, R);
}

void Eskf::PredictPose(double time_s, const Eigen::Isometry3d& T_prev_next, const Matrix6d& covariance) {
  const Eigen::Matrix3d R = state_.q_world_body.toRotationMatrix();
  const Eigen::Matrix3d dR = T_prev_next.linear();
  const Eigen::Vector3d dp = T_prev_next.translation();
  ErrorCovariance F = ErrorCovariance::Identity();
  F.block<3, 3>(kP, kTheta) = -R * Skew(dp);
  F.block<3, 3>(kTheta, kTheta) = dR.transpose();
  P_ = F * P_ * F.transpose();
  start_transfer_ = F * start_transfer_;
  P_.block<3, 3>(kP, kP) += R * covariance.topLeftCorner<3, 3>() * R.transpose();
  P_.block<3, 3>(kP, kTheta) += R * covariance.topRightCorner<3, 3>();
  P_.block<3, 3>(kTheta, kP) += covariance.bottomLeftCorner<3, 3>() * R.transpose();
  P_.block<3, 3>(kTheta, kTheta) += covariance.bottomRightCorner<3, 3>();
  P_ = 0.5 * (P_ + P_.transpose());
  const double dt = time_s - state_.time_s;
  state_.p_world_body_m += R * dp;
  state_.v_world_m_s = dt > 0.0 ? Eigen::Vector3d(R * dp / dt) : Eigen::Vector3d::Zero();
  state_.q_world_body = (state_.q_world_body * Eigen::Quaterniond(dR)).normalized();
  state_.time_s = time_s;
}

void Eskf::SetImuNoise(double sigma_accel_m_s2, double sigma_gyro_rad_s) {
  if (!(sigma_accel_m_s2 > 0.0) || !(sigma_gyro_rad_s > 0.0))
    throw std::invalid_argument("Eskf: IMU sigmas must be > 0");
  options_.sigma_accel_m_s2 = sigma_accel_m_s2;
  options_.sigma_gyro_rad_s = sigma_gyro_rad_s;
}

void Eskf::InflateMotionCovariance(double factor) {
  if (!(factor > 1.0) || !std::isfinite(factor)) return;
  const double s = std::sqrt(factor);
  Eigen::Matrix<double, 15, 1> scale = Eigen::Matrix<double, 15, 1>::Ones();
  scale.segment<9>(error_index::kP).setConstant(s);  // p, v, theta
  P_ = scale.asDiagonal() * P_ * scale.asDiagonal();
  start_transfer_ = scale.asDiagonal() * start_transfer_;
}

Matrix6d Eskf::PoseCovariance() const {
  Matrix6d out;
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < 6; ++c) out(r, c) = P_(kPoseRows[r], kPoseRows[c]);
  }
  return out;
}

Matrix6d Eskf::PoseCovarianceRelativeToStart() const {
  const ErrorCovariance from_start = start_transfer_ * initial_pose_P_ * start_transfer_.transpose();
  Matrix6d out;
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < 6; ++c) out(r, c) = P_(kPoseRows[r], kPoseRows[c]) - from_start(kPoseRows[r], kPoseRows[c]);
  }
  for (int i = 0; i < 6; ++i) out(i, i) = std::max(out(i, i), 0.0);
  return out;
}

void Eskf::InjectAndReset(const Eigen::Matrix<double, 15, 1>& dx) {
  // Injection (Sola eq. 283) and reset (eq. 287): G = diag(I, I, I - [dtheta/2]x, I, I).
  state_.p_world_body_m += dx.segment<3>(kP);
  state_.v_world_m_s += dx.segment<3>(kV);
  state_.q_world_body = (state_.q_world_body * ExpQ(dx.segment<3>(kTheta))).normalized();
  state_.accel_bias_m_s2 += dx.segment<3>(kBa);
  state_.gyro_bias_rad_s += dx.segment<3>(kBg);
  Matrix15d G = Matrix15d::Identity();
  G.block<3, 3>(kTheta, kTheta) -= Skew(0.5 * dx.segment<3>(kTheta));
  P_ = G * P_ * G.transpose();
  start_transfer_ = G * start_transfer_;
}

}  // namespace unimap::estimation
