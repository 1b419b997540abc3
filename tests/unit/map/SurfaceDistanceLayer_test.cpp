#include "map/SurfaceDistanceLayer.hpp"

#include <array>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>

namespace unimap::map {
namespace {

using V3 = Eigen::Vector3f;

constexpr double kResolution = 0.1;
constexpr double kClamp = 0.5;

DistanceMapOptions Options(bool distances = true) {
  DistanceMapOptions o;
  o.resolution_m = kResolution;
  o.clamp_distance_m = kClamp;
  o.compute_distances = distances;
  return o;
}

// Returns of a floor (z = 0.03) and a wall (x = 2.02) around the origin,
// seen from (0, 0, 1), with 5 mm of noise.
std::vector<V3> FloorAndWall(std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.5f, 1.5f);
  std::normal_distribution<float> noise(0.0f, 0.005f);
  std::vector<V3> points;
  for (int i = 0; i < 4000; ++i) points.emplace_back(u(rng), u(rng), 0.03f + noise(rng));
  for (int i = 0; i < 3000; ++i) points.emplace_back(2.02f + noise(rng), u(rng), 0.75f + 0.5f * u(rng));
  return points;
}

// The distance from p to the element of the surface voxel whose centre is
// nearest to p (what the layer's waves find, like DynamicEDT3D); false when
// two voxel centres are equally near (either may be taken).
// Only occupied voxels count (VoxelCenters()).
bool NearestVoxelDistance(const SurfaceDistanceLayer& layer, const V3& p, float* distance) {
  std::set<std::array<int, 3>> occupied;
  for (const V3& c : layer.VoxelCenters()) {
    const Eigen::Vector3i k = (c / 0.1f).array().floor().cast<int>();
    occupied.insert({k.x(), k.y(), k.z()});
  }
  float best_sq = 1e9f, second_sq = 1e9f;
  const SurfacePoints::Element* best = nullptr;
  layer.surfaces().ForEach([&](std::uint64_t key, const SurfacePoints::Element& e) {
    const V3 center((static_cast<float>((key >> 32) & 0xffff) - 32768.0f + 0.5f) * 0.1f,
                    (static_cast<float>((key >> 16) & 0xffff) - 32768.0f + 0.5f) * 0.1f,
                    (static_cast<float>(key & 0xffff) - 32768.0f + 0.5f) * 0.1f);
    const Eigen::Vector3i k = (center / 0.1f).array().floor().cast<int>();
    if (occupied.count({k.x(), k.y(), k.z()}) == 0) return;
    const float sq = (center - p).squaredNorm();
    if (sq < best_sq) {
      second_sq = best_sq;
      best_sq = sq;
      best = &e;
    } else if (sq < second_sq) {
      second_sq = sq;
    }
  });
  if (best == nullptr || second_sq - best_sq < 1e-4f) return false;
  *distance = std::min(layer.surfaces().SignedDistance(*best, p), static_cast<float>(kClamp));
  return true;
}

TEST(SurfaceDistanceLayer, DistancesAreToTheSurfaceInsideTheVoxels) {
  SurfaceDistanceLayer layer(Options());
  layer.Insert(FloorAndWall(1), V3(0.0f, 0.0f, 1.0f));
  const auto field = layer.Export(V3::Zero(), 0.0, 1);
  // Above the middle of the floor: the height above z = 0.03 (cell centres).
  for (const float z : {0.05f, 0.15f, 0.25f, 0.35f}) {
    EXPECT_NEAR(field->Distance(V3(-0.45f, 0.35f, z)), std::abs(z - 0.03f), 0.01f) << z;
  }
  // In front of the wall, and farther than the clamp from everything.
  EXPECT_NEAR(field->Distance(V3(1.85f, 0.05f, 0.75f)), 0.17f, 0.01f);
  EXPECT_EQ(field->Distance(V3(0.05f, 0.05f, 1.05f)), static_cast<float>(kClamp));
  const SurfaceDistanceCounts counts = layer.counts();
  EXPECT_EQ(counts.points_added, 7000u);
  EXPECT_EQ(counts.points_out_of_range, 0u);
  EXPECT_GT(counts.elements, 900u);
}

TEST(SurfaceDistanceLayer, WavesFindTheNearestSurfaceVoxel) {
  SurfaceDistanceLayer layer(Options());
  const std::vector<V3> points = FloorAndWall(2);
  // Three scans: elements appear and move between them.
  for (int part = 0; part < 3; ++part) {
    const std::vector<V3> slice(points.begin() + part * 2000,
                                points.begin() + std::min<int>(7000, (part + 1) * 2000 + 1000));
    layer.Insert(slice, V3(0.0f, 0.0f, 1.0f));
  }
  const auto field = layer.Export(V3::Zero(), 0.0, 1);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.2f, 2.4f);
  int checked = 0;
  for (int i = 0; i < 400; ++i) {
    // Cell centres (the field's samples) near the surfaces.
    const V3 p = ((V3(u(rng), u(rng) * 0.5f, u(rng) * 0.4f) / 0.1f).array().floor() + 0.5f).matrix() * 0.1f;
    float truth = 0.0f;
    if (!NearestVoxelDistance(layer, p, &truth) || !(truth < kClamp - 0.05)) continue;
    // Elements change by up to kMoveTolerance voxels before their blocks are redone.
    EXPECT_NEAR(field->Distance(p), truth, SurfaceDistanceLayer::kMoveTolerance * kResolution + 1e-3) << p.transpose();
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(SurfaceDistanceLayer, EnablingLaterGivesTheSameField) {
  SurfaceDistanceLayer incremental(Options());
  SurfaceDistanceLayer batch(Options(false));
  const std::vector<V3> points = FloorAndWall(4);
  for (int part = 0; part < 7; ++part) {
    const std::vector<V3> slice(points.begin() + part * 1000, points.begin() + (part + 1) * 1000);
    incremental.Insert(slice, V3(0.0f, 0.0f, 1.0f));
    batch.Insert(slice, V3(0.0f, 0.0f, 1.0f));
  }
  EXPECT_EQ(batch.Export(V3::Zero(), 0.0, 1)->CellCount(), 0u);  // no distances yet
  batch.EnableDistances();
  const auto a = incremental.Export(V3::Zero(), 0.0, 1);
  const auto b = batch.Export(V3::Zero(), 0.0, 1);
  ASSERT_EQ(a->dims(), b->dims());
  ASSERT_TRUE(a->origin().isApprox(b->origin()));
  float largest = 0.0f;
  for (int x = 0; x < a->dims().x(); ++x) {
    for (int y = 0; y < a->dims().y(); ++y) {
      for (int z = 0; z < a->dims().z(); ++z) {
        const Eigen::Vector3i cell(x, y, z);
        largest = std::max(largest, std::abs(a->CellDistance(cell) - b->CellDistance(cell)));
      }
    }
  }
  EXPECT_LE(largest, SurfaceDistanceLayer::kMoveTolerance * kResolution + 1e-3);
}

TEST(SurfaceDistanceLayer, ExportsShareUnchangedBlocksAndFollowTheBox) {
  SurfaceDistanceLayer layer(Options());
  layer.Insert(FloorAndWall(5), V3(0.0f, 0.0f, 1.0f));
  const auto first = layer.Export(V3::Zero(), 0.0, 1);
  const auto again = layer.Export(V3::Zero(), 0.0, 2);
  EXPECT_EQ(again->sequence(), 2u);
  EXPECT_EQ(again->StoredBlocks(), first->StoredBlocks());
  EXPECT_EQ(again->Distance(V3(0.05f, 0.05f, 0.25f)), first->Distance(V3(0.05f, 0.05f, 0.25f)));
  // A box of 0.5 m around (-1.2, 0, 0) leaves the wall out.
  const auto near = layer.Export(V3(-1.2f, 0.0f, 0.0f), 0.5, 3);
  EXPECT_LT(near->StoredBlocks(), first->StoredBlocks());
  EXPECT_EQ(near->Distance(V3(1.85f, 0.05f, 0.75f)), static_cast<float>(kClamp));
}

TEST(SurfaceDistanceLayer, PointsOutsideTheKeyRangeAreDroppedAndCounted) {
  SurfaceDistanceLayer layer(Options());
  layer.Insert({V3(1e5f, 0.0f, 0.0f), V3(0.0f, std::nanf(""), 0.0f), V3(0.5f, 0.5f, 0.5f)}, V3::Zero());
  EXPECT_EQ(layer.counts().points_added, 1u);
  EXPECT_EQ(layer.counts().points_out_of_range, 2u);
  EXPECT_EQ(layer.VoxelCenters().size(), 1u);
  EXPECT_TRUE(layer.VoxelCenters().front().isApprox(V3(0.55f, 0.55f, 0.55f)));
}

// Returns on a patch of floor z = 0.03 over x in [x0, x1], |y| <= 0.5.
std::vector<V3> FloorPatch(float x0, float x1, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> ux(x0, x1), uy(-0.5f, 0.5f);
  std::normal_distribution<float> noise(0.0f, 0.003f);
  std::vector<V3> points;
  for (int i = 0; i < 1500; ++i) points.emplace_back(ux(rng), uy(rng), 0.03f + noise(rng));
  return points;
}

// A sensor 0.12 m above a floor sees the floor 5-6 m away: its rays run
// through the floor's voxel layer (z in [0, 0.1]) at 2-4 m without crossing
// the floor. Those voxels keep their occupancy (OctoMap's ray insertion
// would clear them after ~9 such scans).
TEST(SurfaceDistanceLayer, GrazingRaysDoNotClearTheSurfaceTheyRunAlong) {
  SurfaceDistanceLayer layer(Options());
  for (std::uint32_t scan = 0; scan < 3; ++scan) layer.Insert(FloorPatch(2.0f, 4.0f, scan), V3(0.0f, 0.0f, 1.0f));
  const std::size_t occupied = layer.counts().occupied;
  ASSERT_GE(occupied, 190u);  // 2 m x 1 m of 0.1 m voxels
  for (std::uint32_t scan = 0; scan < 20; ++scan) {
    layer.Insert(FloorPatch(5.0f, 6.0f, 100 + scan), V3(0.0f, 0.0f, 0.12f));
  }
  EXPECT_EQ(layer.counts().voxels_cleared, 0u);
  const auto field = layer.Export(V3::Zero(), 0.0, 1);
  EXPECT_NEAR(field->Distance(V3(3.05f, 0.05f, 0.15f)), 0.12f, 0.01f);  // the floor under it is still there
}

// Rays that pass through a wall to returns behind it (a door opened) are
// evidence that the wall is gone: its voxels are cleared and their cells refilled.
TEST(SurfaceDistanceLayer, RaysThroughASurfaceClearIt) {
  SurfaceDistanceLayer layer(Options());
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-0.5f, 0.5f);
  std::vector<V3> wall, behind;
  for (int i = 0; i < 1500; ++i) wall.emplace_back(2.02f, u(rng), 1.0f + u(rng));
  for (int i = 0; i < 1500; ++i) behind.emplace_back(4.02f, 2.0f * u(rng), 1.0f + 2.0f * u(rng));
  const V3 sensor(0.0f, 0.0f, 1.0f);
  layer.Insert(wall, sensor);
  const auto before = layer.Export(V3::Zero(), 0.0, 1);
  EXPECT_LT(before->Distance(V3(1.95f, 0.05f, 1.05f)), 0.1f);
  for (int scan = 0; scan < 20; ++scan) layer.Insert(behind, sensor);
  EXPECT_GT(layer.counts().voxels_cleared, 50u);
  const auto after = layer.Export(V3::Zero(), 0.0, 2);
  EXPECT_EQ(after->Distance(V3(1.95f, 0.05f, 1.05f)), static_cast<float>(kClamp));
}

// Many rays of one scan cross the same voxel: it is missed once per scan
// (OctoMap's discretised insertion), and not at all by a scan that also hits
// it (the hit wins).
TEST(SurfaceDistanceLayer, AVoxelIsMissedOncePerScanAndNotWhereTheScanHits) {
  SurfaceDistanceLayer layer(Options(false));
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(-0.5f, 0.5f);
  std::vector<V3> wall, behind;
  for (int i = 0; i < 1500; ++i) wall.emplace_back(2.02f, u(rng), 1.0f + u(rng));
  for (int i = 0; i < 1500; ++i) behind.emplace_back(4.02f, 2.0f * u(rng), 1.0f + 2.0f * u(rng));
  const V3 sensor(0.0f, 0.0f, 1.0f);
  for (int scan = 0; scan < 3; ++scan) layer.Insert(wall, sensor);
  const std::size_t wall_voxels = layer.counts().occupied;
  ASSERT_GE(wall_voxels, 100u);
  std::vector<V3> both = wall;
  both.insert(both.end(), behind.begin(), behind.end());
  layer.Insert(both, sensor);  // hits every wall voxel, rays through them
  EXPECT_EQ(layer.counts().misses, 0u);
  layer.Insert(behind, sensor);  // 1500 rays through about 100 voxels
  EXPECT_GT(layer.counts().misses, 50u);
  EXPECT_LE(layer.counts().misses, wall_voxels);
}

// A wall cleared by rays to a second wall 0.3 m behind it: the cells the
// first wall was nearest to go to the second (the refill), as a brute-force
// search over the occupied voxels finds.
TEST(SurfaceDistanceLayer, RefilledCellsFindTheNextNearestVoxel) {
  SurfaceDistanceLayer layer(Options());
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-0.5f, 0.5f);
  std::vector<V3> front, back;
  for (int i = 0; i < 1500; ++i) front.emplace_back(2.02f, u(rng), 1.0f + u(rng));
  for (int i = 0; i < 3000; ++i) back.emplace_back(2.33f, 1.6f * u(rng), 1.0f + 1.6f * u(rng));
  const V3 sensor(0.0f, 0.0f, 1.0f);
  layer.Insert(front, sensor);
  layer.Insert(back, sensor);
  for (int scan = 0; scan < 20; ++scan) layer.Insert(back, sensor);
  ASSERT_GT(layer.counts().voxels_cleared, 50u);
  const auto field = layer.Export(V3::Zero(), 0.0, 1);
  int checked = 0;
  for (int ix = 15; ix < 23; ++ix) {
    for (int iy = -6; iy < 6; ++iy) {
      for (int iz = 4; iz < 16; ++iz) {
        const V3 p((static_cast<float>(ix) + 0.5f) * 0.1f, (static_cast<float>(iy) + 0.5f) * 0.1f,
                   (static_cast<float>(iz) + 0.5f) * 0.1f);
        float truth = 0.0f;
        if (!NearestVoxelDistance(layer, p, &truth) || !(truth < kClamp - 0.05)) continue;
        EXPECT_NEAR(field->Distance(p), truth, SurfaceDistanceLayer::kMoveTolerance * kResolution + 1e-3)
            << p.transpose();
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 200);
}

// Nearest first: a cell is claimed about once, by its final voxel, not once
// per voxel whose wave passes it. Claims against the cells that end up with
// an owner (within reach of an occupied voxel centre, counted here by brute
// force), when all voxels are waved at once.
TEST(SurfaceDistanceLayer, CellsAreClaimedAboutOnce) {
  SurfaceDistanceLayer layer(Options(false));
  layer.Insert(FloorAndWall(5), V3(0.0f, 0.0f, 1.0f));
  layer.EnableDistances();
  const int reach = static_cast<int>(std::ceil(kClamp / kResolution)) + 1;
  std::set<std::array<int, 3>> owned;
  for (const V3& c : layer.VoxelCenters()) {
    const Eigen::Vector3i k = (c / 0.1f).array().floor().cast<int>();
    for (int dx = -reach; dx <= reach; ++dx) {
      for (int dy = -reach; dy <= reach; ++dy) {
        for (int dz = -reach; dz <= reach; ++dz) {
          if (dx * dx + dy * dy + dz * dz <= reach * reach) owned.insert({k.x() + dx, k.y() + dy, k.z() + dz});
        }
      }
    }
  }
  const double claims = static_cast<double>(layer.counts().cells_claimed);
  EXPECT_GE(claims, static_cast<double>(owned.size()));
  EXPECT_LE(claims, 1.1 * static_cast<double>(owned.size())) << claims << " claims, " << owned.size() << " cells";
}

}  // namespace
}  // namespace unimap::map
