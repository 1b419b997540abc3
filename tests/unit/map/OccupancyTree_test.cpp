#include "map/OccupancyTree.hpp"

#include <algorithm>

#include <gtest/gtest.h>
#include <octomap/OcTree.h>

#include "unimap/Errors.hpp"

namespace unimap::map {
namespace {

using V3 = Eigen::Vector3f;

DistanceMapOptions Options() {
  DistanceMapOptions options;
  options.resolution_m = 0.1;
  options.max_insert_range_m = 10.0;
  return options;
}

bool IsOccupied(const OccupancyTree& tree, const V3& p) {
  const std::vector<V3> centers = tree.OccupiedVoxelCenters();
  return std::any_of(centers.begin(), centers.end(),
                     [&](const V3& c) { return (c - p).cwiseAbs().maxCoeff() < 0.01f; });
}

TEST(OccupancyTree, HitsWithinRangeAreOccupiedAndBoxed) {
  OccupancyTree tree(Options());
  const V3 origin(0.05f, 0.05f, 0.05f);
  const KeyBox hits = tree.Insert(
      {V3(3.05f, 0.05f, 0.05f), V3(0.05f, -2.05f, 1.05f), V3(20.05f, 0.05f, 0.05f)},  // beyond 10 m: a miss ray only
      origin);
  EXPECT_EQ(hits, KeyBox(tree.KeyOf(V3(0.05f, -2.05f, 0.05f)), tree.KeyOf(V3(3.05f, 0.05f, 1.05f))));
  EXPECT_TRUE(IsOccupied(tree, V3(3.05f, 0.05f, 0.05f)));
  EXPECT_TRUE(IsOccupied(tree, V3(0.05f, -2.05f, 1.05f)));
  EXPECT_EQ(tree.OccupiedVoxelCenters().size(), 2u);
  EXPECT_TRUE(tree.KeyCenter(tree.KeyOf(V3(3.01f, 0.09f, 0.0f))).isApprox(V3(3.05f, 0.05f, 0.05f)));
}

TEST(OccupancyTree, RaysLowerOccupiedVoxelsButNotThoseHitInTheSameScan) {
  OccupancyTree tree(Options());
  const V3 origin(0.05f, 0.05f, 0.05f);
  const V3 near(2.05f, 0.05f, 0.05f);
  const V3 far(4.05f, 0.05f, 0.05f);
  tree.Insert({near}, origin);
  for (int i = 0; i < 5; ++i) tree.Insert({near, far}, origin);  // near is hit every time
  EXPECT_TRUE(IsOccupied(tree, near));
  // Now only crossed: from the upper clamp logit(0.97) = 3.48 it takes
  // ceil(3.48 / -logit(0.4) = 0.405) = 9 misses to drop to free.
  for (int i = 0; i < 8; ++i) tree.Insert({far}, origin);
  EXPECT_TRUE(IsOccupied(tree, near));
  tree.Insert({far}, origin);
  EXPECT_FALSE(IsOccupied(tree, near));
  EXPECT_TRUE(IsOccupied(tree, far));
}

TEST(OccupancyTree, AdoptedTreesAreClearedByRaysToo) {
  for (const bool occupied_only : {true, false}) {
    auto octree = std::make_unique<octomap::OcTree>(0.1);
    octree->updateNode(octomap::point3d(2.05f, 0.05f, 0.05f), true);
    DistanceMapOptions options = Options();
    options.clear_occupied_only = occupied_only;
    OccupancyTree tree(std::move(octree), options);
    EXPECT_TRUE(IsOccupied(tree, V3(2.05f, 0.05f, 0.05f)));
    for (int i = 0; i < 8; ++i) tree.Insert({V3(4.05f, 0.05f, 0.05f)}, V3(0.05f, 0.05f, 0.05f));
    EXPECT_FALSE(IsOccupied(tree, V3(2.05f, 0.05f, 0.05f))) << occupied_only;
  }
}

// A coarse occupied leaf stands for every voxel below it: a pruned 2x2x2
// cube is one leaf of 8 voxels, and max_occupied_voxels counts them all
// before any is tracked.
TEST(OccupancyTree, AdoptedTreesCoveringMoreThanMaxOccupiedVoxelsAreRefused) {
  for (const std::size_t max_voxels : {std::size_t{7}, std::size_t{8}}) {
    auto octree = std::make_unique<octomap::OcTree>(0.1);
    for (int i = 0; i < 8; ++i) {
      const octomap::OcTreeKey key(32768 + (i & 1), 32768 + ((i >> 1) & 1), 32768 + ((i >> 2) & 1));
      for (int hit = 0; hit < 3; ++hit) octree->updateNode(key, true);
    }
    octree->prune();
    ASSERT_EQ(octree->getNumLeafNodes(), 1u);
    DistanceMapOptions options = Options();
    options.max_occupied_voxels = max_voxels;
    if (max_voxels < 8) {
      try {
        OccupancyTree tree(std::move(octree), options);
        ADD_FAILURE() << "no error";
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("octree: its occupied leaves cover more than 7 voxels of 0.1"),
                  std::string::npos)
            << e.what();
      }
    } else {
      OccupancyTree tree(std::move(octree), options);
      EXPECT_EQ(tree.OccupiedVoxelCenters().size(), 8u);
    }
  }
}

TEST(OccupancyTree, WithoutRayCastingReturnsOnlyAdd) {
  DistanceMapOptions options = Options();
  options.raycast_free_space = false;
  OccupancyTree tree(options);
  const V3 origin(0.05f, 0.05f, 0.05f);
  tree.Insert({V3(2.05f, 0.05f, 0.05f)}, origin);
  for (int i = 0; i < 8; ++i) tree.Insert({V3(4.05f, 0.05f, 0.05f)}, origin);
  EXPECT_TRUE(IsOccupied(tree, V3(2.05f, 0.05f, 0.05f)));
  tree.MarkOccupied({V3(-1.05f, 0.05f, 0.05f)});
  EXPECT_EQ(tree.OccupiedVoxelCenters().size(), 3u);
}

}  // namespace
}  // namespace unimap::map
