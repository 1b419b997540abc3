#include "eval/TrajectoryEvaluation.hpp"

#include <gtest/gtest.h>

#include "EvalFixtures.hpp"
#include "unimap/Errors.hpp"

namespace unimap::eval {
namespace {

using testing::Helix;
using testing::MakePose;
using testing::StraightLine;
using testing::Transformed;

constexpr double kTol = 1e-9;

// Path length of the Helix() polyline.
double HelixLength() {
  const std::vector<StampedPose> h = Helix();
  double length = 0.0;
  for (std::size_t k = 1; k < h.size(); ++k) {
    length += (h[k].T_map_body.translation() - h[k - 1].T_map_body.translation()).norm();
  }
  return length;
}

void ExpectAllErrorsZero(const TrajectoryMetrics& m) {
  EXPECT_NEAR(m.ate_rmse_m, 0.0, kTol);
  ASSERT_TRUE(m.drift_percent.has_value());
  EXPECT_NEAR(*m.drift_percent, 0.0, kTol);
  EXPECT_NEAR(m.max_abs_error_m.norm(), 0.0, kTol);
  EXPECT_NEAR(m.mean_abs_rot_error_deg.norm(), 0.0, kTol);
  ASSERT_TRUE(m.rot_drift_deg_per_m.has_value());
  EXPECT_NEAR(*m.rot_drift_deg_per_m, 0.0, kTol);
  ASSERT_TRUE(m.rpe_trans_percent.has_value());
  EXPECT_NEAR(*m.rpe_trans_percent, 0.0, kTol);
  EXPECT_NEAR(*m.rpe_rot_deg_per_m, 0.0, kTol);
  EXPECT_NEAR(m.final_position_error_m, 0.0, kTol);
  EXPECT_NEAR(m.final_rot_error_deg, 0.0, kTol);
}

TEST(TrajectoryEvaluationTest, TruthAgainstItselfIsAllZeros) {
  const TrajectoryEvaluation ev = EvaluateTrajectory(Helix(), Helix());
  ExpectAllErrorsZero(ev.metrics);
  EXPECT_NEAR(ev.metrics.path_length_m, HelixLength(), 1e-12);
  EXPECT_EQ(ev.metrics.poses_associated, 601u);
  EXPECT_EQ(ev.metrics.poses_skipped, 0u);
  EXPECT_NEAR(ev.metrics.duration_s, 60.0, 1e-9);
  EXPECT_GT(ev.metrics.rpe_segments, 0u);
}

TEST(TrajectoryEvaluationTest, ConstantOffsetIsInvisibleAfterAlignmentAndAnchoring) {
  Eigen::Isometry3d T_offset = Eigen::Isometry3d::Identity();
  T_offset.translation() = Eigen::Vector3d(3.0, -4.0, 1.5);
  const TrajectoryEvaluation ev = EvaluateTrajectory(Transformed(Helix(), T_offset), Helix());
  ExpectAllErrorsZero(ev.metrics);
}

TEST(TrajectoryEvaluationTest, RigidlyTransformedEstimateHasZeroErrorsWithFullPoseAnchoring) {
  Eigen::Isometry3d T_est_true = Eigen::Isometry3d::Identity();
  T_est_true.linear() = Eigen::AngleAxisd(0.8, Eigen::Vector3d(1, 2, -1).normalized()).toRotationMatrix();
  T_est_true.translation() = Eigen::Vector3d(-7.0, 2.0, 0.5);
  EvaluationOptions options;
  options.anchor = Anchor::kFullPose;  // an arbitrary (tilted) estimate frame
  const TrajectoryEvaluation ev = EvaluateTrajectory(Transformed(Helix(), T_est_true), Helix(), options);
  ExpectAllErrorsZero(ev.metrics);
  // The alignment found is the inverse transform.
  EXPECT_TRUE(ev.errors.alignment.T_target_source.isApprox(T_est_true.inverse(), 1e-9));
}

TEST(TrajectoryEvaluationTest, GravityAlignedFramesDifferingInYawAndPositionGiveZeroErrors) {
  Eigen::Isometry3d T_est_true = Eigen::Isometry3d::Identity();
  T_est_true.linear() = Eigen::AngleAxisd(-2.1, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T_est_true.translation() = Eigen::Vector3d(4.0, -3.0, 1.5);
  const TrajectoryEvaluation ev = EvaluateTrajectory(Transformed(Helix(), T_est_true), Helix());
  ExpectAllErrorsZero(ev.metrics);
}

TEST(TrajectoryEvaluationTest, ATiltedEstimateFrameIsAnErrorUnlessAnchoredOnTheFullPose) {
  // A gravity-aligned estimator that misjudged the initial tilt by 0.3 deg
  // (e.g. an accelerometer bias taken for gravity) estimates every attitude
  // 0.3 deg off about the world y axis. Anchoring position and heading keeps
  // that error (the paper's rotation error); anchoring the full first pose
  // would tilt the whole estimate to hide it.
  const double tilt_rad = 0.3 * M_PI / 180.0;
  const Eigen::Isometry3d T_tilt(Eigen::AngleAxisd(tilt_rad, Eigen::Vector3d::UnitY()));
  const std::vector<StampedPose> truth = StraightLine(100);
  std::vector<StampedPose> estimate = truth;
  for (StampedPose& p : estimate) p.T_map_body.linear() = T_tilt.linear() * p.T_map_body.linear();
  const TrajectoryMetrics kept = EvaluateTrajectory(estimate, truth).metrics;
  EXPECT_NEAR(kept.mean_abs_rot_error_deg.y(), 0.3, 1e-9);  // pitch: the straight line heads along x
  EXPECT_NEAR(kept.max_abs_error_m.norm(), 0.0, 1e-9);      // positions are right
  EvaluationOptions full;
  full.anchor = Anchor::kFullPose;
  const TrajectoryMetrics hidden = EvaluateTrajectory(estimate, truth, full).metrics;
  EXPECT_NEAR(hidden.mean_abs_rot_error_deg.norm(), 0.0, 1e-9);
  EXPECT_NEAR(hidden.max_abs_error_m.z(), 100.0 * std::sin(tilt_rad), 1e-6);  // the tilt bends the line instead
}

TEST(TrajectoryEvaluationTest, LinearDriftGivesExactDriftMaxErrorAndAte) {
  // 100 m straight line, x error growing linearly from 0 to 1.0 m.
  const int n = 100;
  const std::vector<StampedPose> truth = StraightLine(n);
  std::vector<StampedPose> estimate = truth;
  for (int k = 0; k <= n; ++k) estimate[static_cast<std::size_t>(k)].T_map_body.translation().x() += k / 100.0;
  const TrajectoryMetrics m = EvaluateTrajectory(estimate, truth).metrics;
  EXPECT_NEAR(m.path_length_m, 100.0, 1e-12);
  ASSERT_TRUE(m.drift_percent.has_value());
  EXPECT_NEAR(*m.drift_percent, 1.0, 1e-12);
  EXPECT_NEAR(m.max_abs_error_m.x(), 1.0, 1e-12);
  EXPECT_EQ(m.max_abs_error_m.y(), 0.0);
  EXPECT_EQ(m.max_abs_error_m.z(), 0.0);
  // ATE: the rigid fit centres the errors e_k = k / n, so the RMSE is their
  // standard deviation: sqrt(((n + 1)^2 - 1) / 12) / n = sqrt((n + 2) / (12 n)).
  EXPECT_NEAR(m.ate_rmse_m, std::sqrt((n + 2.0) / (12.0 * n)), 1e-9);
  EXPECT_NEAR(m.mean_abs_rot_error_deg.norm(), 0.0, 1e-12);
  // Each 10 m segment is 10.1 m long in the estimate: 1 % relative error.
  EXPECT_NEAR(*m.rpe_trans_percent, 1.0, 1e-9);
  EXPECT_EQ(m.rpe_segments, 91u);
}

TEST(TrajectoryEvaluationTest, ConstantYawErrorAfterTheStart) {
  // Estimate = truth with its rotation yawed by 2 deg from the second pose on:
  // log(q_est^-1 q_true) = (0, 0, -2 deg) on n - 1 of n poses.
  const std::vector<StampedPose> truth = Helix();
  std::vector<StampedPose> estimate = truth;
  const Eigen::Matrix3d Rz = Eigen::AngleAxisd(2.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (std::size_t k = 1; k < estimate.size(); ++k) estimate[k].T_map_body.linear() = truth[k].T_map_body.linear() * Rz;
  const TrajectoryMetrics m = EvaluateTrajectory(estimate, truth).metrics;
  const double n = static_cast<double>(truth.size());
  EXPECT_NEAR(m.mean_abs_rot_error_deg.z(), 2.0 * (n - 1.0) / n, 1e-9);
  EXPECT_NEAR(m.mean_abs_rot_error_deg.x(), 0.0, 1e-9);
  EXPECT_NEAR(m.mean_abs_rot_error_deg.y(), 0.0, 1e-9);
  EXPECT_NEAR(m.final_rot_error_deg, 2.0, 1e-9);
  EXPECT_NEAR(*m.rot_drift_deg_per_m, 2.0 / HelixLength(), 1e-9);
  EXPECT_NEAR(m.ate_rmse_m, 0.0, kTol);  // positions untouched
  EXPECT_NEAR(*m.drift_percent, 0.0, kTol);
}

TEST(TrajectoryEvaluationTest, PathLengthFollowsTheTruthBetweenSparseEstimates) {
  // Truth: L shape (0,0) -> (10,0) -> (10,10) at 1 m/s sampled at 1 Hz.
  std::vector<StampedPose> truth;
  for (int k = 0; k <= 20; ++k) {
    truth.push_back(MakePose(k, k <= 10 ? Eigen::Vector3d(k, 0, 0) : Eigen::Vector3d(10, k - 10, 0)));
  }
  EvaluationOptions options;
  options.association.max_time_diff_s = 1.0;
  const std::vector<StampedPose> estimate = {MakePose(0.5, {0.5, 0, 0}), MakePose(19.5, {10, 9.5, 0})};
  const TrajectoryMetrics m = EvaluateTrajectory(estimate, truth, options).metrics;
  EXPECT_NEAR(m.path_length_m, 19.0, 1e-12);  // along the L, not the 13.4 m chord
  EXPECT_NEAR(m.duration_s, 19.0, 1e-12);
}

TEST(TrajectoryEvaluationTest, CountsSkippedPoses) {
  const std::vector<StampedPose> truth = StraightLine(50);
  std::vector<StampedPose> estimate;
  for (int k = -5; k <= 55; ++k) estimate.push_back(MakePose(k, Eigen::Vector3d(k, 0, 0)));
  const TrajectoryMetrics m = EvaluateTrajectory(estimate, truth).metrics;
  EXPECT_EQ(m.poses_associated, 51u);
  EXPECT_EQ(m.poses_skipped, 10u);
  EXPECT_EQ(m.poses_outside_truth_span, 10u);
}

TEST(TrajectoryEvaluationTest, NoOverlapIsAnErrorNotZeros) {
  const std::vector<StampedPose> truth = StraightLine(10);
  std::vector<StampedPose> estimate;
  for (int k = 0; k < 10; ++k) estimate.push_back(MakePose(100.0 + k, Eigen::Vector3d::Zero()));
  try {
    EvaluateTrajectory(estimate, truth);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("do not overlap"), std::string::npos) << e.what();
  }
  // One overlapping pose is not enough either; nor is an empty truth.
  estimate.front().time_s = 10.0;
  EXPECT_THROW(EvaluateTrajectory(estimate, truth), InputError);
  EXPECT_THROW(EvaluateTrajectory(truth, {}), InputError);
}

TEST(TrajectoryEvaluationTest, ShortPathHasNoRpeAndStationaryPathNoDrift) {
  const TrajectoryMetrics short_path = EvaluateTrajectory(StraightLine(5), StraightLine(5)).metrics;
  EXPECT_EQ(short_path.rpe_segments, 0u);
  EXPECT_FALSE(short_path.rpe_trans_percent.has_value());
  std::vector<StampedPose> still;
  for (int k = 0; k < 5; ++k) still.push_back(MakePose(k, Eigen::Vector3d(1, 2, 3)));
  const TrajectoryMetrics m = EvaluateTrajectory(still, still).metrics;
  EXPECT_EQ(m.path_length_m, 0.0);
  EXPECT_FALSE(m.drift_percent.has_value());
  EXPECT_FALSE(m.rot_drift_deg_per_m.has_value());
  EXPECT_FALSE(m.trajectory_scale.has_value());
}

TEST(TrajectoryEvaluationTest, AnEstimateThatTravelsLessHasItsScale) {
  // The helix shrunk to 97 % about a point and moved: the rigid ATE sees the
  // shrinkage, trajectory_scale measures it.
  std::vector<StampedPose> estimate = Helix();
  for (StampedPose& p : estimate) {
    p.T_map_body.translation() =
        0.97 * (p.T_map_body.translation() - Eigen::Vector3d(3, 1, 0)) + Eigen::Vector3d(5, -2, 1);
  }
  const TrajectoryMetrics m = EvaluateTrajectory(estimate, Helix()).metrics;
  ASSERT_TRUE(m.trajectory_scale.has_value());
  EXPECT_NEAR(*m.trajectory_scale, 0.97, 1e-9);
  EXPECT_GT(m.ate_rmse_m, 0.1);
  const TrajectoryMetrics same = EvaluateTrajectory(Helix(), Helix()).metrics;
  ASSERT_TRUE(same.trajectory_scale.has_value());
  EXPECT_NEAR(*same.trajectory_scale, 1.0, 1e-12);
}

}  // namespace
}  // namespace unimap::eval
