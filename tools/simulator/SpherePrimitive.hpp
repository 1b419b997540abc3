#pragma once
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "Primitive.hpp"

namespace unimap::sim {

// A solid ball; its surface is the sphere |p - center| = radius.
class SpherePrimitive final : public Primitive {
 public:
  // center_m finite, radius_m > 0 and finite; throws std::invalid_argument otherwise.
  SpherePrimitive(const Eigen::Vector3d& center_m, double radius_m);

  std::optional<RayHit> Intersect(const Ray& ray, double min_range_m, double max_range_m) const override;
  // Exact: | |p - center| - radius |.
  double SurfaceDistance(const Eigen::Vector3d& p) const override;
  Eigen::AlignedBox3d Bounds() const override;
  std::string Kind() const override { return "sphere"; }

  const Eigen::Vector3d& center() const { return center_; }
  double radius() const { return radius_; }

 private:
  Eigen::Vector3d center_;  // world frame
  double radius_;           // m
};

}  // namespace unimap::sim
