#pragma once
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "Ray.hpp"

namespace unimap::sim {

// A solid or surface of a simulated world with analytic ray intersection.
// Surfaces are seen from both sides (a box seen from inside is a room).
class Primitive {
 public:
  virtual ~Primitive() = default;
  // Nearest hit with range in (min_range_m, max_range_m], or nullopt.
  virtual std::optional<RayHit> Intersect(const Ray& ray, double min_range_m, double max_range_m) const = 0;
  // Euclidean distance from p to the primitive's surface (0 on it).
  virtual double SurfaceDistance(const Eigen::Vector3d& p) const = 0;
  // Axis-aligned bounds (for the acceleration structure).
  virtual Eigen::AlignedBox3d Bounds() const = 0;
  // "box", "plane", "cylinder", ...
  virtual std::string Kind() const = 0;
};

}  // namespace unimap::sim
