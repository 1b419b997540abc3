// SurfaceDistanceLayer with DistanceMapOptions::coarse_beyond_m: far returns
// kept in 3x3x3-voxel cells.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "map/SurfaceDistanceLayer.hpp"

namespace unimap::map {
namespace {

using V3 = Eigen::Vector3f;

constexpr float kWallX = 15.02f;  // a wall 15 m from the sensor at the origin

DistanceMapOptions Options(double coarse_beyond_m) {
  DistanceMapOptions o;
  o.resolution_m = 0.1;
  o.clamp_distance_m = 0.5;
  o.coarse_beyond_m = coarse_beyond_m;
  return o;
}

// Returns of a 3 x 3 m wall at x = kWallX (5 mm of noise) and of a floor
// within 2 m of the origin (z = -0.97), as seen from the origin.
std::vector<V3> WallAndFloor() {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.5f, 1.5f);
  std::normal_distribution<float> noise(0.0f, 0.005f);
  std::vector<V3> points;
  for (int i = 0; i < 40000; ++i) points.emplace_back(kWallX + noise(rng), u(rng), u(rng));
  for (int i = 0; i < 8000; ++i) points.emplace_back(u(rng), u(rng), -0.97f + noise(rng));
  return points;
}

int ElementsBeyond(const SurfaceDistanceLayer& layer, float x, float* max_scale) {
  int count = 0;
  *max_scale = 0.0f;
  layer.surfaces().ForEach([&](std::uint64_t, const SurfacePoints::Element& e) {
    if (e.mean_m.x() < x) return;
    ++count;
    *max_scale = std::max(*max_scale, e.scale);
  });
  return count;
}

// The same wall and floor mapped without cells (fine) and with cells past 10 m (coarse).
class SurfaceDistanceLayerCoarseCells : public ::testing::Test {
 protected:
  void SetUp() override {
    fine.Insert(WallAndFloor(), V3::Zero());
    coarse.Insert(WallAndFloor(), V3::Zero());
  }
  SurfaceDistanceLayer fine{Options(0.0)};
  SurfaceDistanceLayer coarse{Options(10.0)};
};

TEST_F(SurfaceDistanceLayerCoarseCells, FarReturnsKeepOneElementPerCell) {
  float fine_scale = 0.0f, coarse_scale = 0.0f;
  // The wall covers 30 x 30 voxels (a few of its noisiest returns fall in
  // the voxels in front): 900 elements and more, or 10-11 x 10-11 cells.
  const int voxels = ElementsBeyond(fine, 14.0f, &fine_scale);
  EXPECT_GE(voxels, 900);
  EXPECT_LE(voxels, 930);
  const int cells = ElementsBeyond(coarse, 14.0f, &coarse_scale);
  EXPECT_GE(cells, 100);
  EXPECT_LE(cells, 121);
  EXPECT_EQ(fine_scale, 1.0f);
  EXPECT_EQ(coarse_scale, static_cast<float>(DistanceMapOptions::kCoarseCell));
  EXPECT_EQ(coarse.counts().points_coarse, 40000u);
  EXPECT_EQ(fine.counts().points_coarse, 0u);
}

TEST_F(SurfaceDistanceLayerCoarseCells, NearReturnsAreKeptAsWithoutCells) {
  std::vector<V3> fine_floor, coarse_floor;
  for (const V3& c : fine.VoxelCenters()) {
    if (c.x() < 5.0f) fine_floor.push_back(c);
  }
  for (const V3& c : coarse.VoxelCenters()) {
    if (c.x() < 5.0f) coarse_floor.push_back(c);
  }
  ASSERT_EQ(fine_floor.size(), coarse_floor.size());
  for (std::size_t i = 0; i < fine_floor.size(); ++i) EXPECT_EQ(fine_floor[i], coarse_floor[i]);
}

TEST_F(SurfaceDistanceLayerCoarseCells, DistancesReachBetweenTheCells) {
  // A wall turned by 30 deg about z, 15 m away: a cell's nearest coarse
  // element's mean lies up to a cell's half diagonal beside it, beyond a
  // voxel-sized disk.
  const V3 normal(std::cos(0.5236f), std::sin(0.5236f), 0.0f);
  const V3 along(-normal.y(), normal.x(), 0.0f);
  const V3 origin(kWallX, 0.0f, 0.0f);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.5f, 1.5f);
  std::normal_distribution<float> noise(0.0f, 0.005f);
  std::vector<V3> points;
  for (int i = 0; i < 40000; ++i)
    points.push_back(origin + u(rng) * along + V3(0.0f, 0.0f, u(rng)) + noise(rng) * normal);
  SurfaceDistanceLayer turned(Options(10.0));
  turned.Insert(points, V3::Zero());
  const auto field = turned.Export(V3(10.0f, 0.0f, 0.0f), 8.0, 1);
  // Every cell centre in front of the wall's middle, 0.1-0.4 m from it,
  // reads its height above the wall.
  int checked = 0;
  for (float x = 13.55f; x < 15.5f; x += 0.1f) {
    for (float y = -1.55f; y < 1.6f; y += 0.1f) {
      for (float z = -0.95f; z < 1.0f; z += 0.1f) {
        const V3 q(x, y, z);
        const float height = normal.dot(q - origin);
        if (height < -0.4f || height > -0.1f || std::abs(along.dot(q - origin)) > 1.0f) continue;
        EXPECT_NEAR(field->Distance(q), -height, 0.004f) << q.transpose();
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST_F(SurfaceDistanceLayerCoarseCells, SurfaceMeansSampleACellsPlaneAVoxelApart) {
  int fine_wall = 0, coarse_wall = 0;
  for (const V3& p : fine.SurfaceMeans()) fine_wall += p.x() > 14.0f ? 1 : 0;
  for (const V3& p : coarse.SurfaceMeans()) {
    if (p.x() < 14.0f) continue;
    ++coarse_wall;
    EXPECT_NEAR(p.x(), kWallX, 0.01f);
    EXPECT_LE(std::abs(p.y()), 1.65f);
    EXPECT_LE(std::abs(p.z()), 1.65f);
  }
  float scale = 0.0f;
  // Nine points per planar cell: about as many as the fine wall's means.
  EXPECT_EQ(coarse_wall, 9 * ElementsBeyond(coarse, 14.0f, &scale));
  EXPECT_NEAR(static_cast<double>(coarse_wall) / fine_wall, 1.0, 0.35);
}

TEST_F(SurfaceDistanceLayerCoarseCells, OptionsRejectANegativeRange) {
  DistanceMapOptions o = Options(-1.0);
  std::string why;
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_NE(why.find("coarse_beyond_m"), std::string::npos) << why;
  o.coarse_beyond_m = 0.0;
  EXPECT_TRUE(o.IsValid(&why)) << why;
}

}  // namespace
}  // namespace unimap::map
