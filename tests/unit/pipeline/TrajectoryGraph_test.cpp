#include "pipeline/TrajectoryGraph.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace unimap::pipeline {
namespace {

Eigen::Isometry3d Pose(double x, double y, double z, double yaw_rad) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(x, y, z);
  T.linear() = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return T;
}

// One key scan into submap `id` (created by this insertion when `create`).
map::SubmapInsertion Into(int id, const Eigen::Isometry3d& T_local_submap, bool create) {
  map::SubmapInsertion insertion;
  insertion.submap_ids = {id};
  insertion.T_local_submaps = {T_local_submap};
  if (create) {
    insertion.created_ids = {id};
    insertion.created_T_local_submaps = {T_local_submap};
  }
  return insertion;
}

TEST(TrajectoryGraphTest, WithoutOptimizationTheWorldIsTheLocalFrame) {
  TrajectoryGraph graph(0.05, 0.005);
  const Eigen::Isometry3d T_local_submap(Eigen::Translation3d(1, 2, 0));
  graph.AddKeyScan(1.0, Pose(1, 2, 0, 0.1), Into(0, T_local_submap, true));
  graph.AddKeyScan(2.0, Pose(2, 2, 0, 0.2), Into(0, T_local_submap, false));
  EXPECT_EQ(graph.key_scan_count(), 2u);
  EXPECT_EQ(graph.graph().NodeCount(), 3u);  // one submap, two key scans
  // Two scan-in-submap; no odometry: both key scans are in submap 0.
  EXPECT_EQ(graph.graph().ConstraintCount(), 2u);
  EXPECT_TRUE(graph.T_world_local().isApprox(Eigen::Isometry3d::Identity()));
  EXPECT_TRUE(graph.ToWorld(1.5, Pose(1.5, 2, 0, 0.15)).isApprox(Pose(1.5, 2, 0, 0.15)));
}

TEST(TrajectoryGraphTest, OdometryLinksOnlyKeyScansWithoutACommonSubmap) {
  TrajectoryGraph graph(0.05, 0.005);
  const Eigen::Isometry3d T_local_a = Eigen::Isometry3d::Identity();
  const Eigen::Isometry3d T_local_b(Eigen::Translation3d(2, 0, 0));
  graph.AddKeyScan(1.0, Pose(1, 0, 0, 0.0), Into(0, T_local_a, true));
  // Into submaps 0 and 1 (as the Mapper's growing and matching submaps overlap).
  map::SubmapInsertion both = Into(1, T_local_b, true);
  both.submap_ids.insert(both.submap_ids.begin(), 0);
  both.T_local_submaps.insert(both.T_local_submaps.begin(), T_local_a);
  graph.AddKeyScan(2.0, Pose(2, 0, 0, 0.1), both);
  EXPECT_EQ(graph.graph().ConstraintCount(), 3u);  // 1 + 2 scan-in-submap, submap 0 shared
  graph.AddKeyScan(3.0, Pose(3, 0, 0, 0.2), Into(2, Pose(3, 0, 0, 0.0), true));
  ASSERT_EQ(graph.graph().ConstraintCount(), 5u);  // scan-in-submap 2 and odometry: nothing shared
  const graph::PoseConstraint& odometry = graph.graph().constraints().back();
  EXPECT_EQ(odometry.kind, graph::ConstraintKind::kOdometry);
  EXPECT_TRUE(odometry.T_from_to.isApprox(Pose(2, 0, 0, 0.1).inverse() * Pose(3, 0, 0, 0.2), 1e-12));
  // The shared submap carries the relative pose the odometry constraint
  // would: T_a_key1^-1 T_a_key2 is the two key scans' local relative pose.
  const auto& c = graph.graph().constraints();
  EXPECT_TRUE(
      (c[0].T_from_to.inverse() * c[1].T_from_to).isApprox(Pose(1, 0, 0, 0.0).inverse() * Pose(2, 0, 0, 0.1), 1e-12));
}

TEST(TrajectoryGraphTest, OptimizedPosesCorrectLaterPosesAndNewNodes) {
  TrajectoryGraph graph(0.05, 0.005);
  const Eigen::Isometry3d T_local_submap = Eigen::Isometry3d::Identity();
  graph.AddKeyScan(1.0, Pose(1, 0, 0, 0.0), Into(0, T_local_submap, true));
  graph.AddKeyScan(2.0, Pose(2, 0, 0, 0.1), Into(0, T_local_submap, false));
  // An optimiser result that moved everything by a known transform.
  const Eigen::Isometry3d T_fix = Pose(0.3, -0.2, 0.05, 0.02);
  std::vector<Eigen::Isometry3d> T_world_node;
  T_world_node.push_back(T_fix * T_local_submap);
  T_world_node.push_back(T_fix * Pose(1, 0, 0, 0.0));
  T_world_node.push_back(T_fix * Pose(2, 0, 0, 0.1));
  // A key scan added while the optimiser ran.
  graph.AddKeyScan(3.0, Pose(3, 0, 0, 0.2), Into(0, T_local_submap, false));
  graph.ApplyOptimized(T_world_node);
  EXPECT_TRUE(graph.T_world_local().isApprox(T_fix, 1e-12));
  EXPECT_TRUE(graph.T_world_key(2).isApprox(T_fix * Pose(3, 0, 0, 0.2), 1e-12));  // moved by the correction
  // A pose inside the second key scan's accumulation, and one after the last.
  EXPECT_TRUE(graph.ToWorld(1.5, Pose(1.5, 0, 0, 0.05)).isApprox(T_fix * Pose(1.5, 0, 0, 0.05), 1e-12));
  EXPECT_TRUE(graph.ToWorld(9.0, Pose(5, 0, 0, 0.3)).isApprox(T_fix * Pose(5, 0, 0, 0.3), 1e-12));
  Eigen::Isometry3d T_world_submap;
  ASSERT_TRUE(graph.T_world_submap(0, &T_world_submap));
  EXPECT_TRUE(T_world_submap.isApprox(T_fix, 1e-12));
  EXPECT_FALSE(graph.T_world_submap(7, &T_world_submap));
}

