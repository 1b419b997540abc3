#pragma once
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "Primitive.hpp"
#include "Ray.hpp"

namespace unimap::sim {

// A static world of primitives behind a bounding-volume hierarchy.
class World {
 public:
  World() = default;
  World(World&&) noexcept;
  World& operator=(World&&) noexcept;
  ~World();

  // Adds a primitive; call Build() after the last one.
  void Add(std::unique_ptr<Primitive> primitive);
  // Builds the acceleration structure (required before Cast/SurfaceDistance).
  void Build();

  // Nearest hit within (min_range_m, max_range_m], or nullopt.
  std::optional<RayHit> Cast(const Ray& ray, double min_range_m, double max_range_m) const;
  // Distance from p to the nearest surface.
  double SurfaceDistance(const Eigen::Vector3d& p) const;

  std::size_t size() const { return primitives_.size(); }
  const Primitive& primitive(std::size_t i) const { return *primitives_[i]; }
  Eigen::AlignedBox3d Bounds() const;

 private:
  struct Node;
  std::vector<std::unique_ptr<Primitive>> primitives_;
  std::vector<Node> nodes_;            // BVH, root at 0
  std::vector<int> ordered_;           // primitive indices in leaf order
};

}  // namespace unimap::sim
