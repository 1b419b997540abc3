#include "matching/VoxelBlockSet.hpp"

#include <random>
#include <set>
#include <tuple>

#include <gtest/gtest.h>

namespace unimap::matching {
namespace {

TEST(VoxelBlockSet, InsertReportsNewCellsOnce) {
  VoxelBlockSet set;
  EXPECT_TRUE(set.Insert({1, 2, 3}));
  EXPECT_FALSE(set.Insert({1, 2, 3}));
  EXPECT_TRUE(set.Insert({1, 2, 4}));
  EXPECT_EQ(set.size(), 2u);
  EXPECT_EQ(set.block_count(), 1u);
  EXPECT_TRUE(set.Contains({1, 2, 3}));
  EXPECT_FALSE(set.Contains({1, 3, 3}));
  EXPECT_FALSE(set.Contains({100, 2, 3}));  // no block there
}

TEST(VoxelBlockSet, NegativeCellsFallInTheirOwnBlocks) {
  VoxelBlockSet set;
  // -1 and 7 share the low three bits; -1 and 0 are neighbours across a block edge.
  EXPECT_TRUE(set.Insert({-1, 0, 0}));
  EXPECT_TRUE(set.Insert({7, 0, 0}));
  EXPECT_TRUE(set.Insert({0, 0, 0}));
  EXPECT_TRUE(set.Insert({0, -8, 0}));
  EXPECT_TRUE(set.Insert({0, 0, -9}));
  EXPECT_EQ(set.size(), 5u);
  EXPECT_EQ(set.block_count(), 4u);  // {-1}, {0, 7}, y -8, z -9
  EXPECT_FALSE(set.Contains({-8, 0, 0}));
  EXPECT_FALSE(set.Contains({15, 0, 0}));
}

TEST(VoxelBlockSet, AgreesWithAnOrderedSetOnRandomCells) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coordinate(-40, 40);
  VoxelBlockSet set;
  std::set<std::tuple<int, int, int>> reference;
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector3i cell(coordinate(rng), coordinate(rng), coordinate(rng));
    ASSERT_EQ(set.Insert(cell), reference.emplace(cell.x(), cell.y(), cell.z()).second) << cell.transpose();
  }
  EXPECT_EQ(set.size(), reference.size());
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector3i cell(coordinate(rng), coordinate(rng), coordinate(rng));
    EXPECT_EQ(set.Contains(cell), reference.count({cell.x(), cell.y(), cell.z()}) == 1) << cell.transpose();
  }
}

TEST(VoxelBlockSet, APlaneCostsBlocksNotCells) {
  // A 100 x 100 wall of cells in the plane z = 3 crosses 13 x 13 blocks
  // (cells 0..99 span blocks 0..12 per axis).
  VoxelBlockSet set;
  for (int x = 0; x < 100; ++x) {
    for (int y = 0; y < 100; ++y) set.Insert({x, y, 3});
  }
  EXPECT_EQ(set.size(), 10000u);
  EXPECT_EQ(set.block_count(), 169u);
  // A hash set of the 10,000 keys holds at least 16 bytes a cell (key and
  // probe distance); the blocks hold under 8.
  EXPECT_LT(set.MemoryBytes(), 8u * 10000u);
}

}  // namespace
}  // namespace unimap::matching
