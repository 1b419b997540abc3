#include "SpherePrimitive.hpp"

#include <cmath>
#include <stdexcept>

namespace unimap::sim {

SpherePrimitive::SpherePrimitive(const Eigen::Vector3d& center_m, double radius_m)
    : center_(center_m), radius_(radius_m) {
  if (!center_m.allFinite() || !std::isfinite(radius_m) || !(radius_m > 0.0)) {
    throw std::invalid_argument("SpherePrimitive: center must be finite and radius > 0");
  }
}

std::optional<RayHit> SpherePrimitive::Intersect(const Ray& ray, double min_range_m, double max_range_m) const {
  // |o + t d|^2 = r^2 with |d| = 1: t^2 + 2 b t + c = 0, b = o.d, c = |o|^2 - r^2.
  // Roots from the closest-approach form t = -b -+ sqrt(r^2 - |o + (-b) d|^2),
  // which keeps its accuracy for distant spheres.
  const Eigen::Vector3d o = ray.origin - center_;
  const double b = o.dot(ray.direction);
  const double miss2 = (o - b * ray.direction).squaredNorm();  // squared closest-approach distance
  const double h2 = radius_ * radius_ - miss2;
  if (h2 < 0.0) return std::nullopt;
  const double h = std::sqrt(h2);
  double t = -b - h;                   // the entry point
  if (!(t > min_range_m)) t = -b + h;  // from inside (or behind): the exit point
  if (!(t > min_range_m) || t > max_range_m) return std::nullopt;
  RayHit hit;
  hit.range_m = t;
  const Eigen::Vector3d n = (o + t * ray.direction) / radius_;
  hit.normal = (n.dot(ray.direction) > 0.0 ? Eigen::Vector3d(-n) : n).normalized();
  return hit;
}

double SpherePrimitive::SurfaceDistance(const Eigen::Vector3d& p) const {
  return std::abs((p - center_).norm() - radius_);
}

Eigen::AlignedBox3d SpherePrimitive::Bounds() const {
  const Eigen::Vector3d r = Eigen::Vector3d::Constant(radius_);
  return Eigen::AlignedBox3d(center_ - r, center_ + r);
}

}  // namespace unimap::sim
