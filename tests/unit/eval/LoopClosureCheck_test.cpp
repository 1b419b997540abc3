#include "eval/LoopClosureCheck.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "EvalFixtures.hpp"

namespace unimap::eval {
namespace {

using testing::MakePose;

// Truth at 10 Hz over [0, 20] s: x = 0.5 t, yaw = 0.2 t (linear position and
// constant-rate yaw: interpolation is exact at any time).
std::vector<StampedPose> Truth() {
  std::vector<StampedPose> truth;
  for (int k = 0; k <= 200; ++k) {
    const double t = 0.1 * k;
    truth.push_back(MakePose(t, Eigen::Vector3d(0.5 * t, 1.0, 2.0), 0.0, 0.0, 0.2 * t));
  }
  return truth;
}

// The true motion between two times (analytic).
Eigen::Isometry3d TrueMotion(double t0, double t1) {
  const Eigen::Isometry3d a = MakePose(t0, Eigen::Vector3d(0.5 * t0, 1.0, 2.0), 0.0, 0.0, 0.2 * t0).T_map_body;
  const Eigen::Isometry3d b = MakePose(t1, Eigen::Vector3d(0.5 * t1, 1.0, 2.0), 0.0, 0.0, 0.2 * t1).T_map_body;
  return a.inverse() * b;
}

TEST(LoopClosureCheck, TrueClaimsBetweenSamplesAreNotFalse) {
  const std::vector<ClaimedMotion> claims = {{1.25, 17.05, TrueMotion(1.25, 17.05)},
                                             {0.0, 20.0, TrueMotion(0.0, 20.0)}};
  const LoopClosureCheck check = CheckLoopClosures(claims, Truth());
  EXPECT_EQ(check.checked, 2u);
  EXPECT_EQ(check.false_closures, 0u);
  EXPECT_LT(check.max_translation_error_m, 1e-9);
  EXPECT_LT(check.max_rotation_error_deg, 1e-6);
}

TEST(LoopClosureCheck, ClaimsOffByMoreThanTheLimitsAreFalse) {
  Eigen::Isometry3d shifted = TrueMotion(2.0, 15.0);
  shifted.translation() += Eigen::Vector3d(0.0, 0.0, 1.5);  // 1.5 m > 1 m
  Eigen::Isometry3d turned = TrueMotion(3.0, 16.0);
  turned.linear() = turned.linear() * Eigen::AngleAxisd(10.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ()).matrix();
  Eigen::Isometry3d close = TrueMotion(4.0, 18.0);
  close.translation() += Eigen::Vector3d(0.3, 0.0, 0.0);  // within the limit
  const LoopClosureCheck check =
      CheckLoopClosures({{2.0, 15.0, shifted}, {3.0, 16.0, turned}, {4.0, 18.0, close}}, Truth());
  EXPECT_EQ(check.checked, 3u);
  EXPECT_EQ(check.false_closures, 2u);
  EXPECT_NEAR(check.max_translation_error_m, 1.5, 1e-9);
  EXPECT_NEAR(check.max_rotation_error_deg, 10.0, 1e-6);
  ASSERT_EQ(check.false_list.size(), 2u);
  EXPECT_DOUBLE_EQ(check.false_list[0].start_time_s, 2.0);
  EXPECT_DOUBLE_EQ(check.false_list[0].end_time_s, 15.0);
  // The claim's end is 1.5 m above the truth's, in the start body's frame.
  EXPECT_NEAR((check.false_list[0].translation_error_m - Eigen::Vector3d(0.0, 0.0, 1.5)).norm(), 0.0, 1e-9);
  EXPECT_NEAR(check.false_list[1].rotation_error_deg, 10.0, 1e-6);
}

TEST(LoopClosureCheck, ClaimsOutsideTheTruthAreNotChecked) {
  const LoopClosureCheck check = CheckLoopClosures(
      {{-1.0, 5.0, Eigen::Isometry3d::Identity()}, {5.0, 20.5, Eigen::Isometry3d::Identity()}}, Truth());
  EXPECT_EQ(check.checked, 0u);
  EXPECT_EQ(check.false_closures, 0u);
  EXPECT_EQ(CheckLoopClosures({{1.0, 2.0, TrueMotion(1.0, 2.0)}}, {}).checked, 0u);
}

}  // namespace
}  // namespace unimap::eval
