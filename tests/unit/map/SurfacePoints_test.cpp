#include "map/SurfacePoints.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <octomap/OcTree.h>

#include "map/DistanceMap.hpp"
#include "map/OccupancyTree.hpp"

namespace unimap::map {
namespace {

using V3 = Eigen::Vector3f;

constexpr float kRes = 0.1f;

// Uniform random points on the square of half-size half_m about centre in
// the plane with unit normal (fixed seed).
std::vector<V3> SamplePlane(const V3& center, const V3& normal, float half_m, int count, std::uint32_t seed) {
  const V3 u = normal.unitOrthogonal();
  const V3 v = normal.cross(u);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> coord(-half_m, half_m);
  std::vector<V3> points(static_cast<std::size_t>(count));
  for (V3& p : points) p = center + coord(rng) * u + coord(rng) * v;
  return points;
}

DistanceMapOptions PlaneOptions(bool subvoxel, bool signed_surfaces = true) {
  DistanceMapOptions options;
  options.signed_surfaces = signed_surfaces;
  options.resolution_m = kRes;
  options.max_range_m = 4.0;
  options.clamp_distance_m = 0.5;
  options.subvoxel_surfaces = subvoxel;
  return options;
}

// The published field after one scan of the plane seen from sensor.
std::shared_ptr<const DistanceField> PlaneField(bool subvoxel, const V3& center, const V3& normal, const V3& sensor,
                                                bool signed_surfaces = true) {
  DistanceMap map(PlaneOptions(subvoxel, signed_surfaces));
  map.InsertScan(SamplePlane(center, normal, 2.0f, 40000, 11), sensor);
  map.WaitForUpdates();
  return map.Snapshot();
}

// Largest trilinear distance at random points on the plane within 1.2 m of centre.
float MaxOnPlane(const DistanceField& field, const V3& center, const V3& normal) {
  float worst = 0.0f;
  for (const V3& p : SamplePlane(center, normal, 1.2f, 500, 5)) {
    worst = std::max(worst, field.DistanceTrilinear(p, nullptr));
  }
  return worst;
}

// Signed offset along normal (1 mm steps within +-0.2 m) of the smallest
// trilinear distance on the line through foot; the first one on ties.
float ArgminAlongNormal(const DistanceField& field, const V3& foot, const V3& normal) {
  float best = std::numeric_limits<float>::infinity();
  float best_offset = 0.0f;
  for (int i = -200; i <= 200; ++i) {
    const float offset = 0.001f * static_cast<float>(i);
    const float d = field.DistanceTrilinear(foot + offset * normal, nullptr);
    if (d < best) {
      best = d;
      best_offset = offset;
    }
  }
  return best_offset;
}

TEST(SurfacePoints, MeanFollowsTheReturnsThenForgetsExponentially) {
  SurfacePoints surfaces(kRes);
  const std::uint64_t key = SurfacePoints::Pack(Eigen::Vector3i(1, 2, 3));
  const V3 center(0.05f, 0.05f, 0.05f);
  EXPECT_EQ(surfaces.Find(key), nullptr);
  surfaces.Add(key, center, V3(0.02f, 0.05f, 0.08f), nullptr);
  EXPECT_EQ(surfaces.Find(key), nullptr);  // not refreshed yet
  surfaces.Add(key, center, V3(0.04f, 0.07f, 0.06f), nullptr);
  surfaces.Refresh(key, center);
  ASSERT_NE(surfaces.Find(key), nullptr);
  EXPECT_TRUE(surfaces.Find(key)->mean_m.isApprox(V3(0.03f, 0.06f, 0.07f), 1e-5f));
  EXPECT_FALSE(surfaces.Find(key)->planar);  // two points span no plane
  // 48 more at one point fill the plain average (weight 50) ...
  for (int i = 0; i < 48; ++i) surfaces.Add(key, center, V3(0.09f, 0.01f, 0.01f), nullptr);
  surfaces.Refresh(key, center);
  const V3 plain = (V3(0.03f, 0.06f, 0.07f) * 2.0f + V3(0.09f, 0.01f, 0.01f) * 48.0f) / 50.0f;
  EXPECT_TRUE(surfaces.Find(key)->mean_m.isApprox(plain, 1e-5f));
  // ... after which each return moves the mean by 1/50 of its offset.
  surfaces.Add(key, center, V3(0.0f, 0.0f, 0.0f), nullptr);
  surfaces.Refresh(key, center);
  EXPECT_TRUE(surfaces.Find(key)->mean_m.isApprox(plain * (49.0f / 50.0f), 1e-5f));
  surfaces.Erase(key);
  EXPECT_EQ(surfaces.Find(key), nullptr);
  EXPECT_EQ(surfaces.size(), 0u);
}

// Voxel (0, 0, 0) of surfaces given returns of the plane z = 0.02 seen from
// above; its element (null when it has none).
const SurfacePoints::Element* SeenFromAbove(SurfacePoints* surfaces) {
  const std::uint64_t key = SurfacePoints::Pack(Eigen::Vector3i(0, 0, 0));
  const V3 center(0.05f, 0.05f, 0.05f);
  const V3 sensor(0.3f, -0.2f, 2.0f);
  for (const V3& p : SamplePlane(V3(0.05f, 0.05f, 0.02f), V3::UnitZ(), 0.05f, 30, 3)) {
    surfaces->Add(key, center, p, &sensor);
  }
  surfaces->Refresh(key, center);
  return surfaces->Find(key);
}

TEST(SurfacePoints, PlanarReturnsSeenFromOneSideGiveASignedDiskDistance) {
  SurfacePoints surfaces(kRes);
  const SurfacePoints::Element* element = SeenFromAbove(&surfaces);
  ASSERT_NE(element, nullptr);
  ASSERT_TRUE(element->planar);
  EXPECT_TRUE(element->oriented);
  EXPECT_NEAR(element->normal.z(), 1.0f, 1e-4f);  // towards the sensor
  const V3 mean = element->mean_m;
  EXPECT_NEAR(mean.z(), 0.02f, 1e-6f);
  // Above and below the disk: the height, negative behind.
  EXPECT_NEAR(surfaces.SignedDistance(*element, mean + V3(0.03f, 0.0f, 0.3f)), 0.3f, 1e-5f);
  EXPECT_NEAR(surfaces.SignedDistance(*element, mean + V3(0.0f, -0.04f, -0.07f)), -0.07f, 1e-5f);
  // Beside the disk (radius 0.15 m): to its rim, never negative.
  EXPECT_NEAR(surfaces.SignedDistance(*element, mean + V3(0.25f, 0.0f, 0.0f)), 0.1f, 1e-5f);
  EXPECT_NEAR(surfaces.SignedDistance(*element, mean + V3(0.0f, 0.25f, -0.1f)), std::sqrt(0.02f), 1e-5f);
}

// A lone scan line: the surface contains it, its normal is taken across it
// towards the sensor; without a sensor it is only a mean point.
TEST(SurfacePoints, ScanLinesTakeTheNormalAcrossThemTowardsTheSensor) {
  SurfacePoints surfaces(kRes);
  const V3 center(0.05f, 0.05f, 0.05f);
  const V3 sensor(0.045f, 0.05f - 3.0f, 0.03f + 4.0f);  // across the line, level with its middle
  const std::uint64_t viewed = SurfacePoints::Pack(Eigen::Vector3i(0, 0, 0));
  const std::uint64_t unviewed = SurfacePoints::Pack(Eigen::Vector3i(10, 0, 0));  // no neighbour
  for (int i = 0; i < 10; ++i) {
    const V3 p(0.01f * static_cast<float>(i), 0.05f, 0.03f);  // along x
    surfaces.Add(viewed, center, p, &sensor);
    surfaces.Add(unviewed, center, p, nullptr);
  }
  surfaces.Refresh(viewed, center);
  surfaces.Refresh(unviewed, center);
  const SurfacePoints::Element* line = surfaces.Find(viewed);
  ASSERT_NE(line, nullptr);
  ASSERT_TRUE(line->planar);
  EXPECT_TRUE(line->oriented);
  EXPECT_NEAR(line->normal.x(), 0.0f, 1e-3f);
  EXPECT_TRUE(line->normal.isApprox(V3(0.0f, -0.6f, 0.8f), 1e-3f)) << line->normal.transpose();
  EXPECT_NEAR(surfaces.SignedDistance(*line, line->mean_m - 0.1f * line->normal), -0.1f, 1e-5f);

  ASSERT_NE(surfaces.Find(unviewed), nullptr);
  EXPECT_FALSE(surfaces.Find(unviewed)->planar);
  EXPECT_NEAR(surfaces.SignedDistance(*surfaces.Find(unviewed), V3(0.045f, 0.05f, -0.2f)), 0.23f, 1e-5f);
}

TEST(SurfacePoints, UnsignedSurfacesReadTheHeightBehindTheDiskAsAMagnitude) {
  SurfacePoints surfaces(kRes, /*signed_distances=*/false);
  const SurfacePoints::Element* element = SeenFromAbove(&surfaces);
  ASSERT_NE(element, nullptr);
  ASSERT_TRUE(element->oriented);  // the element is the same; only the distance's sign goes
  const V3 mean = element->mean_m;
  EXPECT_NEAR(surfaces.SignedDistance(*element, mean + V3(0.03f, 0.0f, 0.3f)), 0.3f, 1e-5f);
  EXPECT_NEAR(surfaces.SignedDistance(*element, mean + V3(0.0f, -0.04f, -0.07f)), 0.07f, 1e-5f);
  EXPECT_NEAR(surfaces.SignedDistance(*element, mean + V3(0.25f, 0.0f, 0.0f)), 0.1f, 1e-5f);
}

TEST(SurfacePoints, PlanesSeenFromNoSensorAreNotSigned) {
  SurfacePoints surfaces(kRes);
  const V3 center(0.05f, 0.05f, 0.05f);
  const std::uint64_t key = SurfacePoints::Pack(Eigen::Vector3i(0, 0, 0));
  for (const V3& p : SamplePlane(center, V3::UnitZ(), 0.05f, 30, 4)) surfaces.Add(key, center, p, nullptr);
  surfaces.Refresh(key, center);
  ASSERT_TRUE(surfaces.Find(key)->planar);
  EXPECT_FALSE(surfaces.Find(key)->oriented);
  EXPECT_NEAR(surfaces.SignedDistance(*surfaces.Find(key), center - V3(0, 0, 0.2f)), 0.2f, 1e-5f);
}

TEST(SurfacePoints, VoxelsTheRaysFreeForgetTheirSurface) {
  OccupancyTree tree(PlaneOptions(true));
  const V3 sensor(0.0f, 0.0f, 0.0f);
  const std::vector<V3> near_wall = SamplePlane(V3(1.05f, 0.0f, 0.0f), V3::UnitX(), 0.3f, 400, 6);
  tree.Insert(near_wall, sensor);
  const std::uint64_t key = SurfacePoints::Pack(tree.KeyOf(V3(1.05f, 0.01f, 0.01f)));
  ASSERT_NE(tree.surfaces()->Find(key), nullptr);
  EXPECT_NEAR(tree.surfaces()->Find(key)->mean_m.x(), 1.05f, 1e-5f);
  const std::vector<V3> far_wall = SamplePlane(V3(3.05f, 0.0f, 0.0f), V3::UnitX(), 0.6f, 4000, 7);
  for (int i = 0; i < 5; ++i) tree.Insert(far_wall, sensor);
  EXPECT_EQ(tree.surfaces()->Find(key), nullptr);
  EXPECT_EQ(OccupancyTree(PlaneOptions(false)).surfaces(), nullptr);
}

// Walls exactly on voxel boundaries: every return falls into the voxel on
// one side, so voxel centres put the surface half a voxel (5 cm) off.
TEST(SurfacePoints, PlaneOnAVoxelBoundaryReadsZeroOnThePlane) {
  const V3 center(0.0f, 0.0f, 0.0f);
  const V3 sensor(0.13f, -0.21f, 1.5f);
  const auto subvoxel = PlaneField(true, center, V3::UnitZ(), sensor);
  ASSERT_EQ(subvoxel->encoding(), DistanceField::Encoding::kSigned);
  EXPECT_LT(MaxOnPlane(*subvoxel, center, V3::UnitZ()), 0.02f);
  for (const V3& foot : {V3(0.0f, 0.0f, 0.0f), V3(0.33f, -0.71f, 0.0f), V3(-0.96f, 0.45f, 0.0f)}) {
    EXPECT_NEAR(ArgminAlongNormal(*subvoxel, foot, V3::UnitZ()), 0.0f, 0.01f) << foot.transpose();
  }
  // Voxel centres (the previous behaviour): 5 cm on the plane, minimum at
  // the centres of the occupied voxels, in free space.
  const auto centers = PlaneField(false, center, V3::UnitZ(), sensor);
  EXPECT_NEAR(MaxOnPlane(*centers, center, V3::UnitZ()), 0.05f, 0.002f);
  EXPECT_NEAR(ArgminAlongNormal(*centers, V3(0.33f, -0.71f, 0.0f), V3::UnitZ()), 0.05f, 0.001f);
}

TEST(SurfacePoints, PlaneAtAnArbitraryOffsetSeenFromBelowReadsZeroOnThePlane) {
  const V3 center(0.0f, 0.0f, 0.037f);
  const V3 sensor(-0.4f, 0.3f, -1.2f);
  const auto subvoxel = PlaneField(true, center, V3::UnitZ(), sensor);
  EXPECT_LT(MaxOnPlane(*subvoxel, center, V3::UnitZ()), 0.02f);
  for (const V3& foot : {V3(0.0f, 0.0f, 0.037f), V3(0.52f, 0.18f, 0.037f), V3(-0.3f, -1.1f, 0.037f)}) {
    EXPECT_NEAR(ArgminAlongNormal(*subvoxel, foot, V3::UnitZ()) + 0.037f, 0.037f, 0.01f);
  }
  // Voxel centres: the minimum sits at the occupied voxels' centres (z = 0.05).
  const auto centers = PlaneField(false, center, V3::UnitZ(), sensor);
  EXPECT_NEAR(ArgminAlongNormal(*centers, V3(0.52f, 0.18f, 0.037f), V3::UnitZ()), 0.013f, 0.001f);
}

TEST(SurfacePoints, TiltedPlaneReadsZeroOnThePlane) {
  const V3 normal = V3(0.3f, -0.2f, 0.9f).normalized();
  const V3 center(0.011f, 0.023f, 0.017f);
  const auto field = PlaneField(true, center, normal, center + 1.5f * normal + V3(0.2f, 0.1f, 0.0f));
  EXPECT_LT(MaxOnPlane(*field, center, normal), 0.02f);
  for (const V3& foot : SamplePlane(center, normal, 1.0f, 5, 8)) {
    EXPECT_NEAR(ArgminAlongNormal(*field, foot, normal), 0.0f, 0.01f) << foot.transpose();
  }
}

// Checks that every exported cell near the middle of the plane z = 0.062
// seen from above holds its exact distance to it (the voxels' means lie on
// the plane, their normals are exact): signed, or its magnitude.
void ExpectCellsHoldTheDistanceToThePlane(bool signed_surfaces) {
  const float plane_z = 0.062f;
  const auto field = PlaneField(true, V3(0.0f, 0.0f, plane_z), V3::UnitZ(), V3(0.1f, 0.2f, 1.0f), signed_surfaces);
  int checked = 0;
  for (int x = 0; x < field->dims().x(); ++x) {
    for (int y = 0; y < field->dims().y(); ++y) {
      for (int z = 0; z < field->dims().z(); ++z) {
        const Eigen::Vector3i cell(x, y, z);
        const V3 c = field->CellCenter(cell);
        if (c.head<2>().cwiseAbs().maxCoeff() > 1.2f) continue;  // 0.8 m from the plane's edges
        const float truth = std::clamp(c.z() - plane_z, -field->clamp(), field->clamp());
        ASSERT_NEAR(field->CellValue(cell), signed_surfaces ? truth : std::abs(truth), 1e-3f) << c.transpose();
        ASSERT_NEAR(field->CellDistance(cell), std::abs(truth), 1e-3f);
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 24 * 24 * 11);  // 0.1 m columns within 1.2 m, 11 layers
}

TEST(SurfacePoints, ExportedCellsHoldTheSignedDistanceToThePlane) { ExpectCellsHoldTheDistanceToThePlane(true); }

// Unsigned surfaces (odometry's default): the magnitude on both sides.
TEST(SurfacePoints, ExportedUnsignedCellsHoldTheDistanceToThePlane) { ExpectCellsHoldTheDistanceToThePlane(false); }

// The standard OctoMap insertion frees voxels inside the tree; their
// surfaces go with the change detection a distance transform enables.
TEST(SurfacePoints, VoxelsFreedByOctomapInsertionForgetTheirSurface) {
  DistanceMapOptions options = PlaneOptions(true);
  options.clear_occupied_only = false;
  OccupancyTree tree(options);
  tree.tree().enableChangeDetection(true);
  const V3 sensor(0.0f, 0.0f, 0.0f);
  tree.Insert(SamplePlane(V3(1.05f, 0.0f, 0.0f), V3::UnitX(), 0.3f, 400, 6), sensor);
  const std::uint64_t key = SurfacePoints::Pack(tree.KeyOf(V3(1.05f, 0.01f, 0.01f)));
  ASSERT_NE(tree.surfaces()->Find(key), nullptr);
  const std::vector<V3> far_wall = SamplePlane(V3(3.05f, 0.0f, 0.0f), V3::UnitX(), 0.6f, 4000, 7);
  for (int i = 0; i < 5; ++i) tree.Insert(far_wall, sensor);
  EXPECT_EQ(tree.surfaces()->Find(key), nullptr);
  EXPECT_NE(tree.surfaces()->Find(SurfacePoints::Pack(tree.KeyOf(V3(3.05f, 0.01f, 0.01f)))), nullptr);
}

// Voxels without returns (an octree prior) keep the distance to their centre.
TEST(SurfacePoints, OctreePriorsKeepVoxelCenterDistances) {
  auto tree = std::make_unique<octomap::OcTree>(kRes);
  for (const V3& p : SamplePlane(V3::Zero(), V3::UnitZ(), 2.0f, 20000, 10)) {
    tree->updateNode(octomap::point3d(p.x(), p.y(), p.z()), true);
  }
  const auto map = DistanceMap::FromOctree(std::move(tree), PlaneOptions(true), V3::Zero());
  map->WaitForUpdates();
  // Floor voxels [0, 0.1] (centre 0.05); query voxel centre 0.45.
  EXPECT_NEAR(map->Snapshot()->Distance(V3(0.31f, 0.22f, 0.42f)), 0.4f, 1e-3f);
  EXPECT_EQ(map->Stats().surface_voxels, 0u);
}

// Prior point clouds have no view direction: the surfaces are unsigned, so a
// plane on a voxel boundary reads the mean-point distance of the cells on
// either side (5 cm), but centred on the plane.
TEST(SurfacePoints, PriorPointCloudsHaveUnsignedSurfaces) {
  const std::vector<V3> plane = SamplePlane(V3::Zero(), V3::UnitZ(), 2.0f, 40000, 9);
  const auto map = DistanceMap::FromPoints(plane, PlaneOptions(true), V3::Zero());
  map->WaitForUpdates();
  EXPECT_EQ(map->Stats().surface_voxels, 40u * 40u);  // every voxel of the 4 m square
  EXPECT_GT(map->Stats().surface_bytes, 40u * 40u * 64u);
  const auto field = map->Snapshot();
  EXPECT_NEAR(MaxOnPlane(*field, V3::Zero(), V3::UnitZ()), 0.05f, 0.002f);
  EXPECT_NEAR(field->DistanceTrilinear(V3(0.31f, 0.2f, 0.05f), nullptr), 0.05f, 0.002f);
  EXPECT_NEAR(field->DistanceTrilinear(V3(0.31f, 0.2f, -0.05f), nullptr), 0.05f, 0.002f);
  EXPECT_NEAR(field->DistanceTrilinear(V3(0.31f, 0.2f, 0.25f), nullptr), 0.25f, 0.002f);
}

}  // namespace
}  // namespace unimap::map
