#pragma once
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "calibration/LidarCorrection.hpp"
#include "calibration/PlaneFit.hpp"

namespace unimap::calibration {

// A surface patch seen from two views, and how far the returns of one view
// lie from the plane of the other's, as a function of a step
// D = [rho (m); phi (rad)] of the LiDAR extrinsic's correction. A return j is
// mapped to q_j(D) = T_j Exp(D) p_j, with T_j = T_world_lidar,j X (X the
// correction so far) and Exp(D) = (AngleAxis(phi), rho). The residual of a
// measured return i is
//   r_i(D) = n' (q_i(D) - c(D)) / sigma,
// c(D) the mean of the plane's returns and n their plane's normal (the
// eigenvector of their covariance's smallest eigenvalue), held at its D = 0
// value (Gauss-Newton, as in point-to-plane ICP). Both views move with D:
// only a disagreement between them is measured, never the shape both share.
class CrossViewPlane {
 public:
  struct Member {
    Eigen::Vector3d p_lidar = Eigen::Vector3d::Zero();                          // the return, LiDAR frame
    Eigen::Isometry3d T_world_lidar_corrected = Eigen::Isometry3d::Identity();  // T_world_lidar X
  };
  // measured: at least one; plane: at least three.
  CrossViewPlane(std::vector<Member> measured, std::vector<Member> plane);

  // The plane's unit normal at D = 0.
  const Eigen::Vector3d& normal() const { return normal_; }
  // ... and fitted again to the plane's returns moved by D.
  Eigen::Vector3d NormalAt(const Vector6d& D) const;
  // The residuals at D with the normal n (one per measured return).
  Eigen::VectorXd Residuals(const Vector6d& D, const Eigen::Vector3d& n, double sigma_m) const;
  // Their Jacobian at D = 0 with the plane's normal (rows: measured returns).
  Eigen::Matrix<double, Eigen::Dynamic, 6> Jacobian(double sigma_m) const;
  // What the plane's noise adds to J'J on average: the fitted normal turns by
  // about sqrt(lambda_0 / (K lambda_m)) towards each in-plane direction v_m
  // (lambda_m the variance of the plane's returns along it, lambda_0 across
  // it), which moves every row of the Jacobian by dn' G_i / sigma
  // (G_i = J_i - mean_k J_k):
  //   E[dJ' dJ] = sum_i sum_m lambda_0 G_i' v_m v_m' G_i / (K lambda_m sigma^2).
  // Information that is only this is noise: subtracting it keeps a direction
  // the surfaces do not constrain from looking observed.
  Matrix6d NormalNoiseInformation(double sigma_m) const;

 private:
  // The plane fitted to its returns moved by D.
  PlaneFit FitAt(const Vector6d& D) const;

  std::vector<Member> measured_;
  std::vector<Member> plane_;
  PlaneFit fit_;                                       // at D = 0
  Eigen::Vector3d normal_ = Eigen::Vector3d::UnitZ();  // fit_'s normal
  Eigen::Matrix<double, 3, 6> mean_jacobian_;          // mean over the plane's returns of dq/dD at D = 0
};

}  // namespace unimap::calibration
