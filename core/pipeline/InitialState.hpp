#pragma once
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "estimation/NavState.hpp"
#include "estimation/StaticInitializer.hpp"
#include "pipeline/LocalizerOptions.hpp"
#include "unimap/ImuSample.hpp"

namespace unimap::pipeline {

// The filter's first state, from the IMU window at the start of the data.
struct InitialState {
  estimation::NavState state;  // at the window's last sample
  std::optional<estimation::InitialAttitude> attitude;  // the source used, when an initial pose was given
  std::vector<std::string> notes;  // what the log should say (failed alignment, pose fallback)
};

// Roll, pitch and gyro bias from the (static) window (estimation::
// AlignFromStatic); level with zero biases when the window is not static
// enough. With initial_pose (T_map_body) the state is placed there
// (estimation::PlaceAtPose, options.initial_attitude). window must not be
// empty.
InitialState InitialStateFromWindow(const std::vector<ImuSample>& window,
                                    const std::optional<Eigen::Isometry3d>& initial_pose,
                                    const LocalizerOptions& options);

}  // namespace unimap::pipeline
