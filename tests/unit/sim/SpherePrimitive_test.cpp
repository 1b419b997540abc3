#include "SpherePrimitive.hpp"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "PrimitiveTestSupport.hpp"

namespace unimap::sim {
namespace {

Ray MakeRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) {
  return Ray{origin, direction.normalized()};
}

TEST(SpherePrimitive, HitsFromOutsideAndInside) {
  const SpherePrimitive ball({3, 4, 4}, 1.5);
  const auto outside = ball.Intersect(MakeRay({-2, 4, 4}, {1, 0, 0}), 0.0, 100.0);
  ASSERT_TRUE(outside.has_value());
  EXPECT_NEAR(outside->range_m, 3.5, 1e-12);
  EXPECT_TRUE(outside->normal.isApprox(Eigen::Vector3d(-1, 0, 0), 1e-12));
  const auto inside = ball.Intersect(MakeRay({3, 4, 4}, {0, 0, 1}), 0.0, 100.0);
  ASSERT_TRUE(inside.has_value());
  EXPECT_NEAR(inside->range_m, 1.5, 1e-12);
  EXPECT_TRUE(inside->normal.isApprox(Eigen::Vector3d(0, 0, -1), 1e-12));
  // Chord at offset 0.9 from the centre: half chord sqrt(1.5^2 - 0.9^2) = 1.2.
  const auto chord = ball.Intersect(MakeRay({-2, 4.9, 4}, {1, 0, 0}), 0.0, 100.0);
  ASSERT_TRUE(chord.has_value());
  EXPECT_NEAR(chord->range_m, 5.0 - 1.2, 1e-12);
  EXPECT_TRUE(chord->normal.isApprox(Eigen::Vector3d(-1.2, 0.9, 0) / 1.5, 1e-12));
}

TEST(SpherePrimitive, MissesGrazesAndRangeWindow) {
  const SpherePrimitive ball({0, 0, 0}, 1.0);
  EXPECT_FALSE(ball.Intersect(MakeRay({-5, 1.01, 0}, {1, 0, 0}), 0.0, 100.0));
  EXPECT_FALSE(ball.Intersect(MakeRay({-5, 0, 0}, {-1, 0, 0}), 0.0, 100.0));
  const auto graze = ball.Intersect(MakeRay({-5, 1.0, 0}, {1, 0, 0}), 0.0, 100.0);  // tangent
  ASSERT_TRUE(graze.has_value());
  EXPECT_NEAR(graze->range_m, 5.0, 1e-12);
  const Ray ray = MakeRay({-5, 0, 0}, {1, 0, 0});  // enters at 4, leaves at 6
  EXPECT_FALSE(ball.Intersect(ray, 0.0, 3.99));
  const auto leave = ball.Intersect(ray, 4.0, 100.0);
  ASSERT_TRUE(leave.has_value());
  EXPECT_NEAR(leave->range_m, 6.0, 1e-12);
  EXPECT_TRUE(leave->normal.isApprox(Eigen::Vector3d(-1, 0, 0), 1e-12));
  EXPECT_FALSE(ball.Intersect(ray, 6.0, 100.0));
  // A far sphere keeps its accuracy: 1000 m away, radius 0.5.
  const SpherePrimitive far({1000, 0, 0}, 0.5);
  const auto far_hit = far.Intersect(MakeRay({0, 0.3, 0}, {1, 0, 0}), 0.0, 2000.0);
  ASSERT_TRUE(far_hit.has_value());
  EXPECT_NEAR(far_hit->range_m, 1000.0 - 0.4, 1e-9);
}

TEST(SpherePrimitive, SurfaceDistanceAndBounds) {
  const SpherePrimitive ball({1, 2, 3}, 2.0);
  EXPECT_NEAR(ball.SurfaceDistance({1, 2, 3}), 2.0, 1e-12);
  EXPECT_NEAR(ball.SurfaceDistance({1, 2, 4.5}), 0.5, 1e-12);
  EXPECT_NEAR(ball.SurfaceDistance({4, 6, 3}), 3.0, 1e-12);
  EXPECT_NEAR(ball.SurfaceDistance({3, 2, 3}), 0.0, 1e-12);
  EXPECT_TRUE(ball.Bounds().min().isApprox(Eigen::Vector3d(-1, 0, 1), 1e-12));
  EXPECT_TRUE(ball.Bounds().max().isApprox(Eigen::Vector3d(3, 4, 5), 1e-12));
}

TEST(SpherePrimitive, RandomRaysAgreeWithInsideMarch) {
  const Eigen::Vector3d center(0.5, 0.25, -1.0);
  const SpherePrimitive ball(center, 1.25);
  const auto inside = [&](const Eigen::Vector3d& p) { return (p - center).norm() <= 1.25; };
  const test::MarchStats stats = test::ExpectHitsMatchInsideMarch(
      ball, inside, Eigen::AlignedBox3d(center.array() - 3.0, center.array() + 3.0), 400, 3);
  EXPECT_GT(stats.hits_from_outside, 100);
  EXPECT_GT(stats.hits_from_inside, 5);
}

TEST(SpherePrimitive, RejectsNonPositiveRadius) {
  EXPECT_THROW(SpherePrimitive({0, 0, 0}, 0.0), std::invalid_argument);
  EXPECT_THROW(SpherePrimitive({0, 0, 0}, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace unimap::sim
