#pragma once
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "matching/DistanceQuery.hpp"
#include "matching/PlanePoint.hpp"
#include "matching/PseudoMeasurement.hpp"

namespace unimap::matching {

// Outcome of refining one pose error.
struct PoseRefinement {
  bool ok = false;  // false: see reason (no points, singular normal equations)
  std::string reason;
  Vector6d mean = Vector6d::Zero();         // MAP pose error [dp, dtheta] (p + dp, q * Exp(dtheta))
  Matrix6d covariance = Matrix6d::Zero();   // Laplace posterior (P^-1 + H)^-1 at the MAP
  Matrix6d information = Matrix6d::Zero();  // H: the scan's (tempered) Gauss-Newton information at the MAP
  int iterations = 0;                       // accepted Gauss-Newton steps
  double initial_cost = 0.0;                // negative log posterior at the start
  double final_cost = 0.0;                  // ... at the MAP (never above initial_cost)
};

// Gauss-Newton refinement of a pose error on a distance field: minimises the
// negative log posterior the GPF samples (docs/design.md 1.3), the Gaussian prior
// N(prior_mean, P) plus the tempered scan likelihood of ScanLikelihood,
//   C(e) = 1/2 (e - m)' P^-1 (e - m) + (E / n) / (2 sigma^2) sum_i min(d_i(e), clamp)^2,
// with d_i(e) the distance of body point i at T(e) = (t + dp, R Exp(dtheta)).
// Each step solves (P^-1 + J' W J) delta = -(P^-1 (e - m) + J' W d) with
// J_i = [g_i', (p_i x R(e)' g_i)'] (g_i the field's gradient, W = E / (n sigma^2),
// clamped points excluded) and is accepted only if C decreases (halving the
// step up to twice otherwise). The result is the Laplace approximation of the
// posterior: its mean (deterministic, free of Monte-Carlo noise) and
// covariance, and the scan information H = J' W J at the MAP, so that
// RecoverPseudoMeasurement(prior_mean, P, mean, covariance) yields R = H^-1.
class PoseRefiner {
 public:
  // sigma_m, clamp_m, effective_points: as in ScanLikelihood; max_iterations >= 1.
  PoseRefiner(double sigma_m, double clamp_m, double effective_points, int max_iterations);

  // T_map_body_predicted: the pose error's reference; prior_mean, prior_covariance:
  // N(m, P) of the error (P positive definite on the active dims); start: the
  // first iterate (e.g. the GPF's posterior mean); active_dims: the error
  // dimensions optimised (others stay at start and get no information);
  // points_body: the (downsampled) scan.
  PoseRefinement Refine(const Eigen::Isometry3d& T_map_body_predicted, const Vector6d& prior_mean,
                        const Matrix6d& prior_covariance, const Vector6d& start, const std::vector<int>& active_dims,
                        const std::vector<Eigen::Vector3f>& points_body, const DistanceQuery& field) const;
  // The same with points tied to planes as well (PlanePoint): their d_i is
  // the distance to their plane and g_i its normal; n counts both kinds and
  // unmeasured_points (as in ScanLikelihood).
  PoseRefinement Refine(const Eigen::Isometry3d& T_map_body_predicted, const Vector6d& prior_mean,
                        const Matrix6d& prior_covariance, const Vector6d& start, const std::vector<int>& active_dims,
                        const std::vector<Eigen::Vector3f>& points_body, const std::vector<PlanePoint>& plane_points,
                        const DistanceQuery& field, int unmeasured_points = 0) const;

 private:
  double sigma_m_;
  double clamp_m_;
  double effective_points_;
  int max_iterations_;
};

}  // namespace unimap::matching
