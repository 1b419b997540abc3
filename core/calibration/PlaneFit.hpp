#pragma once
#include <vector>

#include <Eigen/Core>

namespace unimap::calibration {

// The least-squares plane of some points: their mean, and the eigenvalues
// (ascending, m^2) and eigenvectors (columns) of their covariance; the first
// eigenvector is the normal, the first eigenvalue the variance across it.
struct PlaneFit {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  Eigen::Vector3d eigenvalues = Eigen::Vector3d::Zero();
  Eigen::Matrix3d eigenvectors = Eigen::Matrix3d::Identity();
};

// At least one point.
PlaneFit FitPlane(const std::vector<Eigen::Vector3d>& points);

}  // namespace unimap::calibration
