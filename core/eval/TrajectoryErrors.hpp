#pragma once
// Per-pose errors of an associated estimate against the truth (the series
// behind the metrics and the paper's error plots; docs/evaluation.md).
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "eval/TrajectoryAssociation.hpp"
#include "eval/UmeyamaAlignment.hpp"

namespace unimap::eval {

// How the estimate is placed in the truth frame for the start-anchored errors.
enum class Anchor {
  kYawPosition,  // T_anch(k) = T_0 T_est(k) with T_0 a rotation about z and a translation taking
                 // the estimate's first position and heading onto the truth's: for estimates
                 // whose world frame is gravity-aligned (z up), like every unimap trajectory;
                 // the initial tilt estimate stays part of the error, as in the paper's plots
  kFullPose,     // T_anch(k) = T_true(0) T_est(0)^-1 T_est(k): the first poses coincide exactly
                 // (for estimates in an arbitrary frame); an initial tilt error then tilts the
                 // whole trajectory
};

// Errors at one associated time. "Anchored" is the estimate expressed in the
// truth frame so that it starts from the truth's first associated pose (see
// Anchor; no fitting).
struct PoseError {
  double time_s = 0.0;                               // estimate time stamp
  double distance_m = 0.0;                           // truth distance travelled since the first pair (along the pairs)
  Eigen::Vector3d p_true = Eigen::Vector3d::Zero();  // truth position, truth frame
  Eigen::Vector3d p_anchored = Eigen::Vector3d::Zero();          // anchored estimate position, truth frame
  Eigen::Vector3d p_aligned = Eigen::Vector3d::Zero();           // Umeyama-aligned estimate position, truth frame
  Eigen::Vector3d position_error_m = Eigen::Vector3d::Zero();    // p_anchored - p_true, truth-frame axes
  Eigen::Vector3d rotation_error_rad = Eigen::Vector3d::Zero();  // log(q_anch^-1 q_true) as a rotation vector
};

// The error series and the alignment used for the ATE.
struct TrajectoryErrors {
  std::vector<PoseError> poses;                                         // one per associated pair, same order
  RigidAlignment alignment;                                             // estimate positions onto truth positions (ATE)
  Eigen::Isometry3d T_true_est_anchor = Eigen::Isometry3d::Identity();  // the start anchor (AnchorTransform)
  std::optional<SimilarityAlignment> similarity;  // the same with scale (empty: no positive scale)
};

// Computes every PoseError; requires at least one pair (throws InputError otherwise).
TrajectoryErrors ComputeTrajectoryErrors(const TrajectoryAssociation& association,
                                         Anchor anchor = Anchor::kYawPosition);

// The transform T_true_est placing the estimate's frame in the truth's from
// the first poses of both (see Anchor).
Eigen::Isometry3d AnchorTransform(const Eigen::Isometry3d& T_true_first, const Eigen::Isometry3d& T_est_first,
                                  Anchor anchor);

}  // namespace unimap::eval
