#include "CylinderPrimitive.hpp"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "PrimitiveTestSupport.hpp"

namespace unimap::sim {
namespace {

Ray MakeRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) {
  return Ray{origin, direction.normalized()};
}

// Upright cylinder: radius 1, from z = 0 to z = 2 around the z axis.
CylinderPrimitive Post() { return CylinderPrimitive({0, 0, 0}, {0, 0, 1}, 1.0, 2.0); }

TEST(CylinderPrimitive, SideWallFromOutsideAndInside) {
  const CylinderPrimitive post = Post();
  const auto outside = post.Intersect(MakeRay({-5, 0, 1}, {1, 0, 0}), 0.0, 100.0);
  ASSERT_TRUE(outside.has_value());
  EXPECT_NEAR(outside->range_m, 4.0, 1e-12);
  EXPECT_TRUE(outside->normal.isApprox(Eigen::Vector3d(-1, 0, 0), 1e-12));
  const auto inside = post.Intersect(MakeRay({0, 0, 1}, {1, 0, 0}), 0.0, 100.0);
  ASSERT_TRUE(inside.has_value());
  EXPECT_NEAR(inside->range_m, 1.0, 1e-12);
  EXPECT_TRUE(inside->normal.isApprox(Eigen::Vector3d(-1, 0, 0), 1e-12));
  // Off-centre chord: y = 0.6 meets the wall at x = -0.8, normal (-0.8, 0.6, 0) toward the ray.
  const auto chord = post.Intersect(MakeRay({-5, 0.6, 1}, {1, 0, 0}), 0.0, 100.0);
  ASSERT_TRUE(chord.has_value());
  EXPECT_NEAR(chord->range_m, 4.2, 1e-12);
  EXPECT_TRUE(chord->normal.isApprox(Eigen::Vector3d(-0.8, 0.6, 0), 1e-12));
}

TEST(CylinderPrimitive, CapsFromOutsideAndInside) {
  const CylinderPrimitive post = Post();
  const auto top = post.Intersect(MakeRay({0.5, 0, 5}, {0, 0, -1}), 0.0, 100.0);
  ASSERT_TRUE(top.has_value());
  EXPECT_NEAR(top->range_m, 3.0, 1e-12);
  EXPECT_TRUE(top->normal.isApprox(Eigen::Vector3d(0, 0, 1), 1e-12));
  const auto up_from_inside = post.Intersect(MakeRay({0.5, 0, 1.5}, {0, 0, 1}), 0.0, 100.0);
  ASSERT_TRUE(up_from_inside.has_value());
  EXPECT_NEAR(up_from_inside->range_m, 0.5, 1e-12);
  EXPECT_TRUE(up_from_inside->normal.isApprox(Eigen::Vector3d(0, 0, -1), 1e-12));
  const auto bottom = post.Intersect(MakeRay({0, 0.5, -1}, {0, 0, 1}), 0.0, 100.0);
  ASSERT_TRUE(bottom.has_value());
  EXPECT_NEAR(bottom->range_m, 1.0, 1e-12);
  EXPECT_TRUE(bottom->normal.isApprox(Eigen::Vector3d(0, 0, -1), 1e-12));
  // Slanted through the top rim region: enters the top cap at (0.5, 0, 2).
  const auto slanted = post.Intersect(MakeRay({2.5, 0, 4}, {-1, 0, -1}), 0.0, 100.0);
  ASSERT_TRUE(slanted.has_value());
  EXPECT_NEAR(slanted->range_m, 2.0 * std::sqrt(2.0), 1e-12);
  EXPECT_TRUE(slanted->normal.isApprox(Eigen::Vector3d(0, 0, 1), 1e-12));
}

TEST(CylinderPrimitive, MissesAndRangeWindow) {
  const CylinderPrimitive post = Post();
  EXPECT_FALSE(post.Intersect(MakeRay({-5, 0, 2.5}, {1, 0, 0}), 0.0, 100.0));  // above
  EXPECT_FALSE(post.Intersect(MakeRay({-5, 1.2, 1}, {1, 0, 0}), 0.0, 100.0));  // beside
  EXPECT_FALSE(post.Intersect(MakeRay({1.5, 0, 5}, {0, 0, -1}), 0.0, 100.0));  // parallel, outside
  const Ray ray = MakeRay({-5, 0, 1}, {1, 0, 0});                              // enters at 4, leaves at 6
  EXPECT_FALSE(post.Intersect(ray, 0.0, 3.9));
  const auto leave = post.Intersect(ray, 4.0, 100.0);
  ASSERT_TRUE(leave.has_value());
  EXPECT_NEAR(leave->range_m, 6.0, 1e-12);
  EXPECT_TRUE(leave->normal.isApprox(Eigen::Vector3d(-1, 0, 0), 1e-12));
  EXPECT_FALSE(post.Intersect(ray, 6.0, 100.0));
}

TEST(CylinderPrimitive, SurfaceDistanceMatchesClosedForm) {
  const CylinderPrimitive post = Post();
  EXPECT_NEAR(post.SurfaceDistance({3, 0, 1}), 2.0, 1e-12);                   // radial
  EXPECT_NEAR(post.SurfaceDistance({0.5, 0, 4}), 2.0, 1e-12);                 // above the cap
  EXPECT_NEAR(post.SurfaceDistance({0, 4, 5}), std::sqrt(9.0 + 9.0), 1e-12);  // off the rim
  EXPECT_NEAR(post.SurfaceDistance({0.2, 0, 1}), 0.8, 1e-12);                 // inside, wall nearest
  EXPECT_NEAR(post.SurfaceDistance({0, 0, 0.3}), 0.3, 1e-12);                 // inside, cap nearest
  EXPECT_NEAR(post.SurfaceDistance({0.6, 0.8, 1.3}), 0.0, 1e-12);             // on the wall
  // Tilted along x from (1, 0, 0): the same answers in rotated coordinates.
  const CylinderPrimitive lying({1, 0, 0}, {2, 0, 0}, 1.0, 2.0);  // axis normalised to (1, 0, 0)
  EXPECT_NEAR(lying.SurfaceDistance({2, 0, 3}), 2.0, 1e-12);
  EXPECT_NEAR(lying.SurfaceDistance({5, 0, 0.5}), 2.0, 1e-12);
}

TEST(CylinderPrimitive, BoundsOfTiltedCylinder) {
  const CylinderPrimitive post = Post();
  EXPECT_TRUE(post.Bounds().min().isApprox(Eigen::Vector3d(-1, -1, 0), 1e-12));
  EXPECT_TRUE(post.Bounds().max().isApprox(Eigen::Vector3d(1, 1, 2), 1e-12));
  // Axis (1, 1, 0) / sqrt(2): each cap disk spans sqrt(1/2) along x and y and 1 along z.
  const CylinderPrimitive tilted({0, 0, 0}, {1, 1, 0}, 1.0, std::sqrt(2.0));
  const double s = std::sqrt(0.5);
  EXPECT_TRUE(tilted.Bounds().min().isApprox(Eigen::Vector3d(-s, -s, -1), 1e-12));
  EXPECT_TRUE(tilted.Bounds().max().isApprox(Eigen::Vector3d(1 + s, 1 + s, 1), 1e-12));
}

TEST(CylinderPrimitive, RandomRaysAgreeWithInsideMarch) {
  const Eigen::Vector3d base(0.3, -0.2, 0.5);
  const Eigen::Vector3d axis = Eigen::Vector3d(0.4, -0.3, 0.8).normalized();
  const double radius = 0.9;
  const double height = 2.5;
  const CylinderPrimitive cylinder(base, axis, radius, height);
  const auto inside = [&](const Eigen::Vector3d& p) {
    const double s = (p - base).dot(axis);
    return s >= 0.0 && s <= height && (p - base - s * axis).norm() <= radius;
  };
  const test::MarchStats stats = test::ExpectHitsMatchInsideMarch(
      cylinder, inside, Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-3), Eigen::Vector3d::Constant(4)), 400, 5);
  EXPECT_GT(stats.hits_from_outside, 100);
  EXPECT_GT(stats.hits_from_inside, 5);
}

TEST(CylinderPrimitive, RejectsBadShape) {
  EXPECT_THROW(CylinderPrimitive({0, 0, 0}, {0, 0, 0}, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(CylinderPrimitive({0, 0, 0}, {0, 0, 1}, 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(CylinderPrimitive({0, 0, 0}, {0, 0, 1}, 1.0, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace unimap::sim
