#include "graph/LoopClosureMatcher.hpp"
#include "graph/LoopClosureNormals.hpp"
#include "graph/SubmapMatchGrid.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "LoopClosureTestScenes.hpp"
#include "matching/VoxelDownsampler.hpp"
#include "unimap/Errors.hpp"

namespace unimap::graph {
namespace {

using test::Pose;

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// The submap frame differs from the world frame (rotated and moved).
const Eigen::Isometry3d kTWorldSubmap = Pose(3.0, -2.0, 0.1, 0.0, 0.0, 25.0 * kDeg);

std::vector<Eigen::Vector3f> SubmapPoints(const test::Scene& scene, float spacing_m) {
  return test::Transform(kTWorldSubmap.inverse(), test::SampleSurfaces(scene, spacing_m));
}

// A scan as the mapper hands it over: 0.1 m voxel filter.
std::vector<Eigen::Vector3f> Scan(const test::Scene& scene, const Eigen::Isometry3d& T_world_body, float range_m,
                                  float noise_m = 0.0f) {
  return matching::VoxelDownsample(test::SimulateScan(scene, T_world_body, range_m, noise_m), 0.1, 0, 1);
}

// Guess = truth moved by (dx, dy, dz) in the submap frame and turned by
// dyaw about z and droll about x.
Eigen::Isometry3d Perturbed(const Eigen::Isometry3d& truth, double dx, double dy, double dz, double droll,
                            double dyaw) {
  Eigen::Isometry3d guess = truth;
  guess.linear() = Eigen::AngleAxisd(dyaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() * truth.linear() *
                   Eigen::AngleAxisd(droll, Eigen::Vector3d::UnitX()).toRotationMatrix();
  guess.translation() += Eigen::Vector3d(dx, dy, dz);
  return guess;
}

void ExpectSymmetricPositiveDefinite(const Matrix6d& covariance) {
  EXPECT_LT((covariance - covariance.transpose()).cwiseAbs().maxCoeff(), 1e-12);
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eigen(covariance);
  EXPECT_GT(eigen.eigenvalues().minCoeff(), 0.0);
}

void Print(const char* name, const LoopClosureResult& r, const Eigen::Isometry3d& truth, double ms) {
  const Eigen::AngleAxisd error(truth.linear().transpose() * r.T_submap_body.linear());
  const Eigen::Vector3d rotation_deg = error.angle() * error.axis() / kDeg;
  const Eigen::Vector3d position_m = r.T_submap_body.translation() - truth.translation();
  std::printf(
      "[ %s ] %s | candidates %d | error %.4f m (%.3f %.3f %.3f) %.3f deg (%.3f %.3f %.3f) | sigma %.3f m "
      "%.4f rad | %.1f ms\n",
      name, r.reason.c_str(), r.candidates, position_m.norm(), position_m.x(), position_m.y(), position_m.z(),
      rotation_deg.norm(), rotation_deg.x(), rotation_deg.y(), rotation_deg.z(),
      std::sqrt(r.covariance.diagonal().head<3>().maxCoeff()), std::sqrt(r.covariance.diagonal().tail<3>().maxCoeff()),
      ms);
}

double Ms(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since).count();
}

class HallTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    matcher_ = new LoopClosureMatcher(SubmapPoints(test::DistinctiveHall(), 0.08f), LoopClosureOptions{});
  }
  static void TearDownTestSuite() {
    delete matcher_;
    matcher_ = nullptr;
  }
  static const LoopClosureMatcher* matcher_;
};
const LoopClosureMatcher* HallTest::matcher_ = nullptr;

const Eigen::Isometry3d kHallWorldBody = Pose(8.0, 5.5, 1.2, 1.0 * kDeg, -0.5 * kDeg, 20.0 * kDeg);

TEST_F(HallTest, RecoversAScanFromMetersAndDegreesOff) {
  const Eigen::Isometry3d truth = kTWorldSubmap.inverse() * kHallWorldBody;
  const Eigen::Isometry3d guess = Perturbed(truth, 2.2, -1.6, 0.25, 0.6 * kDeg, 10.0 * kDeg);
  const auto scan = Scan(test::DistinctiveHall(), kHallWorldBody, 20.0f);
  const auto start = std::chrono::steady_clock::now();
  const LoopClosureResult r = matcher_->Match(scan, guess, 3.0);
  Print("hall", r, truth, Ms(start));
  ASSERT_TRUE(r.accepted) << r.reason;
  EXPECT_LT((r.T_submap_body.translation() - truth.translation()).norm(), 0.01);
  EXPECT_LT(test::RotationError(r.T_submap_body, truth), 0.1 * kDeg);
  EXPECT_GT(r.score, 0.9);
  EXPECT_LE(r.ambiguity, LoopClosureOptions{}.max_ambiguity);
  ExpectSymmetricPositiveDefinite(r.covariance);
}

