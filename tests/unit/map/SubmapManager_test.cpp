#include "map/SubmapManager.hpp"

#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "MapTestSupport.hpp"
#include "map/DistanceMap.hpp"
#include "unimap/Errors.hpp"

namespace unimap::map {
namespace {

using V3 = Eigen::Vector3f;

SubmapOptions TestOptions(int m) {
  SubmapOptions options;
  options.scans_3d_per_submap = m;
  options.map.resolution_m = 0.2;
  options.map.max_range_m = 4.0;
  options.map.clamp_distance_m = 1.0;
  options.map.subvoxel_surfaces = false;
  return options;
}

// A wall at x = 2.1 m (a voxel-centre plane at 0.2 m resolution) seen from sensor.
std::vector<V3> Wall() { return test::SampleRectangle(V3(2.1f, -1.1f, -1.1f), V3(0, 2.2f, 0), V3(0, 0, 2.2f), 0.1f); }

TEST(SubmapManagerTest, ScansGoIntoMatchingAndGrowingSubmapsAsThePaperDescribes) {
  SubmapManager manager(TestOptions(4));  // M = 4: a growing submap starts every M / 2 = 2 scans
  EXPECT_EQ(manager.live_count(), 0u);
  // Expected receivers, submaps created and retired after each of 7 scans.
  const std::vector<std::vector<int>> receivers = {{0}, {0}, {0, 1}, {0, 1}, {1, 2}, {1, 2}, {2, 3}};
  const std::vector<std::vector<int>> created = {{0}, {1}, {}, {2}, {}, {3}, {}};
  const std::vector<std::vector<int>> retired = {{}, {}, {}, {0}, {}, {1}, {}};
  for (std::size_t i = 0; i < receivers.size(); ++i) {
    const V3 origin(0.1f * static_cast<float>(i), 0.0f, 0.0f);
    manager.InsertScan(Wall(), origin);
    const SubmapInsertion insertion = manager.last_insertion();
    EXPECT_EQ(insertion.submap_ids, receivers[i]) << "scan " << i;
    EXPECT_EQ(insertion.created_ids, created[i]) << "scan " << i;
    ASSERT_EQ(insertion.T_local_submaps.size(), insertion.submap_ids.size());
    ASSERT_EQ(insertion.created_T_local_submaps.size(), insertion.created_ids.size());
    for (std::size_t c = 0; c < insertion.created_ids.size(); ++c) {
      // A submap's frame is at the sensor position of the scan that started it.
      EXPECT_TRUE(insertion.created_T_local_submaps[c].translation().isApprox(origin.cast<double>()));
    }
    std::vector<int> retired_ids;
    for (const RetiredSubmap& r : manager.TakeRetired()) {
      retired_ids.push_back(r.id);
      EXPECT_EQ(r.scans_3d, 4);
      EXPECT_FALSE(r.points_submap.empty());
    }
    EXPECT_EQ(retired_ids, retired[i]) << "scan " << i;
    EXPECT_EQ(manager.live_count(), i == 0 ? 1u : 2u);  // the growing one starts after M / 2
  }
  EXPECT_EQ(manager.started_count(), 4);
}

TEST(SubmapManagerTest, SnapshotIsTheMatchingSubmapsField) {
  SubmapManager manager(TestOptions(4));
  EXPECT_EQ(manager.Snapshot()->CellCount(), 0u);  // nothing inserted yet
  manager.InsertScan(Wall(), V3::Zero());
  manager.WaitForUpdates();
  const std::shared_ptr<const DistanceField> field = manager.Snapshot();
  ASSERT_GT(field->CellCount(), 0u);
  EXPECT_NEAR(field->Distance(V3(2.1f, 0.1f, 0.1f)), 0.0f, 1e-3f);  // on the wall
  EXPECT_NEAR(field->Distance(V3(1.5f, 0.1f, 0.1f)), 0.6f, 0.01f);  // 0.6 m in front of it
}

TEST(SubmapManagerTest, RetiredSubmapKeepsItsSurfaceInItsOwnFrame) {
  SubmapManager manager(TestOptions(2));  // every scan starts a growing submap; retire after 2
  const V3 origin(0.5f, -0.3f, 0.1f);
  manager.InsertScan(Wall(), origin);
  manager.InsertScan(Wall(), origin);
  const std::vector<RetiredSubmap> retired = manager.TakeRetired();
  ASSERT_EQ(retired.size(), 1u);
  EXPECT_TRUE(retired[0].T_local_submap.translation().isApprox(origin.cast<double>()));
  // Wall voxels at x = 2.1 m in the local frame: 1.6 m in the submap's frame.
  // Kept at half the size: within half a step of where it was.
  const float tolerance = 1e-4f + 0.5f * retired[0].points_submap.step();
  for (const V3& p : retired[0].points_submap.Expand())
    EXPECT_NEAR(p.x(), 2.1f - origin.x(), tolerance) << p.transpose();
  EXPECT_GT(retired[0].points_submap.size(), 100u);
  EXPECT_TRUE(manager.TakeRetired().empty());  // taken once
}

TEST(SubmapManagerTest, BadInputIsRejected) {
  EXPECT_THROW(SubmapManager(TestOptions(1)), ConfigError);
  SubmapManager manager(TestOptions(4));
  EXPECT_THROW(manager.InsertScan(Wall(), V3(std::nanf(""), 0, 0)), InputError);
  EXPECT_EQ(manager.live_count(), 0u);
}

}  // namespace
}  // namespace unimap::map

