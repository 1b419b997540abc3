#include "pipeline/ScanMatcher.hpp"

#include <algorithm>
#include <cmath>

#include "estimation/So3.hpp"
#include "pipeline/FieldDistanceQuery.hpp"

namespace unimap::pipeline {
namespace {

// A match leaving less than this share of the scan on the map is searched from.
constexpr double kPoorInlierShare = 0.5;
// The reacquired correction is made this many sigmas of the inflated prediction.
constexpr double kCorrectionSigmas = 2.0;

}  // namespace

ScanMatcher::ScanMatcher(const LocalizerOptions& options)
    : options_(options), gpf_(options.gpf), reacquirer_(options.reacquire) {}

ScanMatchResult ScanMatcher::Match(const std::shared_ptr<const map::DistanceField>& field,
                                   const Eigen::Isometry3d& T_predicted, const matching::Matrix6d& predicted_covariance,
                                   const matching::Matrix6d& map_relative_covariance,
                                   const std::vector<Eigen::Vector3f>& points_body, bool line) {
  const FieldDistanceQuery query(field, options_.trilinear_distance, options_.neighborhood_planes);
  const double position_sigma = std::sqrt(predicted_covariance.diagonal().head<3>().maxCoeff());
  const double rotation_sigma = std::sqrt(predicted_covariance.diagonal().tail<3>().maxCoeff());
  const double gate_position_sigma = std::sqrt(map_relative_covariance.diagonal().head<3>().maxCoeff());
  const double gate_rotation_sigma = std::sqrt(map_relative_covariance.diagonal().tail<3>().maxCoeff());
  // Points far from every mapped surface at the prediction look at what the
  // map has not seen (past the frontier ahead, above the band a narrow
  // vertical field of view has mapped); measured against the nearest mapped
  // surface they pull the pose towards it. The gate allows for the pose's
  // rotation uncertainty relative to the map, which moves a point by its
  // range times the angle, for every scan; a sweep's also for its position
  // uncertainty (a line's position term let the points between a line
  // scanner's stripes in: docs/robustness.md, "The line gate"). Relative
  // to the map: the first pose's uncertainty, which the map shares, would
  // widen the gate at the start, where nothing has moved yet.
  const bool widen = options_.max_predicted_distance_m > 0.0;
  const double gate_m =
      options_.max_predicted_distance_m + (widen && !line ? options_.sweep_gate_sigmas * gate_position_sigma : 0.0);
  const double gate_per_range = widen ? options_.sweep_gate_sigmas * gate_rotation_sigma : 0.0;
  const bool wide = position_sigma > options_.reacquire.wide_sigma_voxels * field->resolution() ||
                    rotation_sigma > options_.reacquire.wide_sigma_rad;
  ScanMatchResult out;
  const std::vector<Eigen::Vector3f> subset = StridedSubset(points_body, options_.reacquire.max_points);
  double matched_share = 0.0;
  // A single 2D line holds too little of the scene to be placed in 6 DOF
  // on its own: line scans are matched around their prediction only.
  if (line) {
    out.match = gpf_.Match(T_predicted, predicted_covariance, points_body, query, gate_m, gate_per_range);
    if (out.match.ok) {
      out.inliers =
          reacquirer_.InlierShare(*field, estimation::ApplyPoseError(T_predicted, out.match.posterior_mean), subset);
    }
    return out;
  }
  if (!wide) {
    out.match = gpf_.Match(T_predicted, predicted_covariance, points_body, query, gate_m, gate_per_range);
    if (out.match.ok) {
      matched_share =
          reacquirer_.InlierShare(*field, estimation::ApplyPoseError(T_predicted, out.match.posterior_mean), subset);
      out.inliers = matched_share;
      if (matched_share >= kPoorInlierShare) return out;
    }
  }
  out.searched = true;
  const ReacquireResult found = reacquirer_.Search(field, T_predicted, predicted_covariance, subset,
                                                   options_.gpf.point_sigma_m, options_.gpf.clamp_distance_m);
  // An uncertain prediction says little: the search's pose is taken unless
  // it holds fewer of the scan. A confident one is replaced only by a pose
  // holding clearly more of it.
  const bool better = found.ok && (wide ? found.inliers_found >= found.inliers_predicted
                                        : found.inliers_found >= matched_share + options_.reacquire.min_inlier_gain);
  if (!better) {
    if (wide) {  // nothing better found: match as usual
      out.match = gpf_.Match(T_predicted, predicted_covariance, points_body, query, gate_m, gate_per_range);
      if (out.match.ok) {
        out.inliers =
            reacquirer_.InlierShare(*field, estimation::ApplyPoseError(T_predicted, out.match.posterior_mean), subset);
      }
    }
    return out;
  }
  // The prediction was off by found.error: inflate it until that is a
  // kCorrectionSigmas correction, and refine from there.
  const double mahalanobis_sq = found.error.dot(predicted_covariance.ldlt().solve(found.error));
  out.inflation = std::max(1.0, mahalanobis_sq / (kCorrectionSigmas * kCorrectionSigmas));
  out.match = gpf_.MatchFrom(T_predicted, out.inflation * predicted_covariance, points_body, query, gate_m, found.error,
                             gate_per_range);
  out.reacquired = out.match.ok;
  // The share at the refined pose (the search's own share otherwise).
  out.inliers = out.match.ok ? reacquirer_.InlierShare(
                                   *field, estimation::ApplyPoseError(T_predicted, out.match.posterior_mean), subset)
                             : found.inliers_found;
  return out;
}

}  // namespace unimap::pipeline
