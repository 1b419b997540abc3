#pragma once
// Pairs each estimated pose with the ground truth at the same time.
#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

#include "unimap/StampedPose.hpp"

namespace unimap::eval {

// How estimate times are matched to the truth.
struct AssociationOptions {
  // Both truth samples bracketing an estimate time must lie within this many
  // seconds of it (an exact hit counts as both); otherwise the pose is skipped.
  double max_time_diff_s = 0.1;
};

// One estimate pose and the truth interpolated at its time.
struct AssociatedPose {
  double time_s = 0.0;                                            // the estimate's time stamp
  Eigen::Isometry3d T_est_body = Eigen::Isometry3d::Identity();   // estimate, its own map frame
  Eigen::Isometry3d T_true_body = Eigen::Isometry3d::Identity();  // truth (lerp / slerp), truth frame
};

// Result of AssociateTrajectories.
struct TrajectoryAssociation {
  std::vector<AssociatedPose> pairs;     // in estimate order, times non-decreasing
  std::vector<StampedPose> truth_span;   // truth over [first, last] pair time, ends interpolated
  std::size_t skipped_outside_span = 0;  // estimate poses before the first / after the last truth sample
  std::size_t skipped_in_gap = 0;        // estimate poses whose bracketing truth samples are too far
  // All skipped estimate poses.
  std::size_t skipped() const { return skipped_outside_span + skipped_in_gap; }
};

// Associates estimate poses with the truth (linear position, slerp rotation
// between the bracketing truth samples). Never throws for a lack of overlap
// (pairs is then short or empty); throws InputError naming "estimate" or
// "truth" and the pose index for a non-finite time or pose, a time going
// backwards, or a non-positive / non-finite max_time_diff_s.
TrajectoryAssociation AssociateTrajectories(const std::vector<StampedPose>& estimate,
                                            const std::vector<StampedPose>& truth,
                                            const AssociationOptions& options = {});

// Pose between a (at time ta) and b (at tb > ta) at time t: position linearly
// interpolated, rotation slerped along the shorter arc. t == ta gives a exactly.
Eigen::Isometry3d InterpolatePose(const StampedPose& a, const StampedPose& b, double time_s);

}  // namespace unimap::eval
