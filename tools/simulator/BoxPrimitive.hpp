#pragma once
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "Primitive.hpp"

namespace unimap::sim {

// A closed oriented box (cuboid). Its surface is the six faces; a ray from
// inside leaves through a face, so a large box is a room.
class BoxPrimitive final : public Primitive {
 public:
  // center_m: box center (world); size_m: full edge lengths (lx, ly, lz) along
  // the box's own axes, each > 0 and finite; R_world_box: orientation (columns
  // are the box axes in the world). Throws std::invalid_argument otherwise.
  BoxPrimitive(const Eigen::Vector3d& center_m, const Eigen::Vector3d& size_m,
               const Eigen::Matrix3d& R_world_box = Eigen::Matrix3d::Identity());

  std::optional<RayHit> Intersect(const Ray& ray, double min_range_m, double max_range_m) const override;
  // Exact: outside, |max(|q| - h, 0)|; inside, min_i (h_i - |q_i|), with q the
  // point in the box frame and h the half sizes.
  double SurfaceDistance(const Eigen::Vector3d& p) const override;
  Eigen::AlignedBox3d Bounds() const override;
  std::string Kind() const override { return "box"; }

  const Eigen::Vector3d& center() const { return center_; }
  // Full edge lengths.
  Eigen::Vector3d size() const { return 2.0 * half_; }
  const Eigen::Matrix3d& rotation() const { return R_world_box_; }

 private:
  Eigen::Vector3d center_;       // box center, world frame
  Eigen::Vector3d half_;         // half edge lengths, box frame
  Eigen::Matrix3d R_world_box_;  // box axes in the world
  Eigen::Matrix3d R_box_world_;  // its transpose, cached
};

}  // namespace unimap::sim
