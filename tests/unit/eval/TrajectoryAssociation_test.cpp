#include "eval/TrajectoryAssociation.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "EvalFixtures.hpp"
#include "unimap/Errors.hpp"

namespace unimap::eval {
namespace {

using testing::MakePose;

constexpr double kSpeed = 0.7;    // m/s along x
constexpr double kYawRate = 0.1;  // rad/s

// Truth at 10 Hz over [0, 10] s: x = v t, yaw = w t. Linear position and
// constant-rate yaw make lerp / slerp exact.
std::vector<StampedPose> Truth10Hz() {
  std::vector<StampedPose> truth;
  for (int k = 0; k <= 100; ++k) {
    const double t = 0.1 * k;
    truth.push_back(MakePose(t, Eigen::Vector3d(kSpeed * t, 1.0, 2.0), 0.0, 0.0, kYawRate * t));
  }
  return truth;
}

double YawOf(const Eigen::Isometry3d& T) {
  const Eigen::Matrix3d R = T.linear();
  return std::atan2(R(1, 0), R(0, 0));
}

TEST(TrajectoryAssociationTest, InterpolatesBetweenTruthSamplesExactly) {
  std::vector<StampedPose> estimate;
  for (int k = 0; k < 100; ++k) estimate.push_back(MakePose(0.05 + 0.1 * k, Eigen::Vector3d::Zero()));
  const TrajectoryAssociation a = AssociateTrajectories(estimate, Truth10Hz());
  ASSERT_EQ(a.pairs.size(), 100u);
  EXPECT_EQ(a.skipped(), 0u);
  for (const AssociatedPose& pair : a.pairs) {
    EXPECT_NEAR(pair.T_true_body.translation().x(), kSpeed * pair.time_s, 1e-12);
    EXPECT_NEAR(pair.T_true_body.translation().y(), 1.0, 1e-12);
    EXPECT_NEAR(YawOf(pair.T_true_body), kYawRate * pair.time_s, 1e-12);
  }
}

TEST(TrajectoryAssociationTest, ExactHitUsesTheTruthSample) {
  const std::vector<StampedPose> truth = Truth10Hz();
  const TrajectoryAssociation a = AssociateTrajectories({truth[0], truth[37], truth[100]}, truth);
  ASSERT_EQ(a.pairs.size(), 3u);
  EXPECT_TRUE(a.pairs[1].T_true_body.isApprox(truth[37].T_map_body, 1e-15));
  EXPECT_TRUE(a.pairs[2].T_true_body.isApprox(truth[100].T_map_body, 1e-15));
}

TEST(TrajectoryAssociationTest, SkipsAndCountsPosesOutsideTheTruthSpan) {
  std::vector<StampedPose> estimate;
  // t = -1.95 .. 11.95 in 0.1 s steps: 20 before 0 s, 100 inside, 20 after 10 s.
  for (int k = 0; k < 140; ++k) estimate.push_back(MakePose(-1.95 + 0.1 * k, Eigen::Vector3d::Zero()));
  const TrajectoryAssociation a = AssociateTrajectories(estimate, Truth10Hz());
  EXPECT_EQ(a.pairs.size(), 100u);
  EXPECT_EQ(a.skipped_outside_span, 40u);
  EXPECT_EQ(a.skipped_in_gap, 0u);
  EXPECT_NEAR(a.pairs.front().time_s, 0.05, 1e-12);
  EXPECT_NEAR(a.pairs.back().time_s, 9.95, 1e-12);
}

TEST(TrajectoryAssociationTest, SkipsPosesInTruthGapsBeyondTheTolerance) {
  std::vector<StampedPose> truth;
  for (const StampedPose& p : Truth10Hz()) {
    if (p.time_s <= 4.01 || p.time_s >= 4.99) truth.push_back(p);  // a 1 s gap from 4 s to 5 s
  }
  std::vector<StampedPose> estimate;
  for (int k = 0; k < 100; ++k) estimate.push_back(MakePose(0.05 + 0.1 * k, Eigen::Vector3d::Zero()));
  const TrajectoryAssociation strict = AssociateTrajectories(estimate, truth);
  EXPECT_EQ(strict.pairs.size(), 90u);
  EXPECT_EQ(strict.skipped_in_gap, 10u);  // 4.05 .. 4.95 s
  EXPECT_EQ(strict.skipped_outside_span, 0u);

  AssociationOptions loose;
  loose.max_time_diff_s = 1.0;
  const TrajectoryAssociation a = AssociateTrajectories(estimate, truth, loose);
  EXPECT_EQ(a.pairs.size(), 100u);
  // Across the gap the truth is still interpolated exactly (linear motion).
  for (const AssociatedPose& pair : a.pairs) {
    EXPECT_NEAR(pair.T_true_body.translation().x(), kSpeed * pair.time_s, 1e-12);
  }
}

TEST(TrajectoryAssociationTest, TruthSpanHasInterpolatedEndsAndRawSamplesBetween) {
  const std::vector<StampedPose> truth = Truth10Hz();
  const TrajectoryAssociation a =
      AssociateTrajectories({MakePose(1.05, Eigen::Vector3d::Zero()), MakePose(2.05, Eigen::Vector3d::Zero())}, truth);
  ASSERT_EQ(a.truth_span.size(), 12u);  // 1.05, 1.1 .. 2.0 (10 samples), 2.05
  EXPECT_DOUBLE_EQ(a.truth_span.front().time_s, 1.05);
  EXPECT_NEAR(a.truth_span.front().T_map_body.translation().x(), kSpeed * 1.05, 1e-12);
  EXPECT_DOUBLE_EQ(a.truth_span[1].time_s, truth[11].time_s);
  EXPECT_DOUBLE_EQ(a.truth_span.back().time_s, 2.05);
}

TEST(TrajectoryAssociationTest, NoOverlapGivesNoPairsWithoutThrowing) {
  std::vector<StampedPose> estimate;
  for (int k = 0; k < 10; ++k) estimate.push_back(MakePose(20.0 + k, Eigen::Vector3d::Zero()));
  const TrajectoryAssociation a = AssociateTrajectories(estimate, Truth10Hz());
  EXPECT_TRUE(a.pairs.empty());
  EXPECT_EQ(a.skipped_outside_span, 10u);
  EXPECT_TRUE(AssociateTrajectories(estimate, {}).pairs.empty());
}

TEST(TrajectoryAssociationTest, RejectsTimeGoingBackwardsAndBadOptions) {
  std::vector<StampedPose> estimate = {MakePose(1.0, Eigen::Vector3d::Zero()), MakePose(2.0, Eigen::Vector3d::Zero()),
                                       MakePose(1.5, Eigen::Vector3d::Zero())};
  try {
    AssociateTrajectories(estimate, Truth10Hz());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("estimate pose 2"), std::string::npos) << e.what();
  }
  std::vector<StampedPose> truth = Truth10Hz();
  truth[5].time_s = std::nan("");
  EXPECT_THROW(AssociateTrajectories({}, truth), InputError);
  AssociationOptions bad;
  bad.max_time_diff_s = 0.0;
  EXPECT_THROW(AssociateTrajectories({}, Truth10Hz(), bad), InputError);
}

TEST(TrajectoryAssociationTest, InterpolatePoseSlerpsTheShorterArc) {
  const StampedPose a = MakePose(0.0, Eigen::Vector3d(0, 0, 0), 0.0, 0.0, 3.0);
  const StampedPose b = MakePose(1.0, Eigen::Vector3d(2, 4, 6), 0.0, 0.0, -3.0);  // 2 pi - 6 rad apart
  const Eigen::Isometry3d mid = InterpolatePose(a, b, 0.5);
  EXPECT_TRUE(mid.translation().isApprox(Eigen::Vector3d(1, 2, 3), 1e-15));
  EXPECT_NEAR(std::abs(YawOf(mid)), M_PI, 1e-12);  // through pi, not through 0
}

}  // namespace
}  // namespace unimap::eval
