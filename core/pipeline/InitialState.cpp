#include "pipeline/InitialState.hpp"

#include <cassert>

namespace unimap::pipeline {

InitialState InitialStateFromWindow(const std::vector<ImuSample>& window,
                                    const std::optional<Eigen::Isometry3d>& initial_pose,
                                    const LocalizerOptions& options) {
  assert(!window.empty());
  estimation::StaticAlignmentOptions align_options;
  align_options.min_samples = 2;
  const estimation::StaticAlignment alignment = estimation::AlignFromStatic(window, align_options);
  InitialState out;
  out.state.time_s = window.back().time_s;
  if (alignment.ok) {
    out.state.q_world_body = alignment.q_world_body;
    out.state.gyro_bias_rad_s = alignment.gyro_bias_rad_s;
    out.sigma_gyro_bias_rad_s =
        alignment.gyro_bias_std_rad_s.cwiseMin(options.eskf.initial_sigma_gyro_bias_rad_s).eval();
    // Along gravity the accelerometer's bias is what the specific force at
    // rest exceeds gravity by (across it, bias and tilt cannot be told apart).
    const Eigen::Vector3d up_body = alignment.mean_specific_force_m_s2.normalized();
    out.state.accel_bias_m_s2 = (alignment.gravity_m_s2 - options.eskf.gravity_m_s2) * up_body;
    if (alignment.accel_std_m_s2 > InitialState::kNoiseMargin * options.eskf.sigma_accel_m_s2) {
      out.sigma_accel_m_s2 = alignment.accel_std_m_s2;
    }
    if (alignment.gyro_std_rad_s > InitialState::kNoiseMargin * options.eskf.sigma_gyro_rad_s) {
      out.sigma_gyro_rad_s = alignment.gyro_std_rad_s;
    }
    if (out.sigma_accel_m_s2 || out.sigma_gyro_rad_s) {
      out.notes.push_back("IMU noise measured at rest: accelerometer " + std::to_string(alignment.accel_std_m_s2) +
                          " m/s^2, gyroscope " + std::to_string(alignment.gyro_std_rad_s) +
                          " rad/s per sample, above the platform's sigma_accel_m_s2 " +
                          std::to_string(options.eskf.sigma_accel_m_s2) + " / sigma_gyro_rad_s " +
                          std::to_string(options.eskf.sigma_gyro_rad_s) + ": the filter uses the larger ones");
    }
  } else {
    out.notes.push_back("initial alignment: " + alignment.reason +
                        (initial_pose ? "; attitude from the given pose" : "; starting level"));
  }
  if (initial_pose) {
    const estimation::PoseStart start =
        estimation::PlaceAtPose(alignment, *initial_pose, options.initial_attitude, options.eskf.gravity_m_s2,
                                options.max_initial_accel_bias_m_s2, &out.state);
    out.attitude = start.attitude;
    if (!start.note.empty()) out.notes.push_back("initial pose: " + start.note);
  }
  return out;
}

}  // namespace unimap::pipeline
