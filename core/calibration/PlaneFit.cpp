#include "calibration/PlaneFit.hpp"

#include <Eigen/Eigenvalues>

namespace unimap::calibration {

PlaneFit FitPlane(const std::vector<Eigen::Vector3d>& points) {
  PlaneFit fit;
  for (const Eigen::Vector3d& q : points) fit.mean += q;
  const double K = static_cast<double>(points.size());
  fit.mean /= K;
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& q : points) scatter += (q - fit.mean) * (q - fit.mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scatter / K);
  fit.eigenvalues = eig.eigenvalues();
  fit.eigenvectors = eig.eigenvectors();
  return fit;
}

}  // namespace unimap::calibration
