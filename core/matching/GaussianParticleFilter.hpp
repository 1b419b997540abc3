#pragma once
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "matching/DistanceQuery.hpp"
#include "matching/GpfOptions.hpp"
#include "matching/PlanePoint.hpp"
#include "matching/PoseRefiner.hpp"
#include "matching/PseudoMeasurement.hpp"

namespace unimap::matching {

// Outcome of matching one scan.
struct GpfResult {
  bool ok = false;  // false: see reason (no points, degenerate covariance)
  std::string reason;
  Vector6d sample_mean = Vector6d::Zero();           // mu_s of the drawn particles, [dp, dtheta]
  Matrix6d sample_covariance = Matrix6d::Zero();     // S_s
  Vector6d posterior_mean = Vector6d::Zero();        // mu_p, likelihood-weighted
  Matrix6d posterior_covariance = Matrix6d::Zero();  // S_p
  PseudoMeasurement measurement;                     // (z, R) for Eskf::UpdatePoseError
  double effective_sample_size = 0.0;                // 1 / sum w^2
  int points_used = 0;                               // after downsampling
  int points_unseen = 0;                             // of those: beyond max_predicted_distance_m, not measured
  int refine_iterations = 0;                         // accepted Gauss-Newton steps (GpfOptions::refine_iterations)
  bool refined = false;                              // posterior_* are the refined Laplace posterior
  double downsample_s = 0.0;                         // wall time of the scan's voxel filter (part of Match)
};

// Gaussian particle filter scan matcher (Bry et al. 2012): samples pose
// errors [dp, dtheta] (p + dp, q * Exp(dtheta)) from the predicted
// covariance, weights each by the scan likelihood in the distance map, and
// returns the weighted mean and covariance with the pseudo measurement that
// reproduces them in the ESKF. With refine_iterations > 0 the mean is then
// refined by Gauss-Newton on the same posterior (PoseRefiner) and the
// Laplace approximation there replaces the particle statistics.
class GaussianParticleFilter {
 public:
  explicit GaussianParticleFilter(GpfOptions options);
  ~GaussianParticleFilter();

  // max_predicted_distance_m > 0: the (field) points farther than this
  // (plus max_predicted_distance_per_range times the point's range in the
  // body) from the map at the predicted pose are not measured, only counted in
  // the scan's n (ScanLikelihood): they look at surfaces the map has not
  // seen yet, and measured against the nearest one it has they pull the
  // pose towards it.
  GpfResult Match(const Eigen::Isometry3d& T_map_body_predicted, const Matrix6d& predicted_covariance,
                  const std::vector<Eigen::Vector3f>& points_body, const DistanceQuery& field,
                  double max_predicted_distance_m = 0.0, double max_predicted_distance_per_range = 0.0);
  // The same without particles, from a pose error found otherwise (a wide
  // search, pipeline::Reacquirer): the points are gated at the prediction
  // moved by start, and the Gauss-Newton refinement (at least 5 steps)
  // starts there, on the same posterior (prior N(0, predicted_covariance)).
  GpfResult MatchFrom(const Eigen::Isometry3d& T_map_body_predicted, const Matrix6d& predicted_covariance,
                      const std::vector<Eigen::Vector3f>& points_body, const DistanceQuery& field,
                      double max_predicted_distance_m, const Vector6d& start,
                      double max_predicted_distance_per_range = 0.0);

  const GpfOptions& options() const { return options_; }

 private:
  struct Workspace;
  // The Gauss-Newton refinement on the posterior N(0, prior) x likelihood from start.
  PoseRefinement RefineOnPosterior(const Eigen::Isometry3d& T_map_body_predicted, const Matrix6d& prior,
                                   const std::vector<int>& dims, const Vector6d& start,
                                   const std::vector<Eigen::Vector3f>& points,
                                   const std::vector<PlanePoint>& plane_points, const DistanceQuery& field,
                                   int unmeasured, int iterations) const;
  // Fills result's posterior and pseudo measurement from a successful refinement.
  void ApplyRefinement(const Matrix6d& prior, const std::vector<int>& dims, const PoseRefinement& refined,
                       GpfResult* result) const;
  // MatchFrom's work once the points are prepared.
  GpfResult RefineFrom(const Eigen::Isometry3d& T_map_body_predicted, const Eigen::MatrixXd& S,
                       const std::vector<int>& dims, const Vector6d& start, const std::vector<Eigen::Vector3f>& points,
                       const std::vector<PlanePoint>& plane_points, const DistanceQuery& field, int unmeasured,
                       GpfResult result) const;
  GpfResult MatchImpl(const Eigen::Isometry3d& T_map_body_predicted, const Matrix6d& predicted_covariance,
                      const std::vector<Eigen::Vector3f>& points_body, const DistanceQuery& field,
                      double max_predicted_distance_m, double max_predicted_distance_per_range, const Vector6d* start);
  GpfOptions options_;
  std::mt19937_64 rng_;
  std::uint64_t scans_matched_ = 0;
  std::unique_ptr<Workspace> workspace_;
};

}  // namespace unimap::matching
