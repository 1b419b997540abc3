#include "map/EdtRegion.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <octomap/OcTree.h>

#include "MapTestSupport.hpp"
#include "map/OccupancyTree.hpp"

namespace unimap::map {
namespace {

using V3 = Eigen::Vector3f;
using V3i = Eigen::Vector3i;

constexpr float kClamp = 0.8f;

// Largest |field - brute force| over every cell of the field.
float MaxCellError(const DistanceField& field, const std::vector<V3>& occupied) {
  float worst = 0.0f;
  for (int x = 0; x < field.dims().x(); ++x) {
    for (int y = 0; y < field.dims().y(); ++y) {
      for (int z = 0; z < field.dims().z(); ++z) {
        const V3i cell(x, y, z);
        const float truth = test::BruteForceDistance(occupied, field.CellCenter(cell), kClamp);
        worst = std::max(worst, std::abs(field.CellDistance(cell) - truth));
      }
    }
  }
  return worst;
}

void SetOccupancy(octomap::OcTree& tree, const V3& p, bool occupied) {
  // Enough updates to cross the clamping thresholds from any state.
  for (int i = 0; i < 12; ++i) tree.updateNode(octomap::point3d(p.x(), p.y(), p.z()), occupied);
}

class EdtRegionTest : public ::testing::Test {
 protected:
  EdtRegionTest() : tree_(Options()) {
    std::mt19937 rng(42);
    std::uniform_real_distribution<float> coord(-1.4f, 1.4f);
    for (int i = 0; i < 25; ++i) obstacles_.push_back(V3(coord(rng), coord(rng), coord(rng)));
    // An aligned 2 x 2 x 2 block: the octree prunes it into one node.
    for (const float x : {0.05f, 0.15f}) {
      for (const float y : {0.05f, 0.15f}) {
        for (const float z : {0.05f, 0.15f}) obstacles_.push_back(V3(x, y, z));
      }
    }
    tree_.MarkOccupied(obstacles_);
    box_ = KeyBox(tree_.KeyOf(V3(-1.5f, -1.5f, -1.5f)), tree_.KeyOf(V3(1.5f, 1.5f, 1.5f)));
  }
  static DistanceMapOptions Options() {
    DistanceMapOptions options;
    options.resolution_m = 0.1;
    options.clamp_distance_m = kClamp;
    return options;
  }
  std::vector<V3> OccupiedCenters() const { return tree_.OccupiedVoxelCenters(); }

  OccupancyTree tree_;
  std::vector<V3> obstacles_;
  KeyBox box_;
};

TEST_F(EdtRegionTest, InitialTransformMatchesBruteForceInEveryCell) {
  const EdtRegion region(&tree_.tree(), box_, kClamp);
  const std::shared_ptr<const DistanceField> field = region.Export(3);
  EXPECT_EQ(field->dims(), V3i(31, 31, 31));
  EXPECT_EQ(field->sequence(), 3u);
  EXPECT_EQ(OccupiedCenters().size(), 33u);  // 25 voxels + the pruned block of 8
  EXPECT_LE(MaxCellError(*field, OccupiedCenters()), 0.05f);
  // Field cells line up with octree voxels: each obstacle's voxel reads zero.
  for (const V3& p : obstacles_) EXPECT_FLOAT_EQ(field->Distance(p), 0.0f) << p.transpose();
}

TEST_F(EdtRegionTest, IncrementalUpdateFollowsAddedAndFreedVoxels) {
  EdtRegion region(&tree_.tree(), box_, kClamp);
  const V3 freed = obstacles_.front();
  SetOccupancy(tree_.tree(), freed, false);
  SetOccupancy(tree_.tree(), V3(0.15f, 0.15f, 0.15f), false);  // splits the pruned block
  SetOccupancy(tree_.tree(), V3(-0.75f, 0.95f, 1.05f), true);
  SetOccupancy(tree_.tree(), V3(9.0f, 9.0f, 9.0f), true);  // outside the box: ignored
  region.Update();
  const std::shared_ptr<const DistanceField> field = region.Export(4);
  std::vector<V3> occupied = OccupiedCenters();
  EXPECT_EQ(occupied.size(), 33u - 2u + 2u);
  occupied.erase(std::remove_if(occupied.begin(), occupied.end(), [](const V3& c) { return c.x() > 5.0f; }),
                 occupied.end());
  EXPECT_LE(MaxCellError(*field, occupied), 0.05f);
  EXPECT_GT(field->Distance(freed), 0.0f);
  EXPECT_FLOAT_EQ(field->Distance(V3(-0.75f, 0.95f, 1.05f)), 0.0f);
}

TEST(EdtRegion, PlanesReachPastTheEdgeOfASurfaceSeenOnlyInPart) {
  // A floor at z = 0.02 seen from above for x < 0 only (its right half unseen).
  DistanceMapOptions options;
  options.resolution_m = 0.1;
  options.clamp_distance_m = kClamp;
  options.subvoxel_surfaces = true;
  OccupancyTree tree(options);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> x(-1.0f, 0.0f);
  std::uniform_real_distribution<float> y(-1.0f, 1.0f);
  std::vector<V3> floor(8000);
  for (V3& p : floor) p = V3(x(rng), y(rng), 0.02f);
  tree.Insert(floor, V3(-0.5f, 0.0f, 1.0f));
  const KeyBox box(tree.KeyOf(V3(-1.5f, -1.5f, -0.8f)), tree.KeyOf(V3(1.5f, 1.5f, 0.8f)));
  const EdtRegion region(&tree.tree(), box, kClamp);
  EXPECT_FALSE(region.Export(1)->HasPlanes());                   // no surfaces, no planes
  EXPECT_FALSE(region.Export(1, tree.surfaces())->HasPlanes());  // not asked for
  const std::shared_ptr<const DistanceField> field = region.Export(1, tree.surfaces(), /*with_planes=*/true);
  ASSERT_TRUE(field->HasPlanes());
  for (const V3& p : {V3(-0.5f, 0.3f, 0.12f), V3(0.3f, 0.0f, 0.02f), V3(0.4f, -0.2f, -0.1f)}) {
    V3 normal;
    float offset = 0.0f;
    ASSERT_TRUE(field->PlaneAt(p, &normal, &offset)) << p.transpose();
    EXPECT_GT(std::abs(normal.z()), 0.999f) << p.transpose();
    EXPECT_NEAR(std::abs(normal.dot(p) + offset), std::abs(p.z() - 0.02f), 0.005f) << p.transpose();
  }
  // Beside the seen part the field measures to its edge, the plane does not.
  EXPECT_GT(field->DistanceTrilinear(V3(0.3f, 0.0f, 0.02f), nullptr), 0.15f);
  V3 normal;
  float offset = 0.0f;
  EXPECT_FALSE(field->PlaneAt(V3(1.4f, 0.0f, 0.5f), &normal, &offset));  // no surface in reach
}

}  // namespace
}  // namespace unimap::map
