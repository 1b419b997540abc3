#include "map/CompactPoints.hpp"

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
  EXPECT_EQ(compact.bytes(), points.size() * 6);
  const std::vector<Eigen::Vector3f> back = compact.Expand();
  float worst = 0.0f;
  for (std::size_t i = 0; i < points.size(); ++i) worst = std::max(worst, (back[i] - points[i]).cwiseAbs().maxCoeff());
  EXPECT_LE(worst, 0.5f * compact.step() * 1.001f);
  EXPECT_LT(worst, 0.001f);  // under a millimetre for +-60 m
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
