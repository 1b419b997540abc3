#include "PlanePrimitive.hpp"

#include <cmath>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "PrimitiveTestSupport.hpp"

namespace unimap::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

Ray MakeRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) {
  return Ray{origin, direction.normalized()};
}

// Horizontal 4 m x 2 m rectangle at z = 1 centred on x = y = 0.
PlanePrimitive Floor() { return PlanePrimitive({0, 0, 1}, {4, 2}); }

TEST(PlanePrimitive, HitFromEitherSideWithNormalTowardTheRay) {
  const PlanePrimitive floor = Floor();
  const auto from_above = floor.Intersect(MakeRay({1, 0.5, 5}, {0, 0, -1}), 0.0, 100.0);
  ASSERT_TRUE(from_above.has_value());
  EXPECT_NEAR(from_above->range_m, 4.0, 1e-12);
  EXPECT_TRUE(from_above->normal.isApprox(Eigen::Vector3d(0, 0, 1), 1e-12));
  const auto from_below = floor.Intersect(MakeRay({1, 0.5, -2}, {0, 0, 1}), 0.0, 100.0);
  ASSERT_TRUE(from_below.has_value());
  EXPECT_NEAR(from_below->range_m, 3.0, 1e-12);
  EXPECT_TRUE(from_below->normal.isApprox(Eigen::Vector3d(0, 0, -1), 1e-12));
  // Slanted: from (0, 0, 3) toward (1.5, 0, 1): range sqrt(1.5^2 + 2^2) = 2.5.
  const auto slanted = floor.Intersect(MakeRay({0, 0, 3}, {1.5, 0, -2}), 0.0, 100.0);
  ASSERT_TRUE(slanted.has_value());
  EXPECT_NEAR(slanted->range_m, 2.5, 1e-12);
}

TEST(PlanePrimitive, MissesOutsideTheRectangleAndWhenParallel) {
  const PlanePrimitive floor = Floor();
  EXPECT_FALSE(floor.Intersect(MakeRay({2.1, 0, 5}, {0, 0, -1}), 0.0, 100.0));
  EXPECT_FALSE(floor.Intersect(MakeRay({0, 1.1, 5}, {0, 0, -1}), 0.0, 100.0));
  EXPECT_FALSE(floor.Intersect(MakeRay({0, 0, 5}, {0, 0, 1}), 0.0, 100.0));      // away
  EXPECT_FALSE(floor.Intersect(MakeRay({-5, 0, 1.5}, {1, 0, 0}), 0.0, 100.0));   // parallel
  EXPECT_TRUE(floor.Intersect(MakeRay({2.0, 1.0, 5}, {0, 0, -1}), 0.0, 100.0));  // corner counts
}

TEST(PlanePrimitive, RangeWindow) {
  const PlanePrimitive floor = Floor();
  const Ray ray = MakeRay({1, 0.5, 5}, {0, 0, -1});
  EXPECT_TRUE(floor.Intersect(ray, 0.0, 4.0));
  EXPECT_FALSE(floor.Intersect(ray, 0.0, 3.99));
  EXPECT_FALSE(floor.Intersect(ray, 4.0, 100.0));
  EXPECT_TRUE(floor.Intersect(ray, 3.99, 100.0));
}

TEST(PlanePrimitive, RolledWallStandsInTheXZPlane) {
  // Rx(90 deg) maps the local normal z to -y, local x to x and local y to z.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const PlanePrimitive wall({0, 0, 1}, {4, 2}, R);
  EXPECT_TRUE(wall.normal().isApprox(Eigen::Vector3d(0, -1, 0), 1e-12));
  const auto hit = wall.Intersect(MakeRay({1.5, -5, 1.9}, {0, 1, 0}), 0.0, 100.0);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->range_m, 5.0, 1e-12);
  EXPECT_TRUE(hit->normal.isApprox(Eigen::Vector3d(0, -1, 0), 1e-12));
  EXPECT_FALSE(wall.Intersect(MakeRay({1.5, -5, 2.1}, {0, 1, 0}), 0.0, 100.0));  // above its top
  const Eigen::AlignedBox3d bounds = wall.Bounds();
  EXPECT_TRUE(bounds.min().isApprox(Eigen::Vector3d(-2, 0, 0), 1e-12));
  EXPECT_TRUE(bounds.max().isApprox(Eigen::Vector3d(2, 0, 2), 1e-12));
}

TEST(PlanePrimitive, SurfaceDistanceMatchesClosedForm) {
  const PlanePrimitive floor = Floor();
  EXPECT_NEAR(floor.SurfaceDistance({1, 0.5, 3}), 2.0, 1e-12);                        // above
  EXPECT_NEAR(floor.SurfaceDistance({1, 0.5, -1}), 2.0, 1e-12);                       // below
  EXPECT_NEAR(floor.SurfaceDistance({5, 0, 1}), 3.0, 1e-12);                          // beside, in plane
  EXPECT_NEAR(floor.SurfaceDistance({5, 2, 5}), std::sqrt(9.0 + 1.0 + 16.0), 1e-12);  // off a corner
  EXPECT_NEAR(floor.SurfaceDistance({0.3, -0.2, 1}), 0.0, 1e-12);
}

TEST(PlanePrimitive, RandomRaysHitPointsLieOnTheRectangle) {
  const Eigen::Matrix3d R =
      (Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(-0.9, Eigen::Vector3d::UnitY()))
          .toRotationMatrix();
  const Eigen::Vector3d center(1, 2, 3);
  const PlanePrimitive plane(center, {3, 1.5}, R);
  std::mt19937 rng(11);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Ray ray =
        test::RandomRay(Eigen::AlignedBox3d(center.array() - 3, center.array() + 3), plane.Bounds(), i, &rng);
    // Closed form in the plane frame: t = -o_z / d_z, inside when |x| <= 1.5 and |y| <= 0.75.
    const Eigen::Vector3d o = R.transpose() * (ray.origin - center);
    const Eigen::Vector3d d = R.transpose() * ray.direction;
    const double t = -o.z() / d.z();
    const Eigen::Vector3d q = o + t * d;
    const bool expected = t > 0.0 && std::abs(q.x()) <= 1.5 && std::abs(q.y()) <= 0.75;
    const auto hit = plane.Intersect(ray, 0.0, 100.0);
    ASSERT_EQ(hit.has_value(), expected) << "ray " << i;
    if (!hit) continue;
    ++hits;
    EXPECT_NEAR(hit->range_m, t, 1e-9);
    EXPECT_LT(plane.SurfaceDistance(ray.origin + hit->range_m * ray.direction), 1e-9);
    EXPECT_NEAR(std::abs(hit->normal.dot(plane.normal())), 1.0, 1e-12);
    EXPECT_LE(hit->normal.dot(ray.direction), 0.0);
  }
  EXPECT_GT(hits, 500);
}

TEST(PlanePrimitive, RejectsNonPositiveSize) {
  EXPECT_THROW(PlanePrimitive({0, 0, 0}, {0, 1}), std::invalid_argument);
  EXPECT_THROW(PlanePrimitive({0, 0, 0}, {1, -2}), std::invalid_argument);
}

}  // namespace
}  // namespace unimap::sim
