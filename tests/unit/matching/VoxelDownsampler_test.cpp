#include "matching/VoxelDownsampler.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

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

// The first index of each voxel, found by a plain ordered set.
std::vector<std::size_t> FirstIndicesReference(const std::vector<Eigen::Vector3f>& points, double voxel_m) {
  std::set<std::uint64_t> seen;
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (seen.insert(VoxelKey(points[i], 1.0 / voxel_m)).second) kept.push_back(i);
  }
  return kept;
}

TEST(VoxelFirstIndices, MatchesAReferenceWithRunsRevisitsAndShuffledOrder) {
  // A scan-like cloud: runs of neighbours sharing a voxel, rings that come
  // back to voxels seen earlier, and points on both sides of zero.
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> jitter(-0.02f, 0.02f);
  std::vector<Eigen::Vector3f> points;
  for (int ring = 0; ring < 8; ++ring) {
    for (int i = 0; i < 2000; ++i) {
      const float angle = 0.0035f * static_cast<float>(i);
      const float range = 5.0f + 0.3f * static_cast<float>(ring % 3);
      points.emplace_back(range * std::cos(angle) + jitter(rng), range * std::sin(angle) + jitter(rng),
                          -1.0f + 0.05f * static_cast<float>(ring) + jitter(rng));
    }
  }
  std::vector<Eigen::Vector3f> shuffled = points;
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  for (const double voxel_m : {0.05, 0.1, 0.3}) {
    const std::vector<std::size_t> in_order = VoxelFirstIndices(points, voxel_m);
    EXPECT_EQ(in_order, FirstIndicesReference(points, voxel_m)) << "voxel " << voxel_m;
    if (voxel_m >= 0.1) {
      EXPECT_LT(in_order.size(), points.size() / 2) << "voxel " << voxel_m;  // runs share voxels
    }
    EXPECT_EQ(VoxelFirstIndices(shuffled, voxel_m), FirstIndicesReference(shuffled, voxel_m)) << "voxel " << voxel_m;
  }
  // Every point in one voxel, and every point in its own.
  const std::vector<Eigen::Vector3f> same(100, Eigen::Vector3f(0.01f, 0.02f, 0.03f));
  EXPECT_EQ(VoxelFirstIndices(same, 0.1), std::vector<std::size_t>{0});
  EXPECT_EQ(VoxelFirstIndices(points, 1e-4), FirstIndicesReference(points, 1e-4));
  EXPECT_TRUE(VoxelFirstIndices({}, 0.1).empty());
}

}  // namespace
}  // namespace unimap::matching
