#include "pipeline/LoopClosureFinder.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace unimap::pipeline {
namespace {

constexpr double kVoxelM = 0.1;

// A wall x = 2 of 4 m x 2 m sampled at voxel centres from y = y0_m on, as
// the retired surface of submap `id` created at origin_local.
map::RetiredSubmap Wall(int id, const Eigen::Vector3d& origin_local, double y0_m) {
  std::vector<Eigen::Vector3f> points_submap;
  const Eigen::Vector3f origin = origin_local.cast<float>();
  for (double y = y0_m + 0.05; y < y0_m + 4.0; y += kVoxelM) {
    for (double z = 0.05; z < 2.0; z += kVoxelM) {
      points_submap.push_back(Eigen::Vector3f(2.05f, static_cast<float>(y), static_cast<float>(z)) - origin);
    }
  }
  map::RetiredSubmap submap;
  submap.id = id;
  submap.T_local_submap = Eigen::Translation3d(origin_local) * Eigen::Isometry3d::Identity();
  submap.points_submap = map::CompactPoints(points_submap);
  return submap;
}

LoopClosureFinder Finder(double redundant_overlap = 0.9) {
  LoopSearchOptions search;
  search.redundant_overlap = redundant_overlap;
  return LoopClosureFinder(search, graph::LoopClosureOptions::ForVoxel(kVoxelM), kVoxelM);
}

TEST(LoopClosureFinderTest, TheSamePlaceRetiredAgainIsNotKept) {
  LoopClosureFinder finder = Finder();
  finder.AddRetired(Wall(0, Eigen::Vector3d(0, 0, 0), 0.0), 0.0);
  // Same surface, seen from another origin: identical voxels in the local frame.
  finder.AddRetired(Wall(1, Eigen::Vector3d(0.3, 0.2, 0), 0.0), 0.3);
  EXPECT_EQ(finder.retired_count(), 1u);
  EXPECT_EQ(finder.stats().redundant, 1u);
  EXPECT_EQ(finder.retired_points(), 40u * 20u);
}

TEST(LoopClosureFinderTest, ASubmapAddingMoreThanTheShareLeftIsKept) {
  LoopClosureFinder finder = Finder();
  finder.AddRetired(Wall(0, Eigen::Vector3d(0, 0, 0), 0.0), 0.0);
  // 0.5 m further along: 35 of its 40 columns were in the first (87.5 % < 90 %).
  finder.AddRetired(Wall(1, Eigen::Vector3d(0, 0.5, 0), 0.5), 0.5);
  EXPECT_EQ(finder.retired_count(), 2u);
  EXPECT_EQ(finder.stats().redundant, 0u);
  // 0.3 m further along: 37 of 40 columns (92.5 %) in the last kept.
  finder.AddRetired(Wall(2, Eigen::Vector3d(0, 0.8, 0), 0.8), 0.8);
  EXPECT_EQ(finder.retired_count(), 2u);
  EXPECT_EQ(finder.stats().redundant, 1u);
}

TEST(LoopClosureFinderTest, RedundancyIsJudgedAgainstTheLastKeptSubmap) {
  // A sensor creeping along: each submap 0.3 m past the previous one. Against
  // its predecessor each would be redundant (92.5 %), but the place moves on,
  // so one is kept every time the last kept one holds less than 90 %.
  LoopClosureFinder finder = Finder();
  for (int i = 0; i < 10; ++i) {
    finder.AddRetired(Wall(i, Eigen::Vector3d(0, 0.3 * i, 0), 0.3 * i), 0.3 * i);
  }
  // Kept: 0 (0.0 m), 2 (0.6 m: 34 of 40 columns in submap 0's), 4, 6, 8.
  EXPECT_EQ(finder.retired_count(), 5u);
  EXPECT_EQ(finder.stats().redundant, 5u);
}

TEST(LoopClosureFinderTest, AnOverlapOfOneKeepsAllButIdenticalSurfaces) {
  LoopClosureFinder finder = Finder(1.0);
  finder.AddRetired(Wall(0, Eigen::Vector3d(0, 0, 0), 0.0), 0.0);
  finder.AddRetired(Wall(1, Eigen::Vector3d(0, 0.1, 0), 0.1), 0.1);  // one new column
  finder.AddRetired(Wall(2, Eigen::Vector3d(0, 0.1, 0), 0.1), 0.1);  // none
  EXPECT_EQ(finder.retired_count(), 2u);
  EXPECT_EQ(finder.stats().redundant, 1u);
}

TEST(LoopClosureFinderTest, AnOverlapOutsideZeroToOneIsInvalid) {
  LoopSearchOptions search;
  std::string why;
  search.redundant_overlap = 0.0;
  EXPECT_FALSE(search.IsValid(&why));
  EXPECT_NE(why.find("redundant_overlap"), std::string::npos);
  search.redundant_overlap = 1.5;
  EXPECT_FALSE(search.IsValid(&why));
  search.redundant_overlap = 0.5;
  EXPECT_TRUE(search.IsValid(&why));
}

}  // namespace
}  // namespace unimap::pipeline
