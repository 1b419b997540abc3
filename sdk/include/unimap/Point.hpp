#pragma once
#include <cstdint>

#include <Eigen/Core>

namespace unimap {

// One LiDAR return.
struct Point {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  // in the frame the container names
  double time_s = 0.0;                                   // absolute time the return was measured
  float intensity = 0.0f;                                // sensor-specific units
  std::uint16_t ring = 0;                                // beam / ring index (0 for single-beam scanners)
};

}  // namespace unimap
