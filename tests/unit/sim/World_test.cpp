#include "World.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <stdexcept>
#include <utility>

#include <gtest/gtest.h>

#include "BoxPrimitive.hpp"
#include "CylinderPrimitive.hpp"
#include "HeightfieldPrimitive.hpp"
#include "PlanePrimitive.hpp"
#include "PrimitiveTestSupport.hpp"
#include "SpherePrimitive.hpp"

namespace unimap::sim {
namespace {

// A random rotation from three uniform angles.
Eigen::Matrix3d RandomRotation(std::mt19937* rng) {
  std::uniform_real_distribution<double> angle(-3.14159, 3.14159);
  return (Eigen::AngleAxisd(angle(*rng), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(angle(*rng), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(angle(*rng), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

// A room (box 40 x 30 x 12 around the origin) holding n random primitives of
// every kind, some overlapping.
World RandomWorld(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(-18, 18);
  std::uniform_real_distribution<double> y(-13, 13);
  std::uniform_real_distribution<double> z(-5, 5);
  std::uniform_real_distribution<double> size(0.2, 4.0);
  World world;
  world.Add(std::make_unique<BoxPrimitive>(Eigen::Vector3d::Zero(), Eigen::Vector3d(40, 30, 12)));
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d c(x(rng), y(rng), z(rng));
    switch (i % 5) {
      case 0:
        world.Add(
            std::make_unique<BoxPrimitive>(c, Eigen::Vector3d(size(rng), size(rng), size(rng)), RandomRotation(&rng)));
        break;
      case 1:
        world.Add(std::make_unique<PlanePrimitive>(c, Eigen::Vector2d(size(rng), size(rng)), RandomRotation(&rng)));
        break;
      case 2:
        world.Add(std::make_unique<CylinderPrimitive>(c, test::RandomDirection(&rng), 0.3 * size(rng), size(rng)));
        break;
      case 3:
        world.Add(std::make_unique<SpherePrimitive>(c, 0.5 * size(rng)));
        break;
      default:
        world.Add(std::make_unique<HeightfieldPrimitive>(
            c, Eigen::Vector2d(2 * size(rng), 2 * size(rng)), 0.0,
            std::vector<HeightfieldPrimitive::Wave>{{0.1 * size(rng), 1.3, 0.7, 0.2, 0.0}}));
        break;
    }
  }
  world.Build();
  return world;
}

// The nearest hit over every primitive, without the BVH.
std::optional<RayHit> BruteForceCast(const World& world, const Ray& ray, double min_range, double max_range) {
  std::optional<RayHit> best;
  for (std::size_t i = 0; i < world.size(); ++i) {
    auto hit = world.primitive(i).Intersect(ray, min_range, max_range);
    if (hit && (!best || hit->range_m < best->range_m)) {
      best = hit;
      best->primitive_index = static_cast<int>(i);
    }
  }
  return best;
}

TEST(World, EmptyWorldSeesNothing) {
  World world;
  world.Build();
  EXPECT_EQ(world.size(), 0u);
  EXPECT_FALSE(world.Cast(Ray{}, 0.0, 100.0));
  EXPECT_EQ(world.SurfaceDistance(Eigen::Vector3d::Zero()), std::numeric_limits<double>::infinity());
  EXPECT_TRUE(world.Bounds().isEmpty());
}

TEST(World, QueriesBeforeBuildAreRejected) {
  World world;
  world.Add(std::make_unique<SpherePrimitive>(Eigen::Vector3d::Zero(), 1.0));
  EXPECT_FALSE(world.built());
  EXPECT_THROW(world.Cast(Ray{}, 0.0, 10.0), std::logic_error);
  EXPECT_THROW(world.SurfaceDistance(Eigen::Vector3d::Zero()), std::logic_error);
  EXPECT_THROW(world.Add(nullptr), std::invalid_argument);
  world.Build();
  EXPECT_TRUE(world.built());
  world.Add(std::make_unique<SpherePrimitive>(Eigen::Vector3d(5, 0, 0), 1.0));
  EXPECT_THROW(world.Cast(Ray{}, 0.0, 10.0), std::logic_error);
}

TEST(World, RoomWithAnObstacleReportsNearestPrimitive) {
  World world;
  world.Add(std::make_unique<BoxPrimitive>(Eigen::Vector3d(54, 0, 3.5), Eigen::Vector3d(108, 5.8, 7)));
  world.Add(std::make_unique<BoxPrimitive>(Eigen::Vector3d(20, 0, 1.5), Eigen::Vector3d(10, 3, 3)));
  world.Build();
  const Ray along{Eigen::Vector3d(2, 0, 1), Eigen::Vector3d::UnitX()};
  const auto car = world.Cast(along, 0.0, 200.0);
  ASSERT_TRUE(car.has_value());
  EXPECT_EQ(car->primitive_index, 1);
  EXPECT_NEAR(car->range_m, 13.0, 1e-12);
  EXPECT_TRUE(car->normal.isApprox(-Eigen::Vector3d::UnitX(), 1e-12));
  const auto over = world.Cast(Ray{Eigen::Vector3d(2, 0, 5), Eigen::Vector3d::UnitX()}, 0.0, 200.0);
  ASSERT_TRUE(over.has_value());
  EXPECT_EQ(over->primitive_index, 0);
  EXPECT_NEAR(over->range_m, 106.0, 1e-12);
  EXPECT_FALSE(world.Cast(along, 0.0, 12.9));        // window closes before the car
  const auto past = world.Cast(along, 13.0, 200.0);  // min is exclusive: the car's far side
  ASSERT_TRUE(past.has_value());
  EXPECT_NEAR(past->range_m, 23.0, 1e-12);
  EXPECT_NEAR(world.SurfaceDistance({2, 0, 1}), 1.0, 1e-12);     // the floor
  EXPECT_NEAR(world.SurfaceDistance({20, 0, 2}), 1.0, 1e-12);    // inside the car: its top
  EXPECT_NEAR(world.SurfaceDistance({30, 0, 4.5}), 2.5, 1e-12);  // room: ceiling 2.5, floor 4.5
  const Eigen::AlignedBox3d bounds = world.Bounds();
  EXPECT_TRUE(bounds.min().isApprox(Eigen::Vector3d(0, -2.9, 0), 1e-12));
  EXPECT_TRUE(bounds.max().isApprox(Eigen::Vector3d(108, 2.9, 7), 1e-12));
}

TEST(World, CastMatchesBruteForceOnRandomRays) {
  const World world = RandomWorld(120, 17);
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> window(0.0, 2.0);
  const Eigen::AlignedBox3d origins(Eigen::Vector3d(-19, -14, -5.5), Eigen::Vector3d(19, 14, 5.5));
  int hits = 0;
  int non_room_hits = 0;
  for (int i = 0; i < 5000; ++i) {
    const Ray ray{test::RandomPoint(origins, &rng), test::RandomDirection(&rng)};
    const double min_range = i % 4 == 0 ? window(rng) : 0.0;
    const double max_range = i % 7 == 0 ? 5.0 : 80.0;
    const auto bvh = world.Cast(ray, min_range, max_range);
    const auto brute = BruteForceCast(world, ray, min_range, max_range);
    ASSERT_EQ(bvh.has_value(), brute.has_value()) << "ray " << i;
    if (!bvh) continue;
    ++hits;
    non_room_hits += bvh->primitive_index != 0;
    // Heightfields may refine a crossing's bracket differently when the range window
    // differs; every other primitive gives bit-identical ranges.
    EXPECT_NEAR(bvh->range_m, brute->range_m, 1e-8) << "ray " << i;
    if (std::abs(bvh->range_m - brute->range_m) < 1e-12) {
      EXPECT_EQ(bvh->primitive_index, brute->primitive_index) << "ray " << i;
      EXPECT_TRUE(bvh->normal.isApprox(brute->normal, 1e-12)) << "ray " << i;
    }
  }
  EXPECT_GT(hits, 4000);
  EXPECT_GT(non_room_hits, 1000);
}

TEST(World, SurfaceDistanceMatchesBruteForce) {
  const World world = RandomWorld(120, 23);
  std::mt19937 rng(5);
  const Eigen::AlignedBox3d region(Eigen::Vector3d(-25, -20, -10), Eigen::Vector3d(25, 20, 10));
  for (int i = 0; i < 3000; ++i) {
    const Eigen::Vector3d p = test::RandomPoint(region, &rng);
    double brute = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < world.size(); ++k) {
      brute = std::min(brute, world.primitive(k).SurfaceDistance(p));
    }
    EXPECT_EQ(world.SurfaceDistance(p), brute) << "point " << i;
  }
}

TEST(World, LargeWorldsStayConsistentAndSurviveAMove) {
  World world = RandomWorld(1500, 31);
  World moved = std::move(world);
  std::mt19937 rng(2);
  const Eigen::AlignedBox3d origins(Eigen::Vector3d(-19, -14, -5.5), Eigen::Vector3d(19, 14, 5.5));
  for (int i = 0; i < 1000; ++i) {
    const Ray ray{test::RandomPoint(origins, &rng), test::RandomDirection(&rng)};
    const auto bvh = moved.Cast(ray, 0.0, 80.0);
    const auto brute = BruteForceCast(moved, ray, 0.0, 80.0);
    ASSERT_EQ(bvh.has_value(), brute.has_value()) << "ray " << i;
    if (bvh) {
      EXPECT_NEAR(bvh->range_m, brute->range_m, 1e-8) << "ray " << i;
    }
  }
}

TEST(World, RebuildAfterAddingIncludesTheNewPrimitive) {
  World world;
  world.Add(std::make_unique<SpherePrimitive>(Eigen::Vector3d(10, 0, 0), 1.0));
  world.Build();
  const Ray ray{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()};
  EXPECT_NEAR(world.Cast(ray, 0.0, 100.0)->range_m, 9.0, 1e-12);
  world.Add(std::make_unique<PlanePrimitive>(
      Eigen::Vector3d(4, 0, 0), Eigen::Vector2d(2, 2),
      Eigen::AngleAxisd(1.5707963267948966, Eigen::Vector3d::UnitY()).toRotationMatrix()));
  world.Build();
  const auto hit = world.Cast(ray, 0.0, 100.0);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->primitive_index, 1);
  EXPECT_NEAR(hit->range_m, 4.0, 1e-12);
  EXPECT_EQ(world.size(), 2u);
  EXPECT_EQ(world.primitive(1).Kind(), "plane");
}

}  // namespace
}  // namespace unimap::sim
