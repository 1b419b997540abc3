#pragma once
#include <Eigen/Core>

namespace unimap::sim {

// A ray in the world frame: the points origin + range * direction for
// range >= 0. direction must be unit length (ranges are then metres).
struct Ray {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();      // start point, world frame (m)
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  // unit direction, world frame
};

// Where a ray first meets a surface.
struct RayHit {
  double range_m = 0.0;  // distance along the ray (m)
  Eigen::Vector3d normal =
      Eigen::Vector3d::UnitZ();  // unit surface normal at the hit, facing against the ray (normal . direction <= 0)
  int primitive_index = -1;      // which primitive of the world (set by World::Cast; -1 from Primitive::Intersect)
};

}  // namespace unimap::sim
