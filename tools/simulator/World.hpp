#pragma once
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "Primitive.hpp"
#include "Ray.hpp"

namespace unimap::sim {

// A static world of primitives behind a bounding-volume hierarchy (BVH):
// surface-area-heuristic splits, a flattened depth-first node array, and
// iterative traversal that visits the nearer child first and skips nodes
// beyond the best hit (Cast) or the best distance (SurfaceDistance).
// After Build() the world is immutable; Cast and SurfaceDistance are
// const and thread-safe.
class World {
 public:
  World();
  World(World&&) noexcept;
  World& operator=(World&&) noexcept;
  ~World();

  // Adds a primitive (non-null; std::invalid_argument otherwise). Its index
  // (as reported in RayHit::primitive_index) is the number added before it.
  // Invalidates the BVH: call Build() after the last one.
  void Add(std::unique_ptr<Primitive> primitive);
  // Builds the BVH over the primitives' bounds. An empty world is valid.
  void Build();
  // True once Build() has run after the last Add().
  bool built() const { return built_; }

  // Nearest hit over all primitives within (min_range_m, max_range_m], or
  // nullopt; ray.direction must be unit length. Throws std::logic_error when
  // the world is not built.
  std::optional<RayHit> Cast(const Ray& ray, double min_range_m, double max_range_m) const;
  // Distance from p to the nearest surface (the minimum of the primitives'
  // SurfaceDistance); +infinity for an empty world. Throws std::logic_error
  // when the world is not built.
  double SurfaceDistance(const Eigen::Vector3d& p) const;

  std::size_t size() const { return primitives_.size(); }
  // The i-th primitive added, i < size().
  const Primitive& primitive(std::size_t i) const { return *primitives_[i]; }
  // Union of the primitives' bounds (empty box for an empty world).
  Eigen::AlignedBox3d Bounds() const;

 private:
  struct Node;
  // Appends the subtree over ordered_[begin, end) and returns its node index.
  int BuildNode(int begin, int end, int depth, const std::vector<Eigen::AlignedBox3d>& bounds);

  std::vector<std::unique_ptr<Primitive>> primitives_;  // in insertion order
  std::vector<Node> nodes_;                             // BVH, root at 0, depth-first (left child = parent + 1)
  std::vector<int> ordered_;                            // primitive indices in leaf order
  std::vector<const Primitive*> ordered_primitives_;    // primitives_[ordered_[i]], for traversal
  bool built_ = true;                                   // an empty world needs no Build()
};

}  // namespace unimap::sim
