#include "map/DistanceMap.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <future>
#include <limits>
#include <sstream>

#include <gtest/gtest.h>
#include <octomap/OcTree.h>

#include "MapTestSupport.hpp"
#include "unimap/Errors.hpp"

namespace unimap::map {
namespace {

using test::Append;
using test::BruteForceDistance;
using test::MaxVoxelCenterError;
using test::RandomPoints;
using test::SampleBoxSurface;
using test::SampleRectangle;
using test::VoxelCenterOf;
using V3 = Eigen::Vector3f;

constexpr float kRes = 0.2f;  // all test surfaces lie on voxel centres (odd multiples of 0.1 m)

// Distances to voxel centres (the brute-force reference below); the
// sub-voxel surfaces are tested in SurfacePoints_test.cpp.
DistanceMapOptions TestOptions() {
  DistanceMapOptions options;
  options.resolution_m = kRes;
  options.max_range_m = 6.0;
  options.clamp_distance_m = 1.0;
  options.growth_margin_m = 0.6;
  options.subvoxel_surfaces = false;
  return options;
}

// Checks the published field against the brute force over the octree's
// occupied voxels: exact at voxel centres (within half a voxel) and, at the
// query point itself, off by no more than that plus the distance to the
// voxel centre (the distance is 1-Lipschitz).
void ExpectMatchesBruteForce(const DistanceMap& map, std::uint32_t seed, const V3& low, const V3& high) {
  const std::shared_ptr<const DistanceField> field = map.Snapshot();
  const std::vector<V3> occupied = test::CentersNear(map.OccupiedVoxelCenters(), low, high, field->clamp());
  ASSERT_FALSE(occupied.empty());
  const std::vector<V3> queries = RandomPoints(low, high, 2000, seed);
  EXPECT_LE(MaxVoxelCenterError(*field, occupied, queries), 0.5f * kRes);
  for (const V3& p : queries) {
    const float truth = BruteForceDistance(occupied, p, field->clamp());
    const float slack = 0.5f * kRes + (p - VoxelCenterOf(*field, p)).norm() + 1e-4f;
    ASSERT_LE(std::abs(field->Distance(p) - truth), slack) << p.transpose();
  }
}

TEST(DistanceMap, IncrementalScansMatchBruteForce) {
  DistanceMap map(TestOptions());
  const V3 sensor(0.1f, 0.1f, 0.1f);
  // Scan 1: the floor plus two ceiling corners (so the box already spans the room).
  std::vector<V3> scan = SampleRectangle(V3(-2.9f, -1.9f, -0.9f), V3(5.8f, 0, 0), V3(0, 3.8f, 0), 0.1f);
  scan.push_back(V3(-2.9f, -1.9f, 1.9f));
  scan.push_back(V3(2.9f, 1.9f, 1.9f));
  map.InsertScan(scan, sensor);
  map.WaitForUpdates();
  const V3 low = map.Snapshot()->origin();
  const V3 high = map.Snapshot()->box_max();
  EXPECT_NEAR(map.Snapshot()->Distance(V3(0.1f, 0.1f, -0.5f)), 0.4f, 1e-3f);
  ExpectMatchesBruteForce(map, 1, low, high);

  std::vector<V3> walls = SampleRectangle(V3(-2.9f, -1.9f, -0.9f), V3(0, 3.8f, 0), V3(0, 0, 2.8f), 0.1f);
  Append(&walls, SampleRectangle(V3(2.9f, -1.9f, -0.9f), V3(0, 3.8f, 0), V3(0, 0, 2.8f), 0.1f));
  map.InsertScan(walls, sensor);
  map.WaitForUpdates();
  ExpectMatchesBruteForce(map, 2, low, high);

  std::vector<V3> rest = SampleRectangle(V3(-2.9f, -1.9f, -0.9f), V3(5.8f, 0, 0), V3(0, 0, 2.8f), 0.1f);
  Append(&rest, SampleRectangle(V3(-2.9f, 1.9f, -0.9f), V3(5.8f, 0, 0), V3(0, 0, 2.8f), 0.1f));
  Append(&rest, SampleRectangle(V3(-2.9f, -1.9f, 1.9f), V3(5.8f, 0, 0), V3(0, 3.8f, 0), 0.1f));
  map.InsertScan(rest, sensor);
  map.InsertScan(SampleBoxSurface(V3(0.5f, -1.1f, -0.9f), V3(1.3f, -0.3f, -0.1f), 0.1f), sensor);
  map.WaitForUpdates();
  ExpectMatchesBruteForce(map, 3, low, high);
  // The obstacle's top face is 0.4 m below this voxel centre.
  EXPECT_NEAR(map.Snapshot()->Distance(V3(0.9f, -0.7f, 0.3f)), 0.4f, 1e-3f);

  const DistanceMapStats stats = map.Stats();
  EXPECT_EQ(stats.rebuilds, 1u);  // the first box already covered every later scan
  EXPECT_GE(stats.incremental_updates, 2u);
  EXPECT_EQ(stats.scans_inserted, 4u);
  EXPECT_EQ(map.Snapshot()->sequence(), 4u);
}

TEST(DistanceMap, SnapshotDoesNotWaitForAnUpdateInProgress) {
  DistanceMap map(TestOptions());
  const V3 sensor(0.1f, 0.1f, 0.1f);
  map.InsertScan(SampleRectangle(V3(-2.9f, -2.9f, -0.9f), V3(5.8f, 0, 0), V3(0, 5.8f, 0), 0.1f), sensor);
  map.WaitForUpdates();
  const std::shared_ptr<const DistanceField> before = map.Snapshot();
  const V3 near_new_wall(2.5f, 0.1f, 0.1f);  // 0.4 m from the wall added below
  ASSERT_FLOAT_EQ(before->Distance(near_new_wall), before->clamp());

  std::promise<void> entered;
  std::promise<void> release;
  std::shared_future<void> released = release.get_future().share();
  map.SetUpdateHookForTesting([&entered, released] {
    entered.set_value();
    released.wait();
  });
  map.InsertScan(SampleRectangle(V3(2.9f, -2.9f, -0.9f), V3(0, 5.8f, 0), V3(0, 0, 2.8f), 0.1f), sensor);
  ASSERT_EQ(entered.get_future().wait_for(std::chrono::seconds(60)), std::future_status::ready);
  // The update is computed but held back: readers keep the previous field,
  // and queuing more work does not wait either.
  EXPECT_EQ(map.Snapshot().get(), before.get());
  EXPECT_FLOAT_EQ(map.Snapshot()->Distance(near_new_wall), before->clamp());
  map.SetUpdateHookForTesting({});
  map.UpdateSensorPosition(sensor);
  EXPECT_EQ(map.Snapshot().get(), before.get());
  release.set_value();
  map.WaitForUpdates();

  const std::shared_ptr<const DistanceField> after = map.Snapshot();
  EXPECT_NE(after.get(), before.get());
  EXPECT_GT(after->sequence(), before->sequence());
  EXPECT_NEAR(after->Distance(near_new_wall), 0.4f, 1e-3f);
  EXPECT_FLOAT_EQ(before->Distance(near_new_wall), before->clamp());  // old snapshot intact
}

// A corridor along x (floor and two walls, 3 m apart) seen from a sensor
// driving down it: the box follows the sensor, stays clipped to the
// corridor's cross-section, and the distances stay exact in each new box.
TEST(DistanceMap, BoxFollowsTheSensorAndStaysClippedToTheCorridor) {
  DistanceMapOptions options = TestOptions();
  options.recenter_fraction = 0.25;  // 1.5 m
  DistanceMap map(options);
  V3 sensor(0.1f, 0.1f, 0.1f);
  for (int step = 0; step <= 12; ++step) {
    sensor.x() = 0.1f + 2.0f * static_cast<float>(step);
    const float x0 = sensor.x() - 8.0f;
    std::vector<V3> scan = SampleRectangle(V3(x0, -1.5f, -0.9f), V3(16, 0, 0), V3(0, 3.0f, 0), 0.1f);
    Append(&scan, SampleRectangle(V3(x0, -1.5f, -0.9f), V3(16, 0, 0), V3(0, 0, 2.0f), 0.1f));
    Append(&scan, SampleRectangle(V3(x0, 1.5f, -0.9f), V3(16, 0, 0), V3(0, 0, 2.0f), 0.1f));
    map.InsertScan(std::move(scan), sensor);
    map.WaitForUpdates();  // one update per scan (queued scans would be integrated together)
    ASSERT_TRUE(map.Snapshot()->Contains(sensor)) << step;
  }
  const std::shared_ptr<const DistanceField> field = map.Snapshot();
  ASSERT_TRUE(field->Contains(sensor));
  // Along the corridor the box spans the sensor box; across, the occupied
  // cross-section plus the clamp on each side, not 12 m.
  const V3 size = field->box_max() - field->origin();
  EXPECT_NEAR(size.x(), 12.0f + kRes, 1e-3f);
  EXPECT_NEAR(size.y(), 3.0f + kRes + 2.0f, 1e-3f);
  EXPECT_NEAR(size.z(), 2.0f + kRes + 2.0f, 1e-3f);
  EXPECT_EQ(map.Stats().rebuilds, 13u);  // every 2 m step leaves the central 1.5 m

  // Exact wherever no obstacle outside the box could be nearer than the clamp:
  // within max_range - clamp - recentre distance of the sensor along x.
  const float reach = 6.0f - 1.0f - 1.5f;
  const V3 low(sensor.x() - reach, field->origin().y(), field->origin().z());
  const V3 high(sensor.x() + reach, field->box_max().y(), field->box_max().z());
  ExpectMatchesBruteForce(map, 4, low, high);
}

void ExpectFreeSpaceRaysRemoveAVanishedObstacle(bool clear_occupied_only) {
  DistanceMapOptions options = TestOptions();
  options.clear_occupied_only = clear_occupied_only;
  DistanceMap map(options);
  const V3 sensor(0.1f, 0.1f, 0.1f);
  // A wall 2 m ahead, and two corners of a wider wall 4 m ahead (so the box
  // already covers it and all later changes go through the incremental path).
  std::vector<V3> first = SampleRectangle(V3(2.1f, -1.5f, -1.5f), V3(0, 3.0f, 0), V3(0, 0, 3.0f), 0.1f);
  first.push_back(V3(4.1f, -3.9f, -3.9f));
  first.push_back(V3(4.1f, 3.9f, 3.9f));
  map.InsertScan(first, sensor);
  map.WaitForUpdates();
  const V3 on_old_wall(2.1f, 0.1f, 0.1f);
  EXPECT_NEAR(map.Snapshot()->Distance(on_old_wall), 0.0f, 1e-4f);
  EXPECT_NEAR(map.Snapshot()->Distance(V3(1.5f, 0.1f, 0.1f)), 0.6f, 1e-3f);

  // The near wall is gone: returns now come from the far wall, through it.
  const std::vector<V3> far_wall = SampleRectangle(V3(4.1f, -3.9f, -3.9f), V3(0, 7.8f, 0), V3(0, 0, 7.8f), 0.1f);
  for (int i = 0; i < 5; ++i) map.InsertScan(far_wall, sensor);
  map.WaitForUpdates();
  const std::shared_ptr<const DistanceField> field = map.Snapshot();
  EXPECT_FLOAT_EQ(field->Distance(on_old_wall), field->clamp());  // far wall is 2 m away
  EXPECT_NEAR(field->Distance(V3(3.5f, 0.1f, 0.1f)), 0.6f, 1e-3f);
  for (const V3& c : map.OccupiedVoxelCenters()) EXPECT_GT(c.x(), 4.0f) << c.transpose();
  EXPECT_EQ(map.Stats().rebuilds, 1u);
  ExpectMatchesBruteForce(map, 5, field->origin(), field->box_max());
}

TEST(DistanceMap, FreeSpaceRaysRemoveAVanishedObstacle) {
  ExpectFreeSpaceRaysRemoveAVanishedObstacle(/*clear_occupied_only=*/true);
}

TEST(DistanceMap, FreeSpaceRaysRemoveAVanishedObstacleWithFullOctomapInsertion) {
  ExpectFreeSpaceRaysRemoveAVanishedObstacle(/*clear_occupied_only=*/false);
}

TEST(DistanceMap, QueriesOutsideTheBoxOrFarFromObstaclesReturnTheClamp) {
  DistanceMap map(TestOptions());
  EXPECT_FLOAT_EQ(map.Snapshot()->Distance(V3::Zero()), 1.0f);  // nothing inserted yet
  map.InsertScan(SampleRectangle(V3(-2.9f, -2.9f, -0.9f), V3(5.8f, 0, 0), V3(0, 5.8f, 0), 0.1f), V3(0.1f, 0.1f, 0.1f));
  map.WaitForUpdates();
  const std::shared_ptr<const DistanceField> field = map.Snapshot();
  EXPECT_FLOAT_EQ(field->Distance(V3(0.1f, 0.1f, 0.5f)), 1.0f);    // 1.4 m above the floor
  EXPECT_FLOAT_EQ(field->Distance(V3(50.0f, 0.0f, -0.9f)), 1.0f);  // outside the box
  EXPECT_FLOAT_EQ(field->Distance(V3(0.1f, 0.1f, -5.0f)), 1.0f);   // below the box
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FLOAT_EQ(field->Distance(V3(nan, 0.0f, 0.0f)), 1.0f);
  EXPECT_NEAR(field->Distance(V3(0.1f, 0.1f, -0.3f)), 0.6f, 1e-3f);
}

TEST(DistanceMap, RejectsBadInputWithoutLosingTheMap) {
  DistanceMapOptions bad = TestOptions();
  bad.clamp_distance_m = -1.0;
  EXPECT_THROW(DistanceMap{bad}, ConfigError);

  DistanceMap map(TestOptions());
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(map.InsertScan({V3(1, 1, 1)}, V3(nan, 0, 0)), InputError);
  EXPECT_THROW(map.InsertScan({V3(1, 1, 1)}, V3(1e6f, 0, 0)), InputError);
  EXPECT_THROW(map.SetCenter(V3(0, std::numeric_limits<float>::infinity(), 0)), InputError);
  std::vector<V3> scan = SampleRectangle(V3(-2.9f, -2.9f, -0.9f), V3(5.8f, 0, 0), V3(0, 5.8f, 0), 0.1f);
  scan.push_back(V3(nan, 0, 0));
  scan.push_back(V3(0, std::numeric_limits<float>::infinity(), 0));
  scan.push_back(V3(1e9f, 0, 0));  // finite but beyond the octree: only clears free space
  map.InsertScan(scan, V3(0.1f, 0.1f, 0.1f));
  map.WaitForUpdates();
  EXPECT_EQ(map.Stats().points_skipped, 2u);
  EXPECT_NEAR(map.Snapshot()->Distance(V3(0.1f, 0.1f, -0.5f)), 0.4f, 1e-3f);
}

TEST(DistanceMap, LargeBoxesAreShrunkToTheCellBudget) {
  DistanceMapOptions options = TestOptions();
  options.max_edt_cells = 5000;
  DistanceMap map(options);
  map.InsertScan(SampleBoxSurface(V3(-4.9f, -4.9f, -4.9f), V3(4.9f, 4.9f, 4.9f), 0.1f), V3(0.1f, 0.1f, 0.1f));
  map.WaitForUpdates();
  EXPECT_LE(map.Snapshot()->CellCount(), 5000u);
  EXPECT_GT(map.Snapshot()->CellCount(), 0u);
  EXPECT_GE(map.Stats().budget_shrinks, 1u);
  EXPECT_TRUE(map.Snapshot()->Contains(V3(0.1f, 0.1f, 0.1f)));
}

// Prior maps (for `unimap localize --map`): a floor plane at z = -0.9 m.
std::vector<V3> Floor() { return SampleRectangle(V3(-2.9f, -2.9f, -0.9f), V3(5.8f, 0, 0), V3(0, 5.8f, 0), 0.1f); }

// Localisation in a fixed map moves only the sensor: inside the box nothing
// can change, so the published field is kept (no re-export per scan); a move
// that recentres the box publishes a new one.
TEST(DistanceMap, SensorMovesInsideTheBoxKeepTheField) {
  const auto map = DistanceMap::FromPoints(Floor(), TestOptions(), V3::Zero());
  map->WaitForUpdates();
  const std::shared_ptr<const DistanceField> first = map->Snapshot();
  for (int i = 1; i <= 5; ++i) {
    map->UpdateSensorPosition(V3(0.1f * static_cast<float>(i), 0.0f, 0.5f));
    map->WaitForUpdates();
    EXPECT_EQ(map->Snapshot().get(), first.get()) << i;
  }
  const std::uint64_t rebuilds = map->Stats().rebuilds;
  map->UpdateSensorPosition(V3(4.0f, 0.0f, 0.5f));  // beyond the recentring distance
  map->WaitForUpdates();
  const std::shared_ptr<const DistanceField> moved = map->Snapshot();
  EXPECT_NE(moved.get(), first.get());
  EXPECT_EQ(map->Stats().rebuilds, rebuilds + 1);
  // An explicit centre always recentres: a new field even at the same place.
  map->SetCenter(V3(4.0f, 0.0f, 0.5f));
  map->WaitForUpdates();
  EXPECT_NE(map->Snapshot().get(), moved.get());
}

TEST(DistanceMap, PriorMapFromPointsOctreeAndBtFile) {
  const auto from_points = DistanceMap::FromPoints(Floor(), TestOptions(), V3::Zero());
  from_points->WaitForUpdates();
  EXPECT_NEAR(from_points->Snapshot()->Distance(V3(0.1f, 0.1f, -0.5f)), 0.4f, 1e-3f);

  auto tree = std::make_unique<octomap::OcTree>(0.1);  // its resolution wins
  for (const V3& p : Floor()) tree->updateNode(octomap::point3d(p.x(), p.y(), p.z()), true);
  const std::filesystem::path bt = std::filesystem::temp_directory_path() / "unimap_distance_map_test.bt";
  ASSERT_TRUE(tree->writeBinary(bt.string()));
  const auto loaded = DistanceMap::LoadBt(bt, TestOptions(), V3::Zero());
  std::filesystem::remove(bt);
  loaded->WaitForUpdates();
  EXPECT_DOUBLE_EQ(loaded->options().resolution_m, 0.1);
  EXPECT_FLOAT_EQ(loaded->Snapshot()->resolution(), 0.1f);
  // Floor voxels [-0.9, -0.8] (centre -0.85); query voxel centre -0.45.
  EXPECT_NEAR(loaded->Snapshot()->Distance(V3(0.05f, 0.05f, -0.45f)), 0.4f, 1e-3f);

  const auto adopted = DistanceMap::FromOctree(std::move(tree), TestOptions(), V3::Zero());
  adopted->WaitForUpdates();
  EXPECT_NEAR(adopted->Snapshot()->Distance(V3(0.05f, 0.05f, -0.45f)), 0.4f, 1e-3f);
  // Far from the centre the box moves only when told where the sensor is.
  adopted->UpdateSensorPosition(V3(20.0f, 0.0f, 0.0f));
  adopted->WaitForUpdates();
  EXPECT_EQ(adopted->Snapshot()->CellCount(), 0u);  // no obstacle within 6 m of x = 20
  EXPECT_FLOAT_EQ(adopted->Snapshot()->Distance(V3(0.05f, 0.05f, -0.45f)), 1.0f);
}

TEST(DistanceMap, UnreadableBtFilesAreInputErrors) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path();
  EXPECT_THROW(DistanceMap::LoadBt(dir / "unimap_no_such_map.bt", TestOptions(), V3::Zero()), InputError);
  const std::filesystem::path garbage = dir / "unimap_garbage_map.bt";
  std::ofstream(garbage) << "this is not an octree\n";
  EXPECT_THROW(DistanceMap::LoadBt(garbage, TestOptions(), V3::Zero()), InputError);
  // A valid file cut in half.
  octomap::OcTree tree(0.1);
  for (const V3& p : Floor()) tree.updateNode(octomap::point3d(p.x(), p.y(), p.z()), true);
  std::ostringstream full;
  ASSERT_TRUE(tree.writeBinary(full));
  std::ofstream(garbage, std::ios::binary) << full.str().substr(0, full.str().size() / 2);
  EXPECT_THROW(DistanceMap::LoadBt(garbage, TestOptions(), V3::Zero()), InputError);
  std::filesystem::remove(garbage);
}

}  // namespace
}  // namespace unimap::map
