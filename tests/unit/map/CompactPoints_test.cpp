#include "map/CompactPoints.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace unimap::map {
namespace {

TEST(CompactPointsTest, PointsComeBackWithinHalfAStep) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-60.0f, 60.0f);
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 10000; ++i) points.emplace_back(u(rng), u(rng), u(rng) / 10.0f);
  const CompactPoints compact(points);
  ASSERT_EQ(compact.size(), points.size());
  EXPECT_LE(compact.step(), 60.0f / 32767.0f * 1.0001f);
  // Uniform random coordinates leave deflate nothing to find: about the 6
  // bytes per point of the 16-bit integers, plus zlib's framing.
  EXPECT_LE(compact.bytes(), points.size() * 6 + points.size() / 100 + 64);
  const std::vector<Eigen::Vector3f> back = compact.Expand();
  float worst = 0.0f;
  for (std::size_t i = 0; i < points.size(); ++i) worst = std::max(worst, (back[i] - points[i]).cwiseAbs().maxCoeff());
  EXPECT_LE(worst, 0.5f * compact.step() * 1.001f);
  EXPECT_LT(worst, 0.001f);  // under a millimetre for +-60 m
}

// A surface as a submap holds it (means of 0.1 m voxels on a wall and a
// floor, in voxel order, 1 mm noise): each point comes back exactly as its
// quantised value, the same on every Expand, in far fewer than 6 bytes.
TEST(CompactPointsTest, ASurfaceComesBackExactlyInAFractionOfTheBytes) {
  std::mt19937 rng(5);
  std::normal_distribution<float> noise(0.0f, 0.001f);
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 150; ++i) {
    for (int j = 0; j < 40; ++j) {
      points.emplace_back(0.1f * static_cast<float>(i) - 7.0f, 2.0f + noise(rng), 0.1f * static_cast<float>(j));
      points.emplace_back(0.1f * static_cast<float>(i) - 7.0f, 0.1f * static_cast<float>(j) - 2.0f, noise(rng));
    }
  }
  const CompactPoints compact(points);
  const std::vector<Eigen::Vector3f> back = compact.Expand();
  ASSERT_EQ(back.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      ASSERT_EQ(back[i](a), compact.step() * std::round(points[i](a) / compact.step())) << i << " " << a;
    }
  }
  EXPECT_EQ(compact.Expand(), back);
  EXPECT_LT(compact.bytes(), points.size() * 3);  // measured: 1.6 bytes per point
}

TEST(CompactPointsTest, SmallSetsKeepTheFinestStepAndEmptyIsEmpty) {
  const CompactPoints small({Eigen::Vector3f(0.12345f, -0.5f, 1.0f)});
  EXPECT_EQ(small.step(), CompactPoints::kMinStep);
  EXPECT_NEAR(small.Expand()[0].x(), 0.12345f, 0.5f * CompactPoints::kMinStep + 1e-6f);
  EXPECT_TRUE(CompactPoints().empty());
  EXPECT_TRUE(CompactPoints(std::vector<Eigen::Vector3f>{}).Expand().empty());
  // A non-finite coordinate (not expected) is stored as 0, the others kept.
  const CompactPoints odd({Eigen::Vector3f(std::nanf(""), 2.0f, 3.0f)});
  EXPECT_EQ(odd.Expand()[0].x(), 0.0f);
  EXPECT_NEAR(odd.Expand()[0].z(), 3.0f, odd.step());
}

}  // namespace
}  // namespace unimap::map