// A 10 m square flown with a yaw drift of 0.25 deg per metre: the odometry
// ends metres away from the start. One loop closure of the last key scan
// against the first submap (its true relative pose) pulls it back.
TEST(TrajectoryGraphTest, LoopClosureRemovesDriftOnASquare) {
  constexpr int kScans = 40;  // one key scan per metre
  constexpr double kDriftRadPerScan = 0.25 * M_PI / 180.0;
  std::vector<Eigen::Isometry3d> truth, local;
  for (int k = 0; k < kScans; ++k) {
    const int side = k / 10;
    const double s = k % 10;
    const double yaw = side * M_PI / 2.0;
    const Eigen::Vector2d corners[4] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    const Eigen::Vector2d p = corners[side] + s * Eigen::Vector2d(std::cos(yaw), std::sin(yaw));
    truth.push_back(Pose(p.x(), p.y(), 0.0, yaw));
  }
  // Odometry: true increments with a small extra yaw each step.
  local.push_back(truth[0]);
  for (int k = 1; k < kScans; ++k) {
    local.push_back(local.back() * truth[static_cast<std::size_t>(k - 1)].inverse() *
                    truth[static_cast<std::size_t>(k)] * Pose(0, 0, 0, kDriftRadPerScan));
  }
  TrajectoryGraph graph(0.05, 0.005);
  std::vector<Eigen::Isometry3d> submap_frames;
  for (int k = 0; k < kScans; ++k) {
    const int id = k / 4;
    const bool create = k % 4 == 0;
    if (create)
      submap_frames.push_back(
          Eigen::Isometry3d(Eigen::Translation3d(local[static_cast<std::size_t>(k)].translation())));
    graph.AddKeyScan(k, local[static_cast<std::size_t>(k)],
                     Into(id, submap_frames[static_cast<std::size_t>(id)], create));
  }
  const double before = (graph.T_world_key(kScans - 1).translation() - truth.back().translation()).norm();
  ASSERT_GT(before, 1.0);
  LoopClosure closure;
  closure.key_scan = kScans - 1;
  closure.submap_id = 0;  // its local frame is its true frame (no drift at the start)
  closure.T_submap_body = submap_frames[0].inverse() * truth.back();
  closure.covariance.diagonal() << 1e-4, 1e-4, 1e-4, 1e-6, 1e-6, 1e-6;
  graph.AddLoopClosure(closure);
  EXPECT_EQ(graph.loop_closures(), 1u);
  graph::PoseGraph copy = graph.graph();
  const graph::OptimizationSummary summary = copy.Optimize(graph::PoseGraphOptions{});
  ASSERT_TRUE(summary.ok) << summary.reason;
  std::vector<Eigen::Isometry3d> optimized;
  for (std::size_t i = 0; i < copy.NodeCount(); ++i) optimized.push_back(copy.Pose(static_cast<int>(i)));
  graph.ApplyOptimized(optimized);
  const double after = (graph.T_world_key(kScans - 1).translation() - truth.back().translation()).norm();
  // The closure is 100x more certain than one odometry link: the end lands within a few cm.
  EXPECT_LT(after, 0.05) << "before " << before;
  // The whole square improves, not just the end.
  double max_before = 0.0, max_after = 0.0;
  for (int k = 0; k < kScans; ++k) {
    max_before = std::max(
        max_before,
        (local[static_cast<std::size_t>(k)].translation() - truth[static_cast<std::size_t>(k)].translation()).norm());
    max_after = std::max(
        max_after, (graph.T_world_key(k).translation() - truth[static_cast<std::size_t>(k)].translation()).norm());
  }
  EXPECT_LT(max_after, 0.25 * max_before) << max_before << " -> " << max_after;
  // Corrected poses follow: the last key scan's local pose maps to its world pose.
  EXPECT_TRUE(graph.ToWorld(kScans - 1, local.back()).isApprox(graph.T_world_key(kScans - 1), 1e-9));
}

}  // namespace
}  // namespace unimap::pipeline
