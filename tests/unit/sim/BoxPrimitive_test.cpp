#include "BoxPrimitive.hpp"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "PrimitiveTestSupport.hpp"

namespace unimap::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

Ray MakeRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) {
  return Ray{origin, direction.normalized()};
}

Eigen::Matrix3d Yaw(double deg) {
  return Eigen::AngleAxisd(deg * kPi / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

// Axis-aligned box spanning x in [0, 2], y in [0, 4], z in [0, 6].
BoxPrimitive AlignedBox() { return BoxPrimitive({1, 2, 3}, {2, 4, 6}); }

TEST(BoxPrimitive, HitFromOutsideEntersNearFace) {
  const auto hit = AlignedBox().Intersect(MakeRay({-5, 2, 3}, {1, 0, 0}), 0.0, 100.0);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->range_m, 5.0, 1e-12);
  EXPECT_TRUE(hit->normal.isApprox(Eigen::Vector3d(-1, 0, 0), 1e-12));
}

TEST(BoxPrimitive, HitFromInsideLeavesThroughFarWallLikeARoom) {
  const BoxPrimitive room = AlignedBox();
  const Eigen::Vector3d center(1, 2, 3);
  const auto east = room.Intersect(MakeRay(center, {1, 0, 0}), 0.0, 100.0);
  const auto north = room.Intersect(MakeRay(center, {0, 1, 0}), 0.0, 100.0);
  const auto down = room.Intersect(MakeRay(center, {0, 0, -1}), 0.0, 100.0);
  ASSERT_TRUE(east && north && down);
  EXPECT_NEAR(east->range_m, 1.0, 1e-12);
  EXPECT_NEAR(north->range_m, 2.0, 1e-12);
  EXPECT_NEAR(down->range_m, 3.0, 1e-12);
  // Normals face the viewer inside the room.
  EXPECT_TRUE(east->normal.isApprox(Eigen::Vector3d(-1, 0, 0), 1e-12));
  EXPECT_TRUE(north->normal.isApprox(Eigen::Vector3d(0, -1, 0), 1e-12));
  EXPECT_TRUE(down->normal.isApprox(Eigen::Vector3d(0, 0, 1), 1e-12));
  // Along (0, 1, -1) / sqrt(2): the y = 4 wall (2 m away in y, t = 2 sqrt(2)) comes
  // before the floor (3 m away in z).
  const auto diagonal = room.Intersect(MakeRay({0.5, 2, 3}, {0, 1, -1}), 0.0, 100.0);
  ASSERT_TRUE(diagonal.has_value());
  EXPECT_NEAR(diagonal->range_m, 2.0 * std::sqrt(2.0), 1e-12);
  EXPECT_TRUE(diagonal->normal.isApprox(Eigen::Vector3d(0, -1, 0), 1e-12));
}

TEST(BoxPrimitive, MissesAndParallelRays) {
  const BoxPrimitive box = AlignedBox();
  EXPECT_FALSE(box.Intersect(MakeRay({-5, 2, 7}, {1, 0, 0}), 0.0, 100.0));   // passes above
  EXPECT_FALSE(box.Intersect(MakeRay({-5, 2, 3}, {-1, 0, 0}), 0.0, 100.0));  // points away
  EXPECT_FALSE(box.Intersect(MakeRay({-5, -1, 3}, {1, 0, 0}), 0.0, 100.0));  // parallel, beside
  EXPECT_FALSE(box.Intersect(MakeRay({-5, 2, 3}, {1, 1, 0}), 0.0, 100.0));   // passes the corner (x=0 at y=7)
}

TEST(BoxPrimitive, RangeWindowIsOpenBelowAndClosedAbove) {
  const BoxPrimitive box = AlignedBox();
  const Ray ray = MakeRay({-5, 2, 3}, {1, 0, 0});  // enters at 5, leaves at 7
  ASSERT_TRUE(box.Intersect(ray, 0.0, 5.0));       // max is inclusive
  EXPECT_FALSE(box.Intersect(ray, 0.0, 4.999));
  const auto exit_hit = box.Intersect(ray, 5.0, 100.0);  // min is exclusive: the far face
  ASSERT_TRUE(exit_hit.has_value());
  EXPECT_NEAR(exit_hit->range_m, 7.0, 1e-12);
  EXPECT_TRUE(exit_hit->normal.isApprox(Eigen::Vector3d(-1, 0, 0), 1e-12));
  EXPECT_FALSE(box.Intersect(ray, 7.0, 100.0));
  EXPECT_FALSE(box.Intersect(ray, 5.5, 6.9));
}

TEST(BoxPrimitive, RotatedBoxUsesItsOwnAxes) {
  const BoxPrimitive box({1, 2, 3}, {2, 4, 6}, Yaw(90));  // now 4 m along x, 2 m along y
  const auto hit = box.Intersect(MakeRay({-5, 2, 3}, {1, 0, 0}), 0.0, 100.0);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->range_m, 4.0, 1e-12);
  EXPECT_TRUE(hit->normal.isApprox(Eigen::Vector3d(-1, 0, 0), 1e-12));
  const Eigen::AlignedBox3d bounds = box.Bounds();
  EXPECT_TRUE(bounds.min().isApprox(Eigen::Vector3d(-1, 1, 0), 1e-12));
  EXPECT_TRUE(bounds.max().isApprox(Eigen::Vector3d(3, 3, 6), 1e-12));
  // A cube turned 45 deg about z reaches sqrt(2) * half size along x and y.
  const BoxPrimitive cube({0, 0, 0}, {2, 2, 2}, Yaw(45));
  EXPECT_NEAR(cube.Bounds().max().x(), std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(cube.Bounds().max().z(), 1.0, 1e-12);
  const auto corner = cube.Intersect(MakeRay({-5, 0, 0}, {1, 0, 0}), 0.0, 100.0);
  ASSERT_TRUE(corner.has_value());
  EXPECT_NEAR(corner->range_m, 5.0 - std::sqrt(2.0), 1e-12);
}

TEST(BoxPrimitive, SurfaceDistanceMatchesClosedForm) {
  const BoxPrimitive box = AlignedBox();
  EXPECT_NEAR(box.SurfaceDistance({-3, 2, 3}), 3.0, 1e-12);                           // face
  EXPECT_NEAR(box.SurfaceDistance({-1, -2, 3}), std::sqrt(1.0 + 4.0), 1e-12);         // edge
  EXPECT_NEAR(box.SurfaceDistance({-1, -2, -3}), std::sqrt(1.0 + 4.0 + 9.0), 1e-12);  // corner
  EXPECT_NEAR(box.SurfaceDistance({1, 2, 3}), 1.0, 1e-12);                            // inside: x walls
  EXPECT_NEAR(box.SurfaceDistance({1.5, 3.8, 3}), 0.2, 1e-12);                        // inside, near y = 4
  EXPECT_NEAR(box.SurfaceDistance({2, 1, 1}), 0.0, 1e-12);                            // on a face
  const BoxPrimitive turned({1, 2, 3}, {2, 4, 6}, Yaw(90));
  EXPECT_NEAR(turned.SurfaceDistance({-4, 2, 3}), 3.0, 1e-12);   // x face at -1
  EXPECT_NEAR(turned.SurfaceDistance({1, 2.5, 3}), 0.5, 1e-12);  // inside, y walls at 1 and 3
}

TEST(BoxPrimitive, RandomRaysAgreeWithInsideMarch) {
  const Eigen::Matrix3d R =
      (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()) * Eigen::AngleAxisd(-0.7, Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(1.1, Eigen::Vector3d::UnitZ()))
          .toRotationMatrix();
  const Eigen::Vector3d center(0.5, -1.0, 2.0);
  const Eigen::Vector3d half(1.5, 0.75, 1.0);
  const BoxPrimitive box(center, 2.0 * half, R);
  const auto inside = [&](const Eigen::Vector3d& p) {
    return ((R.transpose() * (p - center)).cwiseAbs() - half).maxCoeff() <= 0.0;
  };
  const test::MarchStats stats = test::ExpectHitsMatchInsideMarch(
      box, inside, Eigen::AlignedBox3d(center.array() - 2.5, center.array() + 2.5), 400, 7);
  EXPECT_GT(stats.hits_from_outside, 100);  // the sample exercises both cases
  EXPECT_GT(stats.hits_from_inside, 5);
}

TEST(BoxPrimitive, RejectsNonPositiveSize) {
  EXPECT_THROW(BoxPrimitive({0, 0, 0}, {1, 0, 1}), std::invalid_argument);
  EXPECT_THROW(BoxPrimitive({0, 0, 0}, {1, -1, 1}), std::invalid_argument);
  EXPECT_THROW(BoxPrimitive({0, 0, 0}, {1, 1, 1}, 2.0 * Eigen::Matrix3d::Identity()), std::invalid_argument);
}

}  // namespace
}  // namespace unimap::sim
