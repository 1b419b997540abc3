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
