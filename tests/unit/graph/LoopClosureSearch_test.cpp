#include "graph/LoopClosureSearch.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "LoopClosureTestScenes.hpp"
#include "matching/VoxelDownsampler.hpp"

namespace unimap::graph {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

double Yaw(const Eigen::Isometry3d& T) { return std::atan2(T.linear()(1, 0), T.linear()(0, 0)); }

class LoopClosureSearchTest : public ::testing::Test {
 protected:
  LoopClosureSearchTest()
      : points_(test::SampleSurfaces(test::DistinctiveHall(), 0.1f)),
        grid_(points_, options_.search_resolution_m, options_.search_kernel_m, options_.search_levels) {
    truth_ = test::Pose(8.0, 5.5, 1.2, 0.0, 0.0, 20.0 * kDeg);
    scan_ = matching::VoxelDownsample(test::SimulateScan(test::DistinctiveHall(), truth_, 20.0f),
                                      options_.search_voxel_m, options_.max_search_points, 1);
  }
  LoopClosureOptions options_;
  std::vector<Eigen::Vector3f> points_;
  SubmapMatchGrid grid_;
  Eigen::Isometry3d truth_;
  std::vector<Eigen::Vector3f> scan_;
};

TEST_F(LoopClosureSearchTest, BestMaximumLiesNextToTheTruth) {
  Eigen::Isometry3d guess = test::Pose(8.0 + 1.3, 5.5 - 0.8, 1.2 + 0.2, 0.0, 0.0, 26.0 * kDeg);
  const LoopClosureSearch search(grid_, options_);
  LoopClosureSearchStats stats;
  const auto candidates = search.Run(scan_, guess, 3.0, &stats);
  ASSERT_FALSE(candidates.empty());
  EXPECT_LE(candidates.size(), static_cast<std::size_t>(options_.max_candidates));
  const LoopClosureCandidate& best = candidates.front();
  // Within one lattice step in translation (one cell) and yaw.
  EXPECT_LT((best.T_submap_body.translation() - truth_.translation()).norm(),
            std::sqrt(3.0) * options_.search_resolution_m);
  EXPECT_LE(std::abs(Yaw(best.T_submap_body) - Yaw(truth_)), stats.yaw_step_rad + 1e-9);
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const Eigen::Vector3d shift = candidates[i].T_submap_body.translation() - guess.translation();
    EXPECT_LE(shift.head<2>().norm(), 3.0 + 1e-9);
    EXPECT_LE(std::abs(shift.z()), options_.z_window_m + 1e-9);
    EXPECT_LE(std::abs(Yaw(candidates[i].T_submap_body) - Yaw(guess)), options_.yaw_window_rad + 1e-9);
    EXPECT_GE(candidates[i].score, options_.candidate_score_ratio * best.score - 1e-12);
    if (i > 0) {
      EXPECT_LE(candidates[i].score, candidates[i - 1].score);
    }
    for (std::size_t j = 0; j < i; ++j) {  // pairwise distinct
      const double dt = (candidates[i].T_submap_body.translation() - candidates[j].T_submap_body.translation()).norm();
      const double dyaw = std::abs(Yaw(candidates[i].T_submap_body) - Yaw(candidates[j].T_submap_body));
      EXPECT_TRUE(dt > options_.distinct_translation_m || dyaw > options_.distinct_rotation_rad) << i << " " << j;
    }
  }
  EXPECT_LT(stats.leaves, stats.nodes);
}

TEST_F(LoopClosureSearchTest, BranchAndBoundFindsTheExhaustiveMaximum) {
  options_.yaw_window_rad = 4.0 * kDeg;
  const Eigen::Isometry3d guess = test::Pose(8.0 + 0.6, 5.5 - 0.4, 1.2, 0.0, 0.0, 22.0 * kDeg);
  const double radius = 1.2;
  const LoopClosureSearch search(grid_, options_);
  LoopClosureSearchStats stats;
  const auto candidates = search.Run(scan_, guess, radius, &stats);
  ASSERT_FALSE(candidates.empty());
  // Every lattice pose scored directly on level 0.
  const double r = grid_.resolution();
  const int window = static_cast<int>(std::ceil(radius / r));
  const int z_window = static_cast<int>(std::floor(options_.z_window_m / r + 1e-9));
  const int half = (stats.yaw_steps - 1) / 2;
  int best = 0;
  for (int k = -half; k <= half; ++k) {
    const Eigen::Matrix3d R =
        Eigen::AngleAxisd(k * stats.yaw_step_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix() * guess.linear();
    for (int ix = -window; ix <= window; ++ix) {
      for (int iy = -window; iy <= window; ++iy) {
        if ((ix * ix + iy * iy) * r * r > radius * radius + 1e-9) continue;
        for (int iz = -z_window; iz <= z_window; ++iz) {
          int sum = 0;
          for (const auto& p : scan_) {
            const Eigen::Vector3i cell = grid_.CellOf(R * p.cast<double>() + guess.translation());
            sum += grid_.Value(0, cell + Eigen::Vector3i(ix, iy, iz));
          }
          best = std::max(best, sum);
        }
      }
    }
  }
  EXPECT_NEAR(candidates.front().score, best / (255.0 * static_cast<double>(scan_.size())), 1e-12);
}

TEST_F(LoopClosureSearchTest, NoPointsGiveNoCandidates) {
  const LoopClosureSearch search(grid_, options_);
  EXPECT_TRUE(search.Run({}, truth_, 3.0, nullptr).empty());
}

}  // namespace
}  // namespace unimap::graph