namespace unimap::map {
namespace {

TEST(SubmapManagerTest, GrowingSubmapBuildsItsDistancesWhenItBecomesTheMatchingOne) {
  SubmapManager manager(TestOptions(2));   // M = 2: a new growing submap after every scan
  manager.InsertScan(Wall(), V3::Zero());  // submap 0 (matching), then submap 1 starts growing
  manager.InsertScan(Wall(), V3::Zero());  // into 0 and 1; 0 retires, 1 becomes the matching one
  manager.WaitForUpdates();
  ASSERT_EQ(manager.TakeRetired().size(), 1u);
  const std::shared_ptr<const DistanceField> field = manager.Snapshot();
  ASSERT_GT(field->CellCount(), 0u);  // built at the switch from submap 1's octree
  EXPECT_NEAR(field->Distance(V3(2.1f, 0.1f, 0.1f)), 0.0f, 1e-3f);
  EXPECT_NEAR(field->Distance(V3(1.5f, 0.1f, 0.1f)), 0.6f, 0.01f);
}

TEST(DistanceMapDeferredTest, DistancesStartOnlyWhenEnabled) {
  DistanceMapOptions options = TestOptions(2).map;
  options.compute_distances = false;
  DistanceMap map(options);
  map.InsertScan(Wall(), V3::Zero());
  map.WaitForUpdates();
  EXPECT_EQ(map.Snapshot()->CellCount(), 0u);  // the octree only
  EXPECT_FALSE(map.OccupiedVoxelCenters().empty());
  map.EnableDistances();
  map.WaitForUpdates();
  const std::shared_ptr<const DistanceField> field = map.Snapshot();
  ASSERT_GT(field->CellCount(), 0u);
  EXPECT_NEAR(field->Distance(V3(1.5f, 0.1f, 0.1f)), 0.6f, 0.01f);
  // Later scans update the distances incrementally as usual.
  map.InsertScan(test::SampleRectangle(V3(-1.3f, -1.1f, -1.1f), V3(0, 2.2f, 0), V3(0, 0, 2.2f), 0.1f), V3::Zero());
  map.WaitForUpdates();
  EXPECT_NEAR(map.Snapshot()->Distance(V3(-0.7f, 0.1f, 0.1f)), 0.6f, 0.01f);
}

}  // namespace
}  // namespace unimap::map
