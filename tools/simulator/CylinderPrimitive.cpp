#include "CylinderPrimitive.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace unimap::sim {
namespace {

// Keeps the smallest candidate range t in (lo, hi] and its normal.
struct Nearest {
  double lo;                                         // exclusive lower range bound
  double hi;                                         // inclusive upper range bound, shrinks to the best so far
  bool found = false;                                // whether any candidate was accepted
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // outward normal of the best candidate

  void Offer(double t, const Eigen::Vector3d& outward_normal) {
    if (t > lo && t <= hi) {
      hi = t;
      found = true;
      normal = outward_normal;
    }
  }
};

}  // namespace

CylinderPrimitive::CylinderPrimitive(const Eigen::Vector3d& base_m, const Eigen::Vector3d& axis, double radius_m,
                                     double height_m)
    : base_(base_m), axis_(Eigen::Vector3d::UnitZ()), radius_(radius_m), height_(height_m) {
  const double axis_norm = axis.norm();
  if (!base_m.allFinite() || !axis.allFinite() || !(axis_norm > 0.0) || !std::isfinite(radius_m) ||
      !std::isfinite(height_m) || !(radius_m > 0.0) || !(height_m > 0.0)) {
    throw std::invalid_argument(
        "CylinderPrimitive: base and axis must be finite, axis non-zero, radius and height > 0");
  }
  axis_ = axis / axis_norm;
}

std::optional<RayHit> CylinderPrimitive::Intersect(const Ray& ray, double min_range_m, double max_range_m) const {
  // Split origin and direction into parts along the axis (s) and across it (_r).
  const Eigen::Vector3d o = ray.origin - base_;
  const double o_s = o.dot(axis_);
  const double d_s = ray.direction.dot(axis_);
  const Eigen::Vector3d o_r = o - o_s * axis_;
  const Eigen::Vector3d d_r = ray.direction - d_s * axis_;
  Nearest best{min_range_m, max_range_m};

  // Side wall: |o_r + t d_r|^2 = r^2, i.e. a t^2 + 2 b t + c = 0, with the
  // cancellation-free root pair t1 = q / a, t2 = c / q, q = -(b + sign(b) sqrt(b^2 - a c)).
  const double a = d_r.squaredNorm();
  const double b = o_r.dot(d_r);
  const double c = o_r.squaredNorm() - radius_ * radius_;
  const double discriminant = b * b - a * c;
  if (a > 0.0 && discriminant >= 0.0) {
    const double q = -(b + std::copysign(std::sqrt(discriminant), b));
    const double roots[2] = {q / a, q != 0.0 ? c / q : q / a};
    for (const double t : roots) {
      const double s = o_s + t * d_s;
      if (s >= 0.0 && s <= height_) best.Offer(t, (o_r + t * d_r) / radius_);
    }
  }
  // Caps: s = 0 (outward -axis) and s = height (outward +axis), inside the disk.
  if (d_s != 0.0) {
    for (const double cap_s : {0.0, height_}) {
      const double t = (cap_s - o_s) / d_s;
      if ((o_r + t * d_r).squaredNorm() <= radius_ * radius_) {
        best.Offer(t, cap_s == 0.0 ? Eigen::Vector3d(-axis_) : axis_);
      }
    }
  }
  if (!best.found) return std::nullopt;
  RayHit hit;
  hit.range_m = best.hi;
  const Eigen::Vector3d n = best.normal.normalized();
  hit.normal = n.dot(ray.direction) > 0.0 ? Eigen::Vector3d(-n) : n;
  return hit;
}

double CylinderPrimitive::SurfaceDistance(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d v = p - base_;
  const double s = v.dot(axis_);
  const double rho = (v - s * axis_).norm();
  const double radial_out = rho - radius_;
  const double axial_out = std::max(-s, s - height_);
  if (radial_out <= 0.0 && axial_out <= 0.0) return std::min(-radial_out, -axial_out);
  const double dr = std::max(radial_out, 0.0);
  const double ds = std::max(axial_out, 0.0);
  return std::sqrt(dr * dr + ds * ds);
}

Eigen::AlignedBox3d CylinderPrimitive::Bounds() const {
  // A disk of radius r with unit normal a spans r * sqrt(1 - a_j^2) along world axis j.
  const Eigen::Vector3d extent = radius_ * (Eigen::Vector3d::Ones() - axis_.cwiseAbs2()).cwiseMax(0.0).cwiseSqrt();
  const Eigen::Vector3d top = base_ + height_ * axis_;
  return Eigen::AlignedBox3d(base_.cwiseMin(top) - extent, base_.cwiseMax(top) + extent);
}

}  // namespace unimap::sim
