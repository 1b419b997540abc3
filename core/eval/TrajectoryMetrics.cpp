#include "eval/TrajectoryMetrics.hpp"

#include <cmath>

#include "unimap/Errors.hpp"

namespace unimap::eval {
namespace {

constexpr double kDegPerRad = 180.0 / M_PI;

// Length of the polyline through the poses' positions.
double PathLength(const std::vector<StampedPose>& poses) {
  double length = 0.0;
  for (std::size_t k = 1; k < poses.size(); ++k) {
    length += (poses[k].T_map_body.translation() - poses[k - 1].T_map_body.translation()).norm();
  }
  return length;
}

}  // namespace

TrajectoryMetrics ComputeTrajectoryMetrics(const TrajectoryAssociation& association, const TrajectoryErrors& errors,
                                           double max_time_diff_s, double segment_m) {
  const std::vector<PoseError>& poses = errors.poses;
  if (poses.empty() || poses.size() != association.pairs.size()) {
    throw InputError("trajectory metrics need a non-empty error series matching the association");
  }
  TrajectoryMetrics m;
  m.max_time_diff_s = max_time_diff_s;
  m.segment_m = segment_m;
  m.poses_associated = poses.size();
  m.poses_outside_truth_span = association.skipped_outside_span;
  m.poses_in_truth_gaps = association.skipped_in_gap;
  m.poses_skipped = association.skipped();
  m.duration_s = poses.back().time_s - poses.front().time_s;

  // ATE: sqrt(1/n sum |R p_est(k) + t - p_true(k)|^2) at the Umeyama optimum.
  m.ate_rmse_m = errors.alignment.rmse_m;
  if (errors.similarity) m.trajectory_scale = 1.0 / errors.similarity->scale;
  m.path_length_m = PathLength(association.truth_span);

  Eigen::Vector3d sum_abs_rot = Eigen::Vector3d::Zero();
  for (const PoseError& e : poses) {
    m.max_abs_error_m = m.max_abs_error_m.cwiseMax(e.position_error_m.cwiseAbs());
    sum_abs_rot += e.rotation_error_rad.cwiseAbs();
  }
  m.mean_abs_rot_error_deg = sum_abs_rot / static_cast<double>(poses.size()) * kDegPerRad;
  m.final_position_error_m = poses.back().position_error_m.norm();
  m.final_rot_error_deg = poses.back().rotation_error_rad.norm() * kDegPerRad;
  if (m.path_length_m > 0.0) {
    m.drift_percent = 100.0 * m.final_position_error_m / m.path_length_m;
    m.rot_drift_deg_per_m = m.final_rot_error_deg / m.path_length_m;
  }
  const RelativePoseError rpe = ComputeRelativePoseError(association, errors, segment_m);
  m.rpe_segments = rpe.segments;
  m.rpe_trans_percent = rpe.trans_percent;
  m.rpe_rot_deg_per_m = rpe.rot_deg_per_m;
  return m;
}

}  // namespace unimap::eval