TEST_F(HallTest, NoisyScanWithOutliersIsStillAccepted) {
  const Eigen::Isometry3d truth = kTWorldSubmap.inverse() * kHallWorldBody;
  const Eigen::Isometry3d guess = Perturbed(truth, -2.5, 1.2, -0.2, -0.5 * kDeg, -9.0 * kDeg);
  auto scan = Scan(test::DistinctiveHall(), kHallWorldBody, 20.0f, 0.015f);
  // Replace 8 % of the points by clutter anywhere within 10 m.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<float> any(-10.0f, 10.0f);
  for (std::size_t i = 0; i < scan.size(); i += 12) scan[i] = Eigen::Vector3f(any(rng), any(rng), any(rng) * 0.15f);
  const auto start = std::chrono::steady_clock::now();
  const LoopClosureResult r = matcher_->Match(scan, guess, 3.0);
  Print("hall noisy", r, truth, Ms(start));
  ASSERT_TRUE(r.accepted) << r.reason;
  EXPECT_LT((r.T_submap_body.translation() - truth.translation()).norm(), 0.01);
  EXPECT_LT(test::RotationError(r.T_submap_body, truth), 0.1 * kDeg);
  ExpectSymmetricPositiveDefinite(r.covariance);
}

TEST_F(HallTest, ScanOfAnotherPlaceIsRejectedForItsScore) {
  // A store room with a lower ceiling: only the floor and a wall or two fit.
  const Eigen::Isometry3d T_world_body = Pose(2.0, 3.0, 1.2, 0.0, 0.0, 0.0);
  const auto scan = Scan(test::StoreRoom(2.4f), T_world_body, 20.0f);
  const Eigen::Isometry3d guess = kTWorldSubmap.inverse() * Pose(8.0, 5.0, 1.2, 0.0, 0.0, 0.0);
  const LoopClosureResult r = matcher_->Match(scan, guess, 3.0);
  Print("low store room in hall", r, guess, 0.0);
  EXPECT_FALSE(r.accepted);
  EXPECT_LT(r.score, LoopClosureOptions{}.min_score);
  EXPECT_NE(r.reason.find("score"), std::string::npos) << r.reason;
}

TEST_F(HallTest, ScanOfAnotherPlaceWithTheSameFloorAndCeilingIsRejected) {
  // Floor and ceiling at the hall's heights explain ~60 % of the scan, but
  // every shift along them explains as much: ambiguous.
  const Eigen::Isometry3d T_world_body = Pose(2.0, 3.0, 1.2, 0.0, 0.0, 0.0);
  const auto scan = Scan(test::StoreRoom(3.0f), T_world_body, 20.0f);
  const Eigen::Isometry3d guess = kTWorldSubmap.inverse() * Pose(8.0, 5.0, 1.2, 0.0, 0.0, 0.0);
  const LoopClosureResult r = matcher_->Match(scan, guess, 3.0);
  Print("store room in hall", r, guess, 0.0);
  EXPECT_FALSE(r.accepted);
  EXPECT_LT(r.score, 0.7);
}

TEST_F(HallTest, EmptyOrNonFiniteInputs) {
  const Eigen::Isometry3d guess = Eigen::Isometry3d::Identity();
  const LoopClosureResult empty = matcher_->Match({}, guess, 3.0);
  EXPECT_FALSE(empty.accepted);
  EXPECT_NE(empty.reason.find("too few scan points"), std::string::npos) << empty.reason;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const LoopClosureResult nans = matcher_->Match({Eigen::Vector3f(nan, 0.0f, 0.0f)}, guess, 3.0);
  EXPECT_FALSE(nans.accepted);
  EXPECT_THROW(matcher_->Match({Eigen::Vector3f::Ones()}, guess, -1.0), InputError);
  EXPECT_THROW(matcher_->Match({Eigen::Vector3f::Ones()}, guess, std::nan("")), InputError);
  Eigen::Isometry3d bad = guess;
  bad.translation().x() = std::nan("");
  EXPECT_THROW(matcher_->Match({Eigen::Vector3f::Ones()}, bad, 1.0), InputError);
}

TEST(LoopClosureMatcherTest, ConstructorRejectsBadInputs) {
  EXPECT_THROW(LoopClosureMatcher({}, LoopClosureOptions{}), InputError);
  EXPECT_THROW(LoopClosureMatcher({Eigen::Vector3f(std::nanf(""), 0.0f, 0.0f)}, LoopClosureOptions{}), InputError);
  LoopClosureOptions bad;
  bad.min_score = 2.0;
  EXPECT_THROW(LoopClosureMatcher({Eigen::Vector3f::Zero()}, bad), ConfigError);
  // Points kilometres apart: too large a box.
  EXPECT_THROW(
      LoopClosureMatcher({Eigen::Vector3f::Zero(), Eigen::Vector3f(5000.0f, 5000.0f, 100.0f)}, LoopClosureOptions{}),
      InputError);
}

