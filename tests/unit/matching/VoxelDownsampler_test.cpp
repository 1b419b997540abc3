#include "matching/VoxelDownsampler.hpp"

#include <gtest/gtest.h>

namespace unimap::matching {
namespace {

TEST(VoxelDownsample, KeepsFirstPointPerVoxel) {
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 10; ++i) {
    points.emplace_back(0.1f * static_cast<float>(i) + 0.01f, 0.05f, -0.05f);
    points.emplace_back(0.1f * static_cast<float>(i) + 0.06f, 0.05f, -0.05f);  // same 0.1 m voxel
  }
  const auto kept = VoxelDownsample(points, 0.1, 0, 1);
  ASSERT_EQ(kept.size(), 10u);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(kept[i], points[2 * i]);
}

TEST(VoxelDownsample, CapIsDeterministicPerSeed) {
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 1000; ++i) points.emplace_back(static_cast<float>(i), 0.0f, 0.0f);
  const auto a = VoxelDownsample(points, 0.5, 100, 7);
  const auto b = VoxelDownsample(points, 0.5, 100, 7);
  const auto c = VoxelDownsample(points, 0.5, 100, 8);
  ASSERT_EQ(a.size(), 100u);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
}

}  // namespace
}  // namespace unimap::matching
