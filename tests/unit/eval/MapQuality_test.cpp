#include "eval/MapQuality.hpp"

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace unimap::eval {
namespace {

// A square of edge_m on the plane z = height_m, one point per spacing_m
// cell, moved along z by Gaussian noise of sigma_m (seeded).
std::vector<Eigen::Vector3f> Plane(double edge_m, double spacing_m, double height_m, double sigma_m,
                                   unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma_m > 0.0 ? sigma_m : 1.0);
  std::vector<Eigen::Vector3f> points;
  const int n = static_cast<int>(std::lround(edge_m / spacing_m));
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double z = height_m + (sigma_m > 0.0 ? noise(rng) : 0.0);
      points.emplace_back(static_cast<float>(i * spacing_m), static_cast<float>(j * spacing_m), static_cast<float>(z));
    }
  }
  return points;
}

// Only the points farther than the radius from the square's edges are
// evaluated by the analytic checks: the others see half a disk.
std::vector<Eigen::Vector3f> Interior(const std::vector<Eigen::Vector3f>& points, double edge_m, double margin_m) {
  std::vector<Eigen::Vector3f> inner;
  for (const Eigen::Vector3f& p : points) {
    if (p.x() > margin_m && p.y() > margin_m && p.x() < edge_m - margin_m && p.y() < edge_m - margin_m) {
      inner.push_back(p);
    }
  }
  return inner;
}

TEST(MapQualityTest, ANoiseFreePlaneIsPlanarWithTheVarianceFloor) {
  const MapQuality q = ComputeMapQuality(Plane(4.0, 0.05, 1.0, 0.0));
  EXPECT_EQ(q.points, 6400u);
  EXPECT_EQ(q.evaluated, q.points);
  EXPECT_DOUBLE_EQ(q.planar_share, 1.0);
  EXPECT_NEAR(q.mean_plane_variance_m2, MapQualityOptions{}.min_variance_m2, 1e-12);
}

TEST(MapQualityTest, PlaneVarianceIsTheNoiseVariance) {
  // sigma 1 cm across the plane: the smallest eigenvalue is sigma^2 (the
  // in-plane grid adds nothing across it).
  const double sigma = 0.01;
  const MapQuality q = ComputeMapQuality(Plane(3.0, 0.02, 0.0, sigma));
  EXPECT_NEAR(q.mean_plane_variance_m2, sigma * sigma, 0.1 * sigma * sigma);
  EXPECT_GT(q.planar_share, 0.99);
}

TEST(MapQualityTest, EntropyGrowsByTheLogOfTheNoiseRatio) {
  // The in-plane terms of 0.5 ln det(2 pi e Sigma) are the same for both
  // planes; across the plane sigma doubles: the entropy grows by ln 2.
  MapQualityOptions options;
  options.max_points = 0;
  const std::vector<Eigen::Vector3f> fine = Plane(3.0, 0.02, 0.0, 0.005);
  const std::vector<Eigen::Vector3f> coarse = Plane(3.0, 0.02, 0.0, 0.01);
  const double difference =
      ComputeMapQuality(coarse, options).mean_map_entropy - ComputeMapQuality(fine, options).mean_map_entropy;
  EXPECT_NEAR(difference, std::log(2.0), 0.03);
}

TEST(MapQualityTest, EntropyMatchesAUniformDiskWithNoiseAcrossIt) {
  // Uniform disk of radius r: in-plane variance r^2 / 4 per axis; across it
  // sigma^2: h = 0.5 ln((2 pi e)^3 (r^2 / 4)^2 sigma^2). Points within r of
  // the square's border (10 % of them with r = 0.1 m on 4 m) see less than a
  // disk and lower the mean a little.
  const double sigma = 0.01;
  MapQualityOptions options;
  options.radius_m = 0.1;
  options.max_points = 0;
  const double two_pi_e = 2.0 * M_PI * std::exp(1.0);
  const double r2 = options.radius_m * options.radius_m;
  const double expected = 0.5 * std::log(std::pow(two_pi_e, 3) * std::pow(r2 / 4.0, 2) * sigma * sigma);
  const MapQuality q = ComputeMapQuality(Plane(4.0, 0.01, 0.0, sigma), options);
  EXPECT_LT(q.mean_map_entropy, expected);
  EXPECT_NEAR(q.mean_map_entropy, expected, 0.1) << q.mean_map_entropy - expected;
}

TEST(MapQualityTest, ADoubledWallHasHalfItsSeparationSquared) {
  // Two noise-free sheets d apart: within r of a point, the near sheet holds
  // a disk of r^2 and the far one r^2 - d^2 (areas), so the variance across
  // them is d^2 p q with p, q those shares.
  const double d = 0.15;
  std::vector<Eigen::Vector3f> wall = Plane(3.0, 0.02, 0.0, 0.0);
  const std::vector<Eigen::Vector3f> second = Plane(3.0, 0.02, d, 0.0);
  wall.insert(wall.end(), second.begin(), second.end());
  const double r2 = MapQualityOptions{}.radius_m * MapQualityOptions{}.radius_m;
  const double p = r2 / (2.0 * r2 - d * d);
  const double expected = d * d * p * (1.0 - p);
  MapQualityOptions options;
  options.max_points = 0;
  const MapQuality q = ComputeMapQuality(Interior(wall, 3.0, 0.3), options);
  const MapQuality single = ComputeMapQuality(Interior(Plane(3.0, 0.02, 0.0, 0.0), 3.0, 0.3), options);
  // Interior() keeps the interior of both sheets; their own edges are then
  // 0.3 m in, so a strip of points sees a partial disk: 8 % tolerance.
  EXPECT_NEAR(q.mean_plane_variance_m2, expected, 0.08 * expected);
  EXPECT_LT(q.planar_share, 0.3);
  EXPECT_DOUBLE_EQ(single.planar_share, 1.0);
  EXPECT_GT(q.mean_map_entropy, single.mean_map_entropy + 5.0);
}

TEST(MapQualityTest, SparsePointsAndBadOptions) {
  const std::vector<Eigen::Vector3f> sparse = {Eigen::Vector3f(0, 0, 0), Eigen::Vector3f(5, 0, 0)};
  const MapQuality q = ComputeMapQuality(sparse);
  EXPECT_EQ(q.points, 2u);
  EXPECT_EQ(q.evaluated, 0u);
  EXPECT_EQ(ComputeMapQuality({}).points, 0u);
  MapQualityOptions bad;
  bad.radius_m = 0.0;
  EXPECT_THROW(ComputeMapQuality(sparse, bad), std::invalid_argument);
  bad = MapQualityOptions{};
  bad.planar_ratio = 1.5;
  EXPECT_THROW(ComputeMapQuality(sparse, bad), std::invalid_argument);
}

TEST(MapQualityTest, StridedSubsetIsDeterministic) {
  const std::vector<Eigen::Vector3f> plane = Plane(3.0, 0.02, 0.0, 0.01);
  MapQualityOptions options;
  options.max_points = 1000;
  const MapQuality a = ComputeMapQuality(plane, options);
  const MapQuality b = ComputeMapQuality(plane, options);
  EXPECT_LE(a.evaluated, 1000u);
  EXPECT_EQ(a.mean_map_entropy, b.mean_map_entropy);
  EXPECT_NEAR(a.mean_plane_variance_m2, 1e-4, 1.5e-5);
}

}  // namespace
}  // namespace unimap::eval