// Repeated structure: the scan matches every period_m along the corridor.
void ExpectRejectedInCorridor(float period_m, double offset_m, const char* name) {
  const test::Scene corridor = test::PillarCorridor(period_m);
  const LoopClosureMatcher matcher(SubmapPoints(corridor, 0.08f), LoopClosureOptions{});
  const Eigen::Isometry3d T_world_body = Pose(30.4, 1.5, 1.2, 0.5 * kDeg, 0.0, 3.0 * kDeg);
  const Eigen::Isometry3d truth = kTWorldSubmap.inverse() * T_world_body;
  // The guess is off by about one period along the corridor (x of the world).
  const Eigen::Vector3d along = kTWorldSubmap.linear().transpose() * Eigen::Vector3d(offset_m, 0.1, 0.0);
  const Eigen::Isometry3d guess = Perturbed(truth, along.x(), along.y(), 0.1, 0.0, 4.0 * kDeg);
  const auto scan = Scan(corridor, T_world_body, 10.0f);
  const auto start = std::chrono::steady_clock::now();
  const LoopClosureResult r = matcher.Match(scan, guess, 3.0);
  Print(name, r, truth, Ms(start));
  EXPECT_FALSE(r.accepted) << "accepted " << (r.T_submap_body.translation() - truth.translation()).norm()
                           << " m from the truth";
  EXPECT_GT(r.ambiguity, LoopClosureOptions{}.max_ambiguity);
  EXPECT_NE(r.reason.find("ambiguous"), std::string::npos) << r.reason;
}

TEST(LoopClosureMatcherTest, RepeatedStructureWithinTheRadiusIsRejected) {
  ExpectRejectedInCorridor(2.5f, 2.5, "corridor 2.5 m");
}

TEST(LoopClosureMatcherTest, RepeatedStructureJustBeyondTheRadiusIsRejected) {
  // Only the wrong alignment lies within 3 m of the guess; the true one
  // 3.6 m away is found through the ambiguity margin.
  ExpectRejectedInCorridor(3.6f, 3.6, "corridor 3.6 m");
}

TEST(LoopClosureMatcherTest, FeaturelessCorridorIsRejected) {
  // Nothing fixes the position along the corridor.
  const test::Scene corridor = test::Room(60.0f, 3.0f, 3.0f);
  const LoopClosureMatcher matcher(SubmapPoints(corridor, 0.08f), LoopClosureOptions{});
  const Eigen::Isometry3d T_world_body = Pose(30.0, 1.4, 1.2, 0.0, 0.0, 5.0 * kDeg);
  const Eigen::Isometry3d truth = kTWorldSubmap.inverse() * T_world_body;
  const LoopClosureResult r =
      matcher.Match(Scan(corridor, T_world_body, 10.0f), Perturbed(truth, 1.0, -0.5, 0.1, 0.0, 3.0 * kDeg), 3.0);
  Print("featureless corridor", r, truth, 0.0);
  EXPECT_FALSE(r.accepted);
  EXPECT_GT(r.score, 0.95);  // it fits everywhere along the corridor
}

// Timing on a large submap (~200k points): printed, not asserted.
TEST(LoopClosureMatcherTest, LargeSubmapTiming) {
  test::Scene hall = test::Room(32.0f, 16.0f, 3.5f);
  const test::Scene features = test::DistinctiveHall();
  for (std::size_t i = 6; i < features.size(); ++i) hall.push_back(features[i]);  // furniture only
  const auto points = SubmapPoints(hall, 0.08f);
  const LoopClosureOptions options;
  auto start = std::chrono::steady_clock::now();
  const SubmapMatchGrid grid(points, options.search_resolution_m, options.search_kernel_m, options.search_levels);
  const double grid_ms = Ms(start);
  start = std::chrono::steady_clock::now();
  const auto normals = LoopClosureNormals(points, options.normal_cell_m, options.planarity_ratio);
  const double normals_ms = Ms(start);
  start = std::chrono::steady_clock::now();
  const LoopClosureMatcher matcher(points, options);
  const double build_ms = Ms(start);
  std::printf("[ timing ] parts: search grid %.1f ms (%.1f MB), normals %.1f ms\n", grid_ms,
              static_cast<double>(grid.MemoryBytes()) / 1e6, normals_ms);
  const Eigen::Isometry3d T_world_body = Pose(12.0, 5.0, 1.5, 0.0, 0.0, -30.0 * kDeg);
  const Eigen::Isometry3d truth = kTWorldSubmap.inverse() * T_world_body;
  const auto scan = Scan(hall, T_world_body, 30.0f);
  const Eigen::Isometry3d guess = Perturbed(truth, 1.8, 2.0, 0.2, 0.0, 8.0 * kDeg);
  start = std::chrono::steady_clock::now();
  const LoopClosureResult r = matcher.Match(scan, guess, 3.0);
  const double match_ms = Ms(start);
  std::printf("[ timing ] submap %zu points: construction %.1f ms, %.1f MB; scan %zu points: Match (3 m) %.1f ms\n",
              points.size(), build_ms, static_cast<double>(matcher.MemoryBytes()) / 1e6, scan.size(), match_ms);
  Print("large hall", r, truth, match_ms);
  EXPECT_TRUE(r.accepted) << r.reason;
  EXPECT_LT((r.T_submap_body.translation() - truth.translation()).norm(), 0.03);
}

}  // namespace
}  // namespace unimap::graph
