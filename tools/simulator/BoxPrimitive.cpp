#include "BoxPrimitive.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace unimap::sim {

BoxPrimitive::BoxPrimitive(const Eigen::Vector3d& center_m, const Eigen::Vector3d& size_m,
                           const Eigen::Matrix3d& R_world_box)
    : center_(center_m), half_(0.5 * size_m), R_world_box_(R_world_box), R_box_world_(R_world_box.transpose()) {
  if (!center_m.allFinite() || !size_m.allFinite() || (size_m.array() <= 0.0).any()) {
    throw std::invalid_argument("BoxPrimitive: center and size must be finite, size > 0");
  }
  if (!R_world_box.allFinite() || !(R_world_box.transpose() * R_world_box).isIdentity(1e-9)) {
    throw std::invalid_argument("BoxPrimitive: orientation must be a rotation matrix");
  }
}

std::optional<RayHit> BoxPrimitive::Intersect(const Ray& ray, double min_range_m, double max_range_m) const {
  // Slab method in the box frame: the ray is inside slab i for t between
  // (-h_i - o_i) / d_i and (h_i - o_i) / d_i; inside the box on the
  // intersection of the three intervals [t_enter, t_exit].
  const Eigen::Vector3d o = R_box_world_ * (ray.origin - center_);
  const Eigen::Vector3d d = R_box_world_ * ray.direction;
  double t_enter = -std::numeric_limits<double>::infinity();
  double t_exit = std::numeric_limits<double>::infinity();
  int enter_axis = -1;
  int exit_axis = -1;
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0.0) {  // parallel to slab i: inside it for all t or never
      if (std::abs(o[i]) > half_[i]) return std::nullopt;
      continue;
    }
    const double inv = 1.0 / d[i];
    double t0 = (-half_[i] - o[i]) * inv;
    double t1 = (half_[i] - o[i]) * inv;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > t_enter) {
      t_enter = t0;
      enter_axis = i;
    }
    if (t1 < t_exit) {
      t_exit = t1;
      exit_axis = i;
    }
  }
  if (enter_axis < 0 || t_enter > t_exit) return std::nullopt;
  double t = 0.0;
  int axis = -1;
  if (t_enter > min_range_m) {  // from outside: the entry face
    t = t_enter;
    axis = enter_axis;
  } else if (t_exit > min_range_m) {  // from inside: the exit face
    t = t_exit;
    axis = exit_axis;
  } else {
    return std::nullopt;
  }
  if (t > max_range_m) return std::nullopt;
  RayHit hit;
  hit.range_m = t;
  // The face normal on axis i is +-e_i; the one facing the ray is -sign(d_i) e_i.
  hit.normal = (d[axis] > 0.0 ? -1.0 : 1.0) * R_world_box_.col(axis);
  return hit;
}

double BoxPrimitive::SurfaceDistance(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d q = (R_box_world_ * (p - center_)).cwiseAbs();
  const Eigen::Vector3d outside = (q - half_).cwiseMax(0.0);
  if ((outside.array() > 0.0).any()) return outside.norm();
  return (half_ - q).minCoeff();
}

Eigen::AlignedBox3d BoxPrimitive::Bounds() const {
  // Half extent along world axis j: sum_i |R_ji| h_i.
  const Eigen::Vector3d extent = R_world_box_.cwiseAbs() * half_;
  return Eigen::AlignedBox3d(center_ - extent, center_ + extent);
}

}  // namespace unimap::sim
