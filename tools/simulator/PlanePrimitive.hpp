#pragma once
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "Primitive.hpp"

namespace unimap::sim {

// A bounded, two-sided planar rectangle: the plane is z = 0 of its own frame,
// the rectangle |x| <= lx / 2, |y| <= ly / 2 there (a wall, a floor, a
// ceiling without thickness).
class PlanePrimitive final : public Primitive {
 public:
  // center_m: rectangle center (world); size_m: (lx, ly) > 0 and finite;
  // R_world_plane: orientation (third column = plane normal). Throws
  // std::invalid_argument otherwise.
  PlanePrimitive(const Eigen::Vector3d& center_m, const Eigen::Vector2d& size_m,
                 const Eigen::Matrix3d& R_world_plane = Eigen::Matrix3d::Identity());

  std::optional<RayHit> Intersect(const Ray& ray, double min_range_m, double max_range_m) const override;
  // Exact: distance to the nearest point of the rectangle (in the plane frame,
  // the point clamped to the rectangle with z = 0).
  double SurfaceDistance(const Eigen::Vector3d& p) const override;
  Eigen::AlignedBox3d Bounds() const override;
  std::string Kind() const override { return "plane"; }

  const Eigen::Vector3d& center() const { return center_; }
  // Full side lengths (lx, ly).
  Eigen::Vector2d size() const { return 2.0 * half_; }
  // Unit normal (the plane frame's z axis in the world).
  Eigen::Vector3d normal() const { return R_world_plane_.col(2); }

 private:
  Eigen::Vector3d center_;         // rectangle center, world frame
  Eigen::Vector2d half_;           // half side lengths, plane frame
  Eigen::Matrix3d R_world_plane_;  // plane axes in the world
  Eigen::Matrix3d R_plane_world_;  // its transpose, cached
};

}  // namespace unimap::sim
