#pragma once
// Shared checks for the primitive tests: analytic ray hits against a
// brute-force inside/outside march along the ray.
#include <cmath>
#include <functional>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "Primitive.hpp"
#include "Ray.hpp"

namespace unimap::sim::test {

// A uniformly random unit vector.
inline Eigen::Vector3d RandomDirection(std::mt19937* rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Vector3d d(normal(*rng), normal(*rng), normal(*rng));
  return d.normalized();
}

// A uniformly random point of a box.
inline Eigen::Vector3d RandomPoint(const Eigen::AlignedBox3d& box, std::mt19937* rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  return box.min() + Eigen::Vector3d(unit(*rng), unit(*rng), unit(*rng)).cwiseProduct(box.sizes());
}

// Ray i from a random point of `origins`: even i aim at a random point of
// `targets` (so that many hit), odd i point in a random direction.
inline Ray RandomRay(const Eigen::AlignedBox3d& origins, const Eigen::AlignedBox3d& targets, int i, std::mt19937* rng) {
  Ray ray;
  ray.origin = RandomPoint(origins, rng);
  const Eigen::Vector3d toward = RandomPoint(targets, rng) - ray.origin;
  ray.direction = i % 2 == 0 && toward.norm() > 1e-9 ? toward.normalized() : RandomDirection(rng);
  return ray;
}

// What a march check saw.
struct MarchStats {
  int hits_from_outside = 0;  // rays starting outside that hit
  int hits_from_inside = 0;   // rays starting inside (all must hit)
};

// For `rays` random rays (RandomRay, targets = the primitive's bounds) with origins in `origins`: Intersect(ray, 0,
// max_range) must agree with a march of the inside test at step 1e-3 m (no status change before the hit, a change
// across it, none at all on a miss); the hit point must lie on the surface (SurfaceDistance < 1e-9), and the normal
// must be unit length, face against the ray and separate inside from outside.
inline MarchStats ExpectHitsMatchInsideMarch(const Primitive& primitive,
                                             const std::function<bool(const Eigen::Vector3d&)>& inside,
                                             const Eigen::AlignedBox3d& origins, int rays, unsigned seed) {
  constexpr double kMaxRange = 20.0;
  constexpr double kStep = 1e-3;
  std::mt19937 rng(seed);
  MarchStats stats;
  for (int r = 0; r < rays; ++r) {
    const Ray ray = RandomRay(origins, primitive.Bounds(), r, &rng);
    const auto at = [&](double t) -> Eigen::Vector3d { return ray.origin + t * ray.direction; };
    const auto hit = primitive.Intersect(ray, 0.0, kMaxRange);
    const bool start_inside = inside(ray.origin);
    const double march_end = hit ? hit->range_m - 1e-6 : kMaxRange;
    bool changed = false;
    for (double t = kStep; t < march_end; t += kStep) {
      if (inside(at(t)) != start_inside) {
        changed = true;
        break;
      }
    }
    EXPECT_FALSE(changed) << "ray " << r << ": a crossing before " << march_end << " was missed";
    if (!hit) continue;
    ++(start_inside ? stats.hits_from_inside : stats.hits_from_outside);
    const Eigen::Vector3d p = at(hit->range_m);
    EXPECT_GT(hit->range_m, 0.0);
    EXPECT_LT(primitive.SurfaceDistance(p), 1e-9) << "ray " << r;
    EXPECT_NEAR(hit->normal.norm(), 1.0, 1e-12) << "ray " << r;
    EXPECT_LE(hit->normal.dot(ray.direction), 0.0) << "ray " << r;
    EXPECT_NE(inside(at(hit->range_m - 1e-7)), inside(at(hit->range_m + 1e-7))) << "ray " << r;
    EXPECT_NE(inside(p + 1e-7 * hit->normal), inside(p - 1e-7 * hit->normal)) << "ray " << r;
    EXPECT_EQ(hit->primitive_index, -1);
  }
  return stats;
}

}  // namespace unimap::sim::test
