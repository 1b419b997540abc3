#pragma once
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "Ray.hpp"

namespace unimap::sim {

// A solid or surface of a simulated world with analytic ray intersection.
// Surfaces are seen from both sides: a ray starting inside a closed solid
// (box, cylinder, sphere) hits its boundary on the way out, so a box seen
// from inside is a room. Implementations are immutable after construction
// and safe to query from several threads.
class Primitive {
 public:
  virtual ~Primitive() = default;
  // Nearest crossing of the surface with range in (min_range_m, max_range_m],
  // or nullopt. ray.direction must be unit length. The returned normal is unit
  // length and faces against the ray; primitive_index is left at -1.
  virtual std::optional<RayHit> Intersect(const Ray& ray, double min_range_m, double max_range_m) const = 0;
  // Euclidean distance from p to the primitive's surface (0 on it; for a
  // solid, the distance to its boundary from inside as well as outside).
  // Exact for every primitive except where a class documents a bound.
  virtual double SurfaceDistance(const Eigen::Vector3d& p) const = 0;
  // Axis-aligned box containing the whole surface (for the BVH).
  virtual Eigen::AlignedBox3d Bounds() const = 0;
  // "box", "plane", "cylinder", "sphere", "heightfield".
  virtual std::string Kind() const = 0;
};

}  // namespace unimap::sim
