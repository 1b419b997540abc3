#pragma once
#include <Eigen/Geometry>

namespace unimap {

// The body pose in the map frame at a time.
struct StampedPose {
  double time_s = 0.0;
  Eigen::Isometry3d T_map_body = Eigen::Isometry3d::Identity();
};

}  // namespace unimap
