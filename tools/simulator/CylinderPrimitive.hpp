#pragma once
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "Primitive.hpp"

namespace unimap::sim {

// A finite solid circular cylinder with closed caps: the points
// base + s * axis + radial offset with 0 <= s <= height, |offset| <= radius.
// Its surface is the side wall plus the two cap disks.
class CylinderPrimitive final : public Primitive {
 public:
  // base_m: center of the bottom cap (world); axis: direction from the bottom
  // to the top cap (normalised here; must be finite and non-zero); radius_m,
  // height_m: > 0 and finite. Throws std::invalid_argument otherwise.
  CylinderPrimitive(const Eigen::Vector3d& base_m, const Eigen::Vector3d& axis, double radius_m, double height_m);

  std::optional<RayHit> Intersect(const Ray& ray, double min_range_m, double max_range_m) const override;
  // Exact, with rho the distance from the axis line and s the height along it:
  // inside, min(radius - rho, s, height - s); outside,
  // sqrt(max(rho - radius, 0)^2 + max(-s, s - height, 0)^2).
  double SurfaceDistance(const Eigen::Vector3d& p) const override;
  Eigen::AlignedBox3d Bounds() const override;
  std::string Kind() const override { return "cylinder"; }

  const Eigen::Vector3d& base() const { return base_; }
  const Eigen::Vector3d& axis() const { return axis_; }
  double radius() const { return radius_; }
  double height() const { return height_; }

 private:
  Eigen::Vector3d base_;  // bottom cap center, world frame
  Eigen::Vector3d axis_;  // unit axis, bottom to top
  double radius_;         // m
  double height_;         // m
};

}  // namespace unimap::sim
