#pragma once
#include <string>

#include "Scenario.hpp"

namespace unimap::sim {

// A scenario made harder without editing its file (`unimap simulate
// --speed-scale --imu-noise-scale --imu-bias-scale`, the robustness matrix of
// `unimap bench --matrix`). The defaults leave a scenario unchanged.
struct ScenarioVariant {
  double speed_scale = 1.0;      // the same path, S times as fast: peak speed and yaw rate x S,
                                 // peak acceleration x S^2, dwells / S (the static start and the
                                 // wobble, the carrier's own sway, are kept)
  double imu_noise_scale = 1.0;  // IMU white noise (accelerometer and gyroscope) x K
  double imu_bias_scale = 1.0;   // IMU start biases and bias random walks x B

  // False (with the reason, naming the option, in *why) unless every scale is finite and > 0.
  bool IsValid(std::string* why) const;
  bool IsIdentity() const { return speed_scale == 1.0 && imu_noise_scale == 1.0 && imu_bias_scale == 1.0; }
  // "x2 speed, x2.5 IMU noise", or "nominal".
  std::string Describe() const;
};

// The scenario with the variant applied. Throws ConfigError naming the
// option when the variant is invalid.
Scenario ApplyVariant(Scenario scenario, const ScenarioVariant& variant);

}  // namespace unimap::sim
