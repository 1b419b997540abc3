#include "PlanePrimitive.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace unimap::sim {

PlanePrimitive::PlanePrimitive(const Eigen::Vector3d& center_m, const Eigen::Vector2d& size_m,
                               const Eigen::Matrix3d& R_world_plane)
    : center_(center_m), half_(0.5 * size_m), R_world_plane_(R_world_plane), R_plane_world_(R_world_plane.transpose()) {
  if (!center_m.allFinite() || !size_m.allFinite() || (size_m.array() <= 0.0).any()) {
    throw std::invalid_argument("PlanePrimitive: center and size must be finite, size > 0");
  }
  if (!R_world_plane.allFinite() || !(R_world_plane.transpose() * R_world_plane).isIdentity(1e-9)) {
    throw std::invalid_argument("PlanePrimitive: orientation must be a rotation matrix");
  }
}

std::optional<RayHit> PlanePrimitive::Intersect(const Ray& ray, double min_range_m, double max_range_m) const {
  // In the plane frame the ray meets z = 0 at t = -o_z / d_z.
  const Eigen::Vector3d o = R_plane_world_ * (ray.origin - center_);
  const double dz = R_plane_world_.row(2).dot(ray.direction);
  if (dz == 0.0) return std::nullopt;  // parallel (a ray inside the plane sees no area)
  const double t = -o.z() / dz;
  if (!(t > min_range_m) || t > max_range_m) return std::nullopt;
  const double x = o.x() + t * R_plane_world_.row(0).dot(ray.direction);
  const double y = o.y() + t * R_plane_world_.row(1).dot(ray.direction);
  if (std::abs(x) > half_.x() || std::abs(y) > half_.y()) return std::nullopt;
  RayHit hit;
  hit.range_m = t;
  hit.normal = (dz > 0.0 ? -1.0 : 1.0) * R_world_plane_.col(2);
  return hit;
}

double PlanePrimitive::SurfaceDistance(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d q = R_plane_world_ * (p - center_);
  const double dx = std::max(std::abs(q.x()) - half_.x(), 0.0);
  const double dy = std::max(std::abs(q.y()) - half_.y(), 0.0);
  return std::sqrt(dx * dx + dy * dy + q.z() * q.z());
}

Eigen::AlignedBox3d PlanePrimitive::Bounds() const {
  // Half extent along world axis j: |R_j0| hx + |R_j1| hy.
  const Eigen::Vector3d extent =
      R_world_plane_.col(0).cwiseAbs() * half_.x() + R_world_plane_.col(1).cwiseAbs() * half_.y();
  return Eigen::AlignedBox3d(center_ - extent, center_ + extent);
}

}  // namespace unimap::sim
