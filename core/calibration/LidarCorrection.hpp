#pragma once
// The LiDAR extrinsic's correction as a 6-vector D = [rho (m); phi (rad)]:
// Exp(D) = (Exp(phi), rho), so that X Exp(D) p = X (R(phi) p + rho), and its
// inverse on a pose; the SO(3) maps are estimation/So3.hpp's.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "estimation/So3.hpp"

namespace unimap::calibration {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

inline Eigen::Isometry3d CorrectionExp(const Vector6d& D) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = estimation::ExpQ(D.tail<3>()).toRotationMatrix();
  T.translation() = D.head<3>();
  return T;
}

inline Vector6d CorrectionLog(const Eigen::Isometry3d& X) {
  Vector6d D;
  D << X.translation(), estimation::LogQ(Eigen::Quaterniond(X.linear()));
  return D;
}

}  // namespace unimap::calibration
