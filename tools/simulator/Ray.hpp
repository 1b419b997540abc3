#pragma once
#include <Eigen/Core>

namespace unimap::sim {

// A ray in the world frame: origin + range * direction, direction unit length.
struct Ray {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
};

// Where a ray first meets a surface.
struct RayHit {
  double range_m = 0.0;                               // distance along the ray
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // surface normal at the hit, unit length
  int primitive_index = -1;                           // which primitive of the world
};

}  // namespace unimap::sim
