#pragma once
#include <vector>

#include <Eigen/Core>

#include "World.hpp"

namespace unimap::sim {

// How densely SurfaceSampler looks at the world.
struct SurfaceSamplerOptions {
  int directions_per_viewpoint = 20000;  // rays per viewpoint, a Fibonacci sphere (>= 1)
  double min_range_m = 0.0;              // hits at or below this range are ignored (>= 0)
  double max_range_m = 30.0;             // rays end here (> min_range_m, finite)
  double voxel_m = 0.05;                 // one point is kept per voxel of this edge (> 0)
  unsigned threads = 0;                  // worker threads (0: the hardware's concurrency)
};

// The world's surfaces as seen from a set of viewpoints: noise-free rays
// (World::Cast) from every viewpoint in every direction of a Fibonacci
// sphere, keeping the hit points, one per voxel. The result is deterministic
// and independent of the thread count: of the hits falling in one voxel the
// first in (viewpoint, direction) order is kept, and points come out in that
// order. Every point lies exactly on a surface (origin + range * direction).
class SurfaceSampler {
 public:
  // Keeps a reference to world (built, outliving the sampler). Throws
  // std::invalid_argument for options out of range.
  SurfaceSampler(const World& world, SurfaceSamplerOptions options);

  // Surface points (world frame) seen from the viewpoints (world frame).
  std::vector<Eigen::Vector3d> Sample(const std::vector<Eigen::Vector3d>& viewpoints) const;

  // n unit vectors spread evenly over the sphere (the golden-angle spiral):
  //   z_i = 1 - (2 i + 1) / n,  phi_i = i * pi (3 - sqrt 5),  d_i = (sqrt(1 - z_i^2) [cos phi_i, sin phi_i], z_i).
  static std::vector<Eigen::Vector3d> FibonacciSphere(int n);

  const SurfaceSamplerOptions& options() const { return options_; }

 private:
  const World& world_;                       // the surfaces
  SurfaceSamplerOptions options_;            // validated
  std::vector<Eigen::Vector3d> directions_;  // FibonacciSphere(directions_per_viewpoint)
};

}  // namespace unimap::sim
