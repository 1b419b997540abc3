#include "eval/MetricRows.hpp"

#include <cstdio>
#include <optional>

namespace unimap::eval {
namespace {

std::string Fixed(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.4f", value);
  std::string text = buffer;
  if (text == "-0.0000") text = "0.0000";
  return text;
}

std::string Optional(const std::optional<double>& value) { return value ? Fixed(*value) : "n/a"; }

std::string Vector(const Eigen::Vector3d& v) {
  return "[" + Fixed(v.x()) + ", " + Fixed(v.y()) + ", " + Fixed(v.z()) + "]";
}

}  // namespace

std::vector<MetricRow> DescribeMetrics(const TrajectoryMetrics& m) {
  return {
      {"ate_rmse_m", Fixed(m.ate_rmse_m), "position RMSE after SE(3) Umeyama alignment (no scale), m"},
      {"trajectory_scale", Optional(m.trajectory_scale),
       "estimate size / truth size (1 / scale of the Sim(3) Umeyama alignment); < 1: travel under-estimated"},
      {"path_length_m", Fixed(m.path_length_m), "truth path length over the associated span, m"},
      {"drift_percent", Optional(m.drift_percent), "100 x final position error / path length (start-anchored), %"},
      {"max_abs_error_m", Vector(m.max_abs_error_m), "max |position error| per axis [x, y, z] (start-anchored), m"},
      {"mean_abs_rot_error_deg", Vector(m.mean_abs_rot_error_deg),
       "mean |log(q_est^-1 q_true)| per component [roll, pitch, yaw], deg"},
      {"rot_drift_deg_per_m", Optional(m.rot_drift_deg_per_m), "final rotation error / path length, deg/m"},
      {"rpe_trans_percent", Optional(m.rpe_trans_percent),
       "mean relative translation error per segment / segment length, %"},
      {"rpe_rot_deg_per_m", Optional(m.rpe_rot_deg_per_m), "mean relative rotation error per segment length, deg/m"},
      {"rpe_segments", std::to_string(m.rpe_segments), "segments averaged for rpe_*"},
      {"final_position_error_m", Fixed(m.final_position_error_m), "|position error| at the last pose, m"},
      {"final_rot_error_deg", Fixed(m.final_rot_error_deg), "rotation error angle at the last pose, deg"},
      {"poses_associated", std::to_string(m.poses_associated), "estimate poses with interpolated truth"},
      {"poses_skipped", std::to_string(m.poses_skipped), "estimate poses without truth (next two rows)"},
      {"poses_outside_truth_span", std::to_string(m.poses_outside_truth_span),
       "skipped: before the first / after the last truth sample"},
      {"poses_in_truth_gaps", std::to_string(m.poses_in_truth_gaps),
       "skipped: bracketing truth samples further than max_time_diff_s"},
      {"duration_s", Fixed(m.duration_s), "last minus first associated time, s"},
      {"max_time_diff_s", Fixed(m.max_time_diff_s), "association tolerance, s"},
      {"segment_m", Fixed(m.segment_m), "RPE segment length (travelled distance), m"},
  };
}

}  // namespace unimap::eval
