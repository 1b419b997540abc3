#include "eval/LargestPlanes.hpp"

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

namespace unimap::eval {
namespace {

// A w_m x h_m rectangle of the plane normal . x = offset_m, one point per
// spacing_m, moved along the normal by Gaussian noise of sigma_m (seeded),
// or by +-split_m / 2 alternately (a wall mapped twice, split_m apart).
struct Sheet {
  Eigen::Vector3d normal;
  double offset_m = 0.0;
  double w_m = 4.0, h_m = 3.0, spacing_m = 0.02;
  double sigma_m = 0.0;
  double split_m = 0.0;
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();  // added to every point (along the plane)
};

void AddSheet(const Sheet& s, unsigned seed, std::vector<Eigen::Vector3f>* points) {
  const Eigen::Vector3d n = s.normal.normalized();
  const Eigen::Vector3d u = n.unitOrthogonal();
  const Eigen::Vector3d v = n.cross(u);
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  const int nu = static_cast<int>(std::lround(s.w_m / s.spacing_m));
  const int nv = static_cast<int>(std::lround(s.h_m / s.spacing_m));
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      double across = s.sigma_m * noise(rng);
      if (s.split_m > 0.0) across += ((i + j) % 2 == 0 ? 0.5 : -0.5) * s.split_m;
      const Eigen::Vector3d p = s.offset_m * n + (i * s.spacing_m - 0.5 * s.w_m) * u +
                                (j * s.spacing_m - 0.5 * s.h_m) * v + across * n + s.shift;
      points->push_back(p.cast<float>());
    }
  }
}

TEST(LargestPlanesTest, ANoiseFreePlaneHasNoThickness) {
  std::vector<Eigen::Vector3f> points;
  AddSheet({Eigen::Vector3d(0.0, 0.0, 1.0), 1.5}, 1, &points);
  const std::vector<MapPlane> planes = FindLargestPlanes(points);
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0].points, points.size());
  EXPECT_LT(planes[0].thickness_m, 1e-6);
  EXPECT_NEAR(planes[0].offset_m, 1.5, 1e-5);
  EXPECT_NEAR(planes[0].normal.z(), 1.0, 1e-6);
}

TEST(LargestPlanesTest, ThicknessIsTheNoiseStandardDeviation) {
  // 30,000 points with sigma 1 cm across: the robust spread is sigma within
  // its sampling error (about 1 %), and the band of 0.1 m (10 sigma) keeps
  // every point.
  std::vector<Eigen::Vector3f> points;
  AddSheet({Eigen::Vector3d(1.0, 0.0, 0.0), 2.0, 4.0, 3.0, 0.02, 0.01}, 3, &points);
  const std::vector<MapPlane> planes = FindLargestPlanes(points);
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_NEAR(planes[0].thickness_m, 0.01, 0.0005);
  EXPECT_EQ(planes[0].points, points.size());
}

TEST(LargestPlanesTest, ADoubledWallReadsAsThickAsItsSplit) {
  // Two sheets 4 cm apart, no noise: every point is 2 cm from the fitted
  // mid-plane, so the robust spread is 1.4826 x 2 cm.
  std::vector<Eigen::Vector3f> points;
  AddSheet({Eigen::Vector3d(0.0, 1.0, 0.0), 1.2, 4.0, 3.0, 0.02, 0.0, 0.04}, 5, &points);
  const std::vector<MapPlane> planes = FindLargestPlanes(points);
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_NEAR(planes[0].thickness_m, 1.4826 * 0.02, 1e-4);
}

