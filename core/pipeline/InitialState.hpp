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
  estimation::NavState state;                           // at the window's last sample
  std::optional<estimation::InitialAttitude> attitude;  // the source used, when an initial pose was given
  std::vector<std::string> notes;                       // what the log should say (failed alignment, pose fallback)
  // The IMU's white noise measured at rest, when the window was static and
  // it exceeds the options' sigmas by more than kNoiseMargin (the platform
  // file claims a better IMU than the data shows): the filter's sigmas.
  std::optional<double> sigma_accel_m_s2;
  std::optional<double> sigma_gyro_rad_s;
  // The gyro bias's standard deviation per axis, as the static window
  // measured it (the standard error of its mean rate), when that is below
  // the options' initial_sigma_gyro_bias_rad_s: the filter's initial one.
  std::optional<Eigen::Vector3d> sigma_gyro_bias_rad_s;
  // A sample standard deviation of a 1 s window at 200 Hz varies by ~5 %:
  // more than this ratio is the IMU's, not chance.
  static constexpr double kNoiseMargin = 1.2;
};

// Roll, pitch and gyro bias from the (static) window (estimation::
// AlignFromStatic); level with zero biases when the window is not static
// enough. With initial_pose (T_map_body) the state is placed there
// (estimation::PlaceAtPose, options.initial_attitude). The IMU's noise at
// rest may replace the options' sigmas (see InitialState). window must not
// be empty.
InitialState InitialStateFromWindow(const std::vector<ImuSample>& window,
                                    const std::optional<Eigen::Isometry3d>& initial_pose,
                                    const LocalizerOptions& options);

}  // namespace unimap::pipeline
