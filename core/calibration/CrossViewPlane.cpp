#include "calibration/CrossViewPlane.hpp"

#include <algorithm>

#include <Eigen/Eigenvalues>

namespace unimap::calibration {
namespace {

Eigen::Isometry3d Exp(const Vector6d& D) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d phi = D.tail<3>();
  const double angle = phi.norm();
  if (angle > 0.0) T.linear() = Eigen::AngleAxisd(angle, phi / angle).toRotationMatrix();
  T.translation() = D.head<3>();
  return T;
}

// dq/dD at D = 0: A [I, -[p]x].
Eigen::Matrix<double, 3, 6> PointJacobian(const CrossViewPlane::Member& m) {
  const Eigen::Matrix3d& A = m.T_world_lidar_corrected.linear();
  const Eigen::Vector3d& p = m.p_lidar;
  Eigen::Matrix3d skew;
  skew << 0, -p.z(), p.y(), p.z(), 0, -p.x(), -p.y(), p.x(), 0;
  Eigen::Matrix<double, 3, 6> J;
  J << A, -A * skew;
  return J;
}

}  // namespace

CrossViewPlane::CrossViewPlane(std::vector<Member> measured, std::vector<Member> plane)
    : measured_(std::move(measured)), plane_(std::move(plane)) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Member& m : plane_) mean += m.T_world_lidar_corrected * m.p_lidar;
  mean /= static_cast<double>(plane_.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Member& m : plane_) {
    const Eigen::Vector3d e = m.T_world_lidar_corrected * m.p_lidar - mean;
    scatter += e * e.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scatter / static_cast<double>(plane_.size()));
  normal_ = eig.eigenvectors().col(0);
  across_variance_ = std::max(0.0, eig.eigenvalues()(0));
  for (int m = 0; m < 2; ++m) {
    in_plane_[m] = eig.eigenvectors().col(m + 1);
    in_plane_variance_[m] = eig.eigenvalues()(m + 1);
  }
}

Matrix6d CrossViewPlane::NormalNoiseInformation(double sigma_m) const {
  Eigen::Matrix<double, 3, 6> mean = Eigen::Matrix<double, 3, 6>::Zero();
  for (const Member& m : plane_) mean += PointJacobian(m);
  mean /= static_cast<double>(plane_.size());
  const double K = static_cast<double>(plane_.size());
  Matrix6d noise = Matrix6d::Zero();
  for (const Member& measured : measured_) {
    const Eigen::Matrix<double, 3, 6> G = PointJacobian(measured) - mean;
    for (int m = 0; m < 2; ++m) {
      if (!(in_plane_variance_[m] > 0.0)) continue;
      const Eigen::Matrix<double, 1, 6> row = in_plane_[m].transpose() * G;
      noise += across_variance_ * row.transpose() * row / (K * in_plane_variance_[m] * sigma_m * sigma_m);
    }
  }
  return noise;
}

Eigen::Vector3d CrossViewPlane::NormalAt(const Vector6d& D) const {
  const Eigen::Isometry3d E = Exp(D);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (const Member& m : plane_) {
    const Eigen::Vector3d q = m.T_world_lidar_corrected * (E * m.p_lidar);
    mean += q;
    second += q * q.transpose();
  }
  const double K = static_cast<double>(plane_.size());
  mean /= K;
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(second / K - mean * mean.transpose()).eigenvectors().col(0);
}

Eigen::VectorXd CrossViewPlane::Residuals(const Vector6d& D, const Eigen::Vector3d& n, double sigma_m) const {
  const Eigen::Isometry3d E = Exp(D);
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const Member& m : plane_) c += m.T_world_lidar_corrected * (E * m.p_lidar);
  c /= static_cast<double>(plane_.size());
  Eigen::VectorXd r(static_cast<Eigen::Index>(measured_.size()));
  for (std::size_t i = 0; i < measured_.size(); ++i) {
    const Member& m = measured_[i];
    r(static_cast<Eigen::Index>(i)) = n.dot(m.T_world_lidar_corrected * (E * m.p_lidar) - c) / sigma_m;
  }
  return r;
}

Eigen::Matrix<double, Eigen::Dynamic, 6> CrossViewPlane::Jacobian(double sigma_m) const {
  Eigen::Matrix<double, 3, 6> mean = Eigen::Matrix<double, 3, 6>::Zero();
  for (const Member& m : plane_) mean += PointJacobian(m);
  mean /= static_cast<double>(plane_.size());
  Eigen::Matrix<double, Eigen::Dynamic, 6> J(static_cast<Eigen::Index>(measured_.size()), 6);
  for (std::size_t i = 0; i < measured_.size(); ++i) {
    J.row(static_cast<Eigen::Index>(i)) = normal_.transpose() * (PointJacobian(measured_[i]) - mean) / sigma_m;
  }
  return J;
}

}  // namespace unimap::calibration
