#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "graph/LoopClosureDistanceField.hpp"
#include "graph/LoopClosureOptions.hpp"

namespace unimap::graph {

// Outcome of refining one pose.
struct LoopClosureRefinement {
  bool ok = false;  // false: no scan point near the submap surface (see reason)
  std::string reason;
  Eigen::Isometry3d T_submap_body = Eigen::Isometry3d::Identity();  // refined pose
  double score = 0.0;                     // fraction of the points within inlier_distance_m of the surface
  int inliers = 0;                        // points within inlier_distance_m
  std::vector<std::uint8_t> inlier_mask;  // per point, 1 when within inlier_distance_m (when ok)
  int iterations = 0;                     // Levenberg-Marquardt iterations run
  double rms_m = 0.0;                     // RMS plane residual of the inliers with a planar correspondence (m)
  Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Identity();  // see Refine
};

// 6-DOF refinement of a scan pose in a submap's fine field (point-to-plane
// ICP with the field's precomputed nearest points as correspondences):
// Levenberg-Marquardt on the Huber-weighted (iteratively reweighted)
// residuals r_i = n_q . (R p_i + t - q) of the points p_i against the
// submap point q nearest their cell (|R p_i + t - q| where q has no
// normal), with the pose perturbed as t + dp, R Exp(dtheta) (dp in the
// submap frame, dtheta in the body frame, the convention of
// RelativePoseCost) and Jacobian rows
//   J_i = [ n^T ,  (p_i x R^T n)^T ].
// Points with no submap point near carry no weight. Stateless apart from
// its references: safe to use from several threads.
class LoopClosureRefiner {
 public:
  // Keeps references: field and options must outlive the refiner.
  LoopClosureRefiner(const LoopClosureDistanceField& field, const LoopClosureOptions& options);

  // Refines T_initial; the covariance of the result, order [dp, dtheta], is
  //   C = s^2 max(1, n / effective_points) H^-1 + diag(min_sigma^2),
  // H = sum J_i^T J_i and s^2 = sum r_i^2 / (n - 6) over the n inliers with
  // a planar correspondence (point-to-point ones along edges would constrain
  // the edge direction by the sampling ripple: conservative), with
  // s at least inlier_distance_m / 10 (eigenvalues of H floored at 1e-12 of
  // the largest, so C stays symmetric positive definite).
  // At most max_iterations Levenberg-Marquardt iterations.
  LoopClosureRefinement Refine(const std::vector<Eigen::Vector3f>& points_body, const Eigen::Isometry3d& T_initial,
                               int max_iterations) const;
  // Fraction of the points within inlier_distance_m of the surface at T.
  double Score(const std::vector<Eigen::Vector3f>& points_body, const Eigen::Isometry3d& T_submap_body) const;

 private:
  const LoopClosureDistanceField& field_;
  const LoopClosureOptions& options_;
};

}  // namespace unimap::graph
