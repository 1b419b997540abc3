#include "graph/LoopClosureRefiner.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "LoopClosureTestScenes.hpp"
#include "matching/VoxelDownsampler.hpp"

namespace unimap::graph {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

struct World {
  LoopClosureOptions options;
  std::vector<Eigen::Vector3f> points;
  LoopClosureDistanceField field;
  explicit World(const test::Scene& scene)
      : points(test::SampleSurfaces(scene, 0.08f)),
        field(points, options.fine_resolution_m, options.fine_clamp_m, options.normal_cell_m, options.planarity_ratio) {
  }
};

std::vector<Eigen::Vector3f> Scan(const test::Scene& scene, const Eigen::Isometry3d& T_world_body, float range_m) {
  return matching::VoxelDownsample(test::SimulateScan(scene, T_world_body, range_m), 0.1, 2000, 1);
}

TEST(LoopClosureRefinerTest, ConvergesFromDecimetersAndDegreesOff) {
  const World world(test::DistinctiveHall());
  const Eigen::Isometry3d truth = test::Pose(8.0, 5.5, 1.2, 1.0 * kDeg, -0.5 * kDeg, 20.0 * kDeg);
  const auto scan = Scan(test::DistinctiveHall(), truth, 20.0f);
  const Eigen::Isometry3d start = test::Pose(8.12, 5.42, 1.25, 0.0, 0.5 * kDeg, 22.0 * kDeg);
  const LoopClosureRefiner refiner(world.field, world.options);
  EXPECT_LT(refiner.Score(scan, start), 0.8);
  const LoopClosureRefinement r = refiner.Refine(scan, start, 30);
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_LT((r.T_submap_body.translation() - truth.translation()).norm(), 0.005);
  EXPECT_LT(test::RotationError(r.T_submap_body, truth), 0.1 * kDeg);
  EXPECT_GT(r.score, 0.99);
  EXPECT_NEAR(r.score, refiner.Score(scan, r.T_submap_body), 1e-12);
  EXPECT_LT(r.rms_m, 0.01);  // plane residuals of a noise-free scan (local plane fits near edges)
  EXPECT_LE(r.iterations, 30);
  // Covariance: SPD, floors included, well constrained in a closed hall.
  EXPECT_LT((r.covariance - r.covariance.transpose()).cwiseAbs().maxCoeff(), 1e-15);
  using Matrix6 = Eigen::Matrix<double, 6, 6>;
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Matrix6>(r.covariance).eigenvalues().minCoeff(), 0.0);
  for (int a = 0; a < 3; ++a) {
    EXPECT_GE(r.covariance(a, a), std::pow(world.options.min_sigma_position_m, 2));
    EXPECT_LT(std::sqrt(r.covariance(a, a)), 0.05);
    EXPECT_GE(r.covariance(3 + a, 3 + a), std::pow(world.options.min_sigma_rotation_rad, 2));
  }
}

TEST(LoopClosureRefinerTest, CovarianceIsLargeAlongAFeaturelessCorridor) {
  const test::Scene corridor = test::Room(40.0f, 3.0f, 3.0f);
  const World world(corridor);
  const Eigen::Isometry3d truth = test::Pose(20.0, 1.5, 1.2, 0.0, 0.0, 0.0);
  const auto scan = Scan(corridor, truth, 8.0f);
  const LoopClosureRefiner refiner(world.field, world.options);
  const LoopClosureRefinement r = refiner.Refine(scan, truth, 30);
  ASSERT_TRUE(r.ok) << r.reason;
  const double sigma_x = std::sqrt(r.covariance(0, 0));  // along the corridor
  const double sigma_y = std::sqrt(r.covariance(1, 1));
  EXPECT_GT(sigma_x, world.options.max_position_sigma_m);
  EXPECT_LT(sigma_y, 0.05);
}

TEST(LoopClosureRefinerTest, ScanFarFromTheSubmapFails) {
  const World world(test::DistinctiveHall());
  const std::vector<Eigen::Vector3f> scan(50, Eigen::Vector3f(100.0f, 0.0f, 0.0f));
  const LoopClosureRefiner refiner(world.field, world.options);
  const LoopClosureRefinement r = refiner.Refine(scan, Eigen::Isometry3d::Identity(), 30);
  EXPECT_FALSE(r.ok);
  EXPECT_FALSE(r.reason.empty());
  EXPECT_EQ(refiner.Score(scan, Eigen::Isometry3d::Identity()), 0.0);
  EXPECT_EQ(refiner.Score({}, Eigen::Isometry3d::Identity()), 0.0);
}

}  // namespace
}  // namespace unimap::graph