TEST(LargestPlanesTest, ARoomsPlanesComeLargestFirstEachWithItsOwnNoise) {
  // A room's corner: floor 6 x 4 m at z = -1 (sigma 5 mm), standing on it a
  // 6 x 3 m wall at y = 2 (1 cm) and a 4 x 3 m wall at x = 3 (2 cm).
  std::vector<Eigen::Vector3f> points;
  const Eigen::Vector3d up(0.0, 0.0, 0.5);
  AddSheet({Eigen::Vector3d(0.0, 0.0, 1.0), -1.0, 4.0, 6.0, 0.04, 0.005}, 11, &points);
  AddSheet({Eigen::Vector3d(0.0, 1.0, 0.0), 2.0, 6.0, 3.0, 0.04, 0.01, 0.0, up}, 12, &points);
  AddSheet({Eigen::Vector3d(1.0, 0.0, 0.0), 3.0, 4.0, 3.0, 0.04, 0.02, 0.0, up}, 13, &points);
  const std::vector<MapPlane> planes = FindLargestPlanes(points);
  ASSERT_EQ(planes.size(), 3u);
  EXPECT_NEAR(std::abs(planes[0].normal.z()), 1.0, 1e-3);
  EXPECT_NEAR(planes[0].offset_m, 1.0, 0.01);
  EXPECT_NEAR(std::abs(planes[1].normal.y()), 1.0, 1e-3);
  EXPECT_NEAR(std::abs(planes[2].normal.x()), 1.0, 1e-3);
  // Where two planes meet, the other plane's points within band_m (about 2 %
  // of a plane's) join its spread: checked to 10 %.
  EXPECT_NEAR(planes[0].thickness_m, 0.005, 0.0005);
  EXPECT_NEAR(planes[1].thickness_m, 0.01, 0.001);
  EXPECT_NEAR(planes[2].thickness_m, 0.02, 0.002);
  EXPECT_GE(planes[0].points, planes[1].points);
  EXPECT_GE(planes[1].points, planes[2].points);
}

TEST(LargestPlanesTest, StopsAtPlanesBelowTheMinimumShare) {
  std::vector<Eigen::Vector3f> points;
  AddSheet({Eigen::Vector3d(0.0, 0.0, 1.0), -1.0, 6.0, 6.0, 0.05}, 1, &points);
  // 100 of 14,500 points, 2 m above the floor (clear of its band).
  AddSheet({Eigen::Vector3d(1.0, 0.0, 0.0), 2.0, 0.5, 0.5, 0.05, 0.0, 0.0, Eigen::Vector3d(0.0, 0.0, 1.0)}, 2, &points);
  EXPECT_EQ(FindLargestPlanes(points).size(), 1u);
  LargestPlanesOptions options;
  options.min_share = 0.005;
  EXPECT_EQ(FindLargestPlanes(points, options).size(), 2u);
}

TEST(LargestPlanesTest, AFanThroughTheSensorIsNotAPlane) {
  // A scanner's own fan of rays (a plane through the map's origin, as a
  // standing tilting scanner's slices are) holds more points than the wall.
  std::vector<Eigen::Vector3f> points;
  AddSheet({Eigen::Vector3d(0.0, 0.0, 1.0), 0.0, 2.0, 2.0, 0.01}, 1, &points);  // 40,000 points
  AddSheet({Eigen::Vector3d(1.0, 0.0, 0.0), 1.5, 3.0, 2.0, 0.02, 0.01, 0.0, Eigen::Vector3d(0.0, 0.0, 1.5)}, 2,
           &points);  // 15,000 points
  const std::vector<MapPlane> planes = FindLargestPlanes(points);
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_NEAR(planes[0].offset_m, 1.5, 0.01);
  EXPECT_NEAR(planes[0].thickness_m, 0.01, 0.001);
}

TEST(LargestPlanesTest, DeterministicAndCheckedOptions) {
  std::vector<Eigen::Vector3f> points;
  AddSheet({Eigen::Vector3d(0.3, 0.2, 1.0), 1.0, 4.0, 3.0, 0.05, 0.02}, 9, &points);
  const std::vector<MapPlane> a = FindLargestPlanes(points);
  const std::vector<MapPlane> b = FindLargestPlanes(points);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].thickness_m, b[i].thickness_m);
  EXPECT_TRUE(FindLargestPlanes({}).empty());
  LargestPlanesOptions bad;
  bad.band_m = 0.01;  // narrower than the inlier distance
  std::string why;
  EXPECT_FALSE(bad.IsValid(&why));
  EXPECT_THROW(FindLargestPlanes(points, bad), std::invalid_argument);
}

}  // namespace
}  // namespace unimap::eval
