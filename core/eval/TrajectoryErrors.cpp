#include "eval/TrajectoryErrors.hpp"

#include <cmath>

#include "estimation/So3.hpp"
#include "unimap/Errors.hpp"

namespace unimap::eval {

Eigen::Isometry3d AnchorTransform(const Eigen::Isometry3d& T_true_first, const Eigen::Isometry3d& T_est_first,
                                  Anchor anchor) {
  if (anchor == Anchor::kFullPose) return T_true_first * T_est_first.inverse();
  Eigen::Isometry3d T_true_est = Eigen::Isometry3d::Identity();
  T_true_est.linear() =
      Eigen::AngleAxisd(estimation::Heading(T_true_first.linear()) - estimation::Heading(T_est_first.linear()),
                        Eigen::Vector3d::UnitZ())
          .toRotationMatrix();
  T_true_est.translation() = T_true_first.translation() - T_true_est.linear() * T_est_first.translation();
  return T_true_est;
}

TrajectoryErrors ComputeTrajectoryErrors(const TrajectoryAssociation& association, Anchor anchor) {
  const std::vector<AssociatedPose>& pairs = association.pairs;
  if (pairs.empty()) throw InputError("no associated poses to compute errors from");
  TrajectoryErrors errors;
  std::vector<Eigen::Vector3d> est_positions;
  std::vector<Eigen::Vector3d> true_positions;
  est_positions.reserve(pairs.size());
  true_positions.reserve(pairs.size());
  for (const AssociatedPose& pair : pairs) {
    est_positions.push_back(pair.T_est_body.translation());
    true_positions.push_back(pair.T_true_body.translation());
  }
  errors.alignment = AlignRigid(est_positions, true_positions);
  errors.similarity = AlignSimilarity(est_positions, true_positions);

  // T_true_est: places the estimate's first pose on the truth's (see Anchor).
  const Eigen::Isometry3d T_true_est = AnchorTransform(pairs.front().T_true_body, pairs.front().T_est_body, anchor);
  errors.T_true_est_anchor = T_true_est;
  errors.poses.reserve(pairs.size());
  double distance_m = 0.0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const AssociatedPose& pair = pairs[k];
    if (k > 0) distance_m += (true_positions[k] - true_positions[k - 1]).norm();
    PoseError e;
    e.time_s = pair.time_s;
    e.distance_m = distance_m;
    const Eigen::Isometry3d T_anchored = T_true_est * pair.T_est_body;
    e.p_true = true_positions[k];
    e.p_anchored = T_anchored.translation();
    e.p_aligned = errors.alignment.T_target_source * est_positions[k];
    e.position_error_m = e.p_anchored - e.p_true;
    // Rotation error as in the paper's pose-error figure (Fig. 8): log(q_est^-1 q_true).
    const Eigen::Quaterniond q_est(T_anchored.linear());
    const Eigen::Quaterniond q_true(pair.T_true_body.linear());
    e.rotation_error_rad = estimation::LogQ(q_est.conjugate() * q_true);
    errors.poses.push_back(e);
  }
  return errors;
}

}  // namespace unimap::eval
