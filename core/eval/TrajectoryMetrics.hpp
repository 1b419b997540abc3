#pragma once
// Summary numbers of one trajectory evaluation (definitions and formulas in
// docs/evaluation.md; the JSON keys are the field names).
#include <cstddef>
#include <optional>

#include <Eigen/Core>

#include "eval/RelativePoseError.hpp"
#include "eval/TrajectoryAssociation.hpp"
#include "eval/TrajectoryErrors.hpp"

namespace unimap::eval {

// Angles in degrees, lengths in metres. Optionals are empty when undefined
// (path length zero, or shorter than one RPE segment); they are never zero-filled.
struct TrajectoryMetrics {
  double ate_rmse_m = 0.0;                 // RMSE of positions after SE(3) Umeyama alignment (no scale)
  std::optional<double> trajectory_scale;  // the estimate's size relative to the truth's: 1 / c of the
                                           // Sim(3) Umeyama alignment (< 1: travel under-estimated);
                                           // empty when the estimate or the truth does not move
  double path_length_m = 0.0;              // truth path length over the associated time span
  std::optional<double> drift_percent;     // 100 |e_p(last)| / path_length_m, start-anchored
  Eigen::Vector3d max_abs_error_m = Eigen::Vector3d::Zero();         // max_k |e_p(k)| per axis x, y, z
  Eigen::Vector3d mean_abs_rot_error_deg = Eigen::Vector3d::Zero();  // mean_k |e_R(k)| per component (roll, pitch, yaw)
  std::optional<double> rot_drift_deg_per_m;                         // |e_R(last)| / path_length_m
  std::optional<double> rpe_trans_percent;                           // mean relative translation error per segment, %
  std::optional<double> rpe_rot_deg_per_m;                           // mean relative rotation error per segment, deg/m
  std::size_t rpe_segments = 0;                                      // segments averaged by the two rpe_* values
  double final_position_error_m = 0.0;                               // |e_p(last)|
  double final_rot_error_deg = 0.0;                                  // |e_R(last)|
  std::size_t poses_associated = 0;                                  // estimate poses with a truth partner
  std::size_t poses_skipped = 0;                                     // estimate poses without one (outside span + gaps)
  std::size_t poses_outside_truth_span = 0;                          // skipped: before / after the truth
  std::size_t poses_in_truth_gaps = 0;                               // skipped: truth samples too far from the time
  double duration_s = 0.0;                                           // last minus first associated time
  double max_time_diff_s = 0.0;                                      // association tolerance used
  double segment_m = 0.0;                                            // RPE segment length used
};

// Summarises an association and its error series (both from the same pairs,
// at least one). segment_m: RPE segment length (> 0). max_time_diff_s is only
// recorded. Throws InputError on mismatched or empty inputs.
TrajectoryMetrics ComputeTrajectoryMetrics(const TrajectoryAssociation& association, const TrajectoryErrors& errors,
                                           double max_time_diff_s, double segment_m);

}  // namespace unimap::eval
