#include "map/CellPlanes.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace unimap::map {
namespace {

using V3 = Eigen::Vector3f;

TEST(CellPlanes, CellsStartWithoutAPlane) {
  const CellPlanes planes(8);
  EXPECT_EQ(planes.size(), 8u);
  EXPECT_EQ(planes.MemoryBytes(), 32u);
  V3 normal;
  float height = 0.0f;
  for (std::size_t i = 0; i < 8; ++i) EXPECT_FALSE(planes.Get(i, &normal, &height)) << i;
}

TEST(CellPlanes, NormalsKeepTheirDirectionWithinADegreeAndHeightsTheirTenthOfAMillimetre) {
  std::mt19937 rng(3);
  std::normal_distribution<float> gauss(0.0f, 1.0f);
  std::uniform_real_distribution<float> heights(-0.6f, 0.6f);
  CellPlanes planes(2000);
  std::vector<V3> normals;
  std::vector<float> set_heights;
  for (std::size_t i = 0; i < planes.size(); ++i) {
    // Random directions plus the axes (the folds of the octahedral map).
    V3 n(gauss(rng), gauss(rng), gauss(rng));
    if (i < 6) n = V3::Zero(), n(static_cast<int>(i / 2)) = i % 2 == 0 ? 1.0f : -1.0f;
    normals.push_back(n.normalized());
    set_heights.push_back(heights(rng));
    planes.Set(i, normals.back(), set_heights.back());
  }
  const float cos_one_degree = std::cos(1.0f * static_cast<float>(M_PI) / 180.0f);
  for (std::size_t i = 0; i < planes.size(); ++i) {
    V3 normal;
    float height = 0.0f;
    ASSERT_TRUE(planes.Get(i, &normal, &height)) << i;
    EXPECT_NEAR(normal.norm(), 1.0f, 1e-6f) << i;
    EXPECT_GT(normal.dot(normals[i]), cos_one_degree) << i;
    EXPECT_NEAR(height, set_heights[i], 0.5f * CellPlanes::kHeightStepM + 1e-6f) << i;
  }
}

TEST(CellPlanes, HeightsBeyondTheRangeSaturate) {
  CellPlanes planes(2);
  planes.Set(0, V3::UnitZ(), 10.0f);
  planes.Set(1, V3::UnitZ(), -10.0f);
  V3 normal;
  float height = 0.0f;
  ASSERT_TRUE(planes.Get(0, &normal, &height));
  EXPECT_NEAR(height, 32767 * CellPlanes::kHeightStepM, 1e-6f);
  ASSERT_TRUE(planes.Get(1, &normal, &height));  // saturated, still a plane
  EXPECT_NEAR(height, -32767 * CellPlanes::kHeightStepM, 1e-6f);
}

}  // namespace
}  // namespace unimap::map
