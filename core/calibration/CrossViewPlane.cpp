#include "calibration/CrossViewPlane.hpp"

#include <algorithm>

namespace unimap::calibration {
namespace {

// dq/dD at D = 0: A [I, -[p]x].
Eigen::Matrix<double, 3, 6> PointJacobian(const CrossViewPlane::Member& m) {
  const Eigen::Matrix3d& A = m.T_world_lidar_corrected.linear();
  Eigen::Matrix<double, 3, 6> J;
  J << A, -A * estimation::Skew(m.p_lidar);
  return J;
}

}  // namespace

CrossViewPlane::CrossViewPlane(std::vector<Member> measured, std::vector<Member> plane)
    : measured_(std::move(measured)), plane_(std::move(plane)), fit_(FitAt(Vector6d::Zero())) {
  normal_ = fit_.eigenvectors.col(0);
  mean_jacobian_.setZero();
  for (const Member& m : plane_) mean_jacobian_ += PointJacobian(m);
  mean_jacobian_ /= static_cast<double>(plane_.size());
}

PlaneFit CrossViewPlane::FitAt(const Vector6d& D) const {
  const Eigen::Isometry3d E = CorrectionExp(D);
  std::vector<Eigen::Vector3d> q;
  q.reserve(plane_.size());
  for (const Member& m : plane_) q.push_back(m.T_world_lidar_corrected * (E * m.p_lidar));
  return FitPlane(q);
}

Matrix6d CrossViewPlane::NormalNoiseInformation(double sigma_m) const {
  const double K = static_cast<double>(plane_.size());
  const double across_variance = std::max(0.0, fit_.eigenvalues(0));
  Matrix6d noise = Matrix6d::Zero();
  for (const Member& measured : measured_) {
    const Eigen::Matrix<double, 3, 6> G = PointJacobian(measured) - mean_jacobian_;
    for (int m = 1; m < 3; ++m) {
      if (!(fit_.eigenvalues(m) > 0.0)) continue;
      const Eigen::Matrix<double, 1, 6> row = fit_.eigenvectors.col(m).transpose() * G;
      noise += across_variance * row.transpose() * row / (K * fit_.eigenvalues(m) * sigma_m * sigma_m);
    }
  }
  return noise;
}

Eigen::Vector3d CrossViewPlane::NormalAt(const Vector6d& D) const { return FitAt(D).eigenvectors.col(0); }

Eigen::VectorXd CrossViewPlane::Residuals(const Vector6d& D, const Eigen::Vector3d& n, double sigma_m) const {
  const Eigen::Isometry3d E = CorrectionExp(D);
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
  Eigen::Matrix<double, Eigen::Dynamic, 6> J(static_cast<Eigen::Index>(measured_.size()), 6);
  for (std::size_t i = 0; i < measured_.size(); ++i) {
    J.row(static_cast<Eigen::Index>(i)) =
        normal_.transpose() * (PointJacobian(measured_[i]) - mean_jacobian_) / sigma_m;
  }
  return J;
}

}  // namespace unimap::calibration
