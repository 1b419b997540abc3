#include "HeightfieldPrimitive.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "PrimitiveTestSupport.hpp"

namespace unimap::sim {
namespace {

using Wave = HeightfieldPrimitive::Wave;

Ray MakeRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) {
  return Ray{origin, direction.normalized()};
}

// 20 m x 16 m rolling ground around (1, -1), mean height 0.5.
HeightfieldPrimitive Rolling() {
  return HeightfieldPrimitive({1, -1, 0.25}, {20, 16}, 0.25,
                              {Wave{0.3, 0.5, 0.3, 0.1, -0.2}, Wave{0.1, 1.7, 1.1, 0.0, 0.4}});
}

// Analytic h and its unit normal (-h_x, -h_y, 1) / norm for Rolling().
double RollingHeight(double x, double y, Eigen::Vector3d* normal) {
  const double h =
      0.5 + 0.3 * std::sin(0.5 * x + 0.1) * std::cos(0.3 * y - 0.2) + 0.1 * std::sin(1.7 * x) * std::cos(1.1 * y + 0.4);
  const double hx = 0.3 * 0.5 * std::cos(0.5 * x + 0.1) * std::cos(0.3 * y - 0.2) +
                    0.1 * 1.7 * std::cos(1.7 * x) * std::cos(1.1 * y + 0.4);
  const double hy = -0.3 * 0.3 * std::sin(0.5 * x + 0.1) * std::sin(0.3 * y - 0.2) -
                    0.1 * 1.1 * std::sin(1.7 * x) * std::sin(1.1 * y + 0.4);
  if (normal != nullptr) *normal = Eigen::Vector3d(-hx, -hy, 1.0).normalized();
  return h;
}

// Brute force: the first sign change of z(t) - h(x(t), y(t)) over (t_min, t_max]
// sampled every `step` inside the rectangle, as the bracket [t_k, t_k+1].
std::optional<std::pair<double, double>> MarchFirstCrossing(const Ray& ray, double t_min, double t_max, double step) {
  const auto in_rectangle = [](const Eigen::Vector3d& p) {
    return std::abs(p.x() - 1.0) <= 10.0 && std::abs(p.y() + 1.0) <= 8.0;
  };
  std::optional<double> previous_t;
  double previous_f = 0.0;
  for (double t = t_min + step; t <= t_max; t += step) {
    const Eigen::Vector3d p = ray.origin + t * ray.direction;
    if (!in_rectangle(p)) {
      previous_t.reset();
      continue;
    }
    const double f = p.z() - RollingHeight(p.x(), p.y(), nullptr);
    if (previous_t && (f < 0.0) != (previous_f < 0.0)) return std::make_pair(*previous_t, t);
    previous_t = t;
    previous_f = f;
  }
  return std::nullopt;
}

TEST(HeightfieldPrimitive, FlatFieldBehavesLikeARectangle) {
  const HeightfieldPrimitive flat({0, 0, 1}, {10, 10}, 0.0, {});
  const auto down = flat.Intersect(MakeRay({1, 1, 5}, {0, 0, -1}), 0.0, 100.0);
  ASSERT_TRUE(down.has_value());
  EXPECT_NEAR(down->range_m, 4.0, 1e-9);
  EXPECT_TRUE(down->normal.isApprox(Eigen::Vector3d(0, 0, 1), 1e-12));
  const auto up = flat.Intersect(MakeRay({1, 1, -1}, {0.6, 0, 0.8}), 0.0, 100.0);
  ASSERT_TRUE(up.has_value());
  EXPECT_NEAR(up->range_m, 2.5, 1e-9);
  EXPECT_TRUE(up->normal.isApprox(Eigen::Vector3d(0, 0, -1), 1e-12));
  EXPECT_FALSE(flat.Intersect(MakeRay({6, 0, 5}, {0, 0, -1}), 0.0, 100.0));  // off the rectangle
  EXPECT_FALSE(flat.Intersect(MakeRay({0, 0, 2}, {1, 0, 0}), 0.0, 100.0));   // horizontal
  EXPECT_FALSE(flat.Intersect(MakeRay({1, 1, 5}, {0, 0, -1}), 0.0, 3.9));    // window
  EXPECT_FALSE(flat.Intersect(MakeRay({1, 1, 5}, {0, 0, -1}), 4.1, 100.0));
  EXPECT_NEAR(flat.SurfaceDistance({1, 1, 3}), 2.0, 1e-12);
  EXPECT_NEAR(flat.SurfaceDistance({8, 0, 5}), 5.0, 1e-12);  // sqrt(3^2 + 4^2), off the edge
  EXPECT_NEAR(flat.Bounds().min().z(), 1.0, 1e-12);
  EXPECT_NEAR(flat.Bounds().max().x(), 5.0, 1e-12);
}

TEST(HeightfieldPrimitive, VerticalRaysHitTheAnalyticHeightWithItsNormal) {
  const HeightfieldPrimitive ground = Rolling();
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> x(-8.5, 10.5);
  std::uniform_real_distribution<double> y(-8.5, 6.5);
  for (int i = 0; i < 200; ++i) {
    const double px = x(rng);
    const double py = y(rng);
    Eigen::Vector3d normal;
    const double h = RollingHeight(px, py, &normal);
    EXPECT_NEAR(ground.Height(px, py), h, 1e-12);
    const auto down = ground.Intersect(MakeRay({px, py, 3}, {0, 0, -1}), 0.0, 100.0);
    ASSERT_TRUE(down.has_value());
    EXPECT_NEAR(down->range_m, 3.0 - h, 1e-6);
    EXPECT_TRUE(down->normal.isApprox(normal, 1e-6));
    const auto up = ground.Intersect(MakeRay({px, py, -2}, {0, 0, 1}), 0.0, 100.0);
    ASSERT_TRUE(up.has_value());
    EXPECT_NEAR(up->range_m, 2.0 + h, 1e-6);
    EXPECT_TRUE(up->normal.isApprox(-normal, 1e-6));
  }
}

TEST(HeightfieldPrimitive, RandomRaysMatchBruteForceMarch) {
  const HeightfieldPrimitive ground = Rolling();
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> x(-12, 14);
  std::uniform_real_distribution<double> y(-11, 9);
  std::uniform_real_distribution<double> z(-0.2, 1.2);
  std::uniform_real_distribution<double> window(0.0, 3.0);
  constexpr double kStep = 2e-4;
  int hits = 0;
  std::uniform_real_distribution<double> reach(0.5, 6.0);
  for (int i = 0; i < 300; ++i) {
    // Shallow rays (the hard case for marching): direction z in [-0.35, 0.35] of a
    // unit vector; even ones aimed at a surface point 0.5-6 m away, odd ones random.
    Eigen::Vector3d d = test::RandomDirection(&rng);
    d.z() *= 0.35;
    Ray ray{Eigen::Vector3d(x(rng), y(rng), z(rng)), d.normalized()};
    if (i % 2 == 0) {
      const Eigen::Vector2d target = ray.origin.head<2>() + reach(rng) * d.head<2>().normalized();
      const Eigen::Vector3d aim(target.x(), target.y(), RollingHeight(target.x(), target.y(), nullptr));
      ray.direction = (aim - ray.origin).normalized();
    }
    const double t_min = i % 3 == 0 ? window(rng) : 0.0;
    const double t_max = t_min + 8.0;
    const auto hit = ground.Intersect(ray, t_min, t_max);
    const auto bracket = MarchFirstCrossing(ray, t_min, t_max, kStep);
    ASSERT_EQ(hit.has_value(), bracket.has_value()) << "ray " << i;
    if (!hit) continue;
    ++hits;
    EXPECT_GE(hit->range_m, bracket->first - 1e-9) << "ray " << i;
    EXPECT_LE(hit->range_m, bracket->second + 1e-9) << "ray " << i;
    EXPECT_GT(hit->range_m, t_min);
    EXPECT_LE(hit->range_m, t_max);
    const Eigen::Vector3d p = ray.origin + hit->range_m * ray.direction;
    Eigen::Vector3d normal;
    // Bisection to 1e-9 m along the ray: the point is within 1e-6 m of the surface height.
    EXPECT_NEAR(p.z(), RollingHeight(p.x(), p.y(), &normal), 1e-6) << "ray " << i;
    EXPECT_NEAR(std::abs(hit->normal.dot(normal)), 1.0, 1e-9);
    EXPECT_LE(hit->normal.dot(ray.direction), 0.0);
  }
  EXPECT_GT(hits, 100);
}

TEST(HeightfieldPrimitive, SurfaceDistanceNearTheSurfaceMatchesBruteForce) {
  const HeightfieldPrimitive ground = Rolling();
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> x(-7, 9);
  std::uniform_real_distribution<double> y(-7, 5);
  std::uniform_real_distribution<double> offset(0.02, 0.3);
  for (int i = 0; i < 12; ++i) {
    const double px = x(rng);
    const double py = y(rng);
    const double side = i % 2 == 0 ? 1.0 : -1.0;  // above and below
    const Eigen::Vector3d p(px, py, RollingHeight(px, py, nullptr) + side * offset(rng));
    // Brute force: coarse grid (1 cm over +-0.5 m), then a fine grid (5e-5 m) around
    // its best; at >= 2 cm from the surface the fine grid is within ~1e-7 m of the minimum.
    const auto distance_to = [&](double u, double v) {
      return (Eigen::Vector3d(u, v, RollingHeight(u, v, nullptr)) - p).norm();
    };
    double best = std::numeric_limits<double>::infinity();
    double best_u = px;
    double best_v = py;
    for (double u = px - 0.5; u <= px + 0.5; u += 0.01) {
      for (double v = py - 0.5; v <= py + 0.5; v += 0.01) {
        const double dist = distance_to(u, v);
        if (dist < best) {
          best = dist;
          best_u = u;
          best_v = v;
        }
      }
    }
    const double cu = best_u;
    const double cv = best_v;
    for (double u = cu - 0.01; u <= cu + 0.01; u += 5e-5) {
      for (double v = cv - 0.01; v <= cv + 0.01; v += 5e-5) {
        best = std::min(best, distance_to(u, v));
      }
    }
    const double d = ground.SurfaceDistance(p);
    EXPECT_LE(d, best + 1e-12) << "point " << i;  // a true minimum, never worse than the grid
    EXPECT_NEAR(d, best, 1e-6) << "point " << i;
  }
}

TEST(HeightfieldPrimitive, SurfaceDistanceStaysWithinItsDocumentedBounds) {
  const HeightfieldPrimitive ground = Rolling();
  const double slope = ground.slope_bound();
  EXPECT_NEAR(slope, 0.3 * 0.5 + 0.1 * 1.7, 1e-12);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> x(-8, 10);
  std::uniform_real_distribution<double> y(-8, 6);
  std::uniform_real_distribution<double> z(-4, 5);
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector3d p(x(rng), y(rng), z(rng));
    const double vertical = std::abs(p.z() - RollingHeight(p.x(), p.y(), nullptr));
    const double d = ground.SurfaceDistance(p);
    EXPECT_LE(d, vertical + 1e-12);
    EXPECT_GE(d, vertical / std::sqrt(1.0 + slope * slope) - 1e-12);
  }
  // Beside the rectangle over flat-looking ground: at least the horizontal gap.
  EXPECT_GE(ground.SurfaceDistance({15, -1, 0.5}), 4.0);
}

TEST(HeightfieldPrimitive, BoundsCoverTheAmplitudes) {
  const Eigen::AlignedBox3d bounds = Rolling().Bounds();
  EXPECT_TRUE(bounds.min().isApprox(Eigen::Vector3d(-9, -9, 0.1), 1e-12));
  EXPECT_TRUE(bounds.max().isApprox(Eigen::Vector3d(11, 7, 0.9), 1e-12));
}

TEST(HeightfieldPrimitive, RejectsBadShape) {
  EXPECT_THROW(HeightfieldPrimitive({0, 0, 0}, {0, 1}, 0.0, {}), std::invalid_argument);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(HeightfieldPrimitive({0, 0, 0}, {1, 1}, 0.0, {Wave{nan, 1, 1, 0, 0}}), std::invalid_argument);
}

}  // namespace
}  // namespace unimap::sim
