#include "eval/RelativePoseError.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "EvalFixtures.hpp"
#include "unimap/Errors.hpp"

namespace unimap::eval {
namespace {

using testing::StraightLine;

RelativePoseError Rpe(const std::vector<StampedPose>& estimate, const std::vector<StampedPose>& truth,
                      double segment_m) {
  const TrajectoryAssociation a = AssociateTrajectories(estimate, truth);
  return ComputeRelativePoseError(a, ComputeTrajectoryErrors(a), segment_m);
}

TEST(RelativePoseErrorTest, StepErrorAffectsOnlySegmentsSpanningIt) {
  // Truth x = k (k = 0..100); the estimate jumps by 0.5 m at k = 50. Segments
  // (i, i + 10) with 40 <= i <= 49 contain the jump: 0.5 m / 10 m = 5 %; the
  // other 81 of the 91 segments are exact.
  const std::vector<StampedPose> truth = StraightLine(100);
  std::vector<StampedPose> estimate = truth;
  for (std::size_t k = 50; k < estimate.size(); ++k) estimate[k].T_map_body.translation().x() += 0.5;
  const RelativePoseError rpe = Rpe(estimate, truth, 10.0);
  EXPECT_EQ(rpe.segments, 91u);
  ASSERT_TRUE(rpe.trans_percent.has_value());
  EXPECT_NEAR(*rpe.trans_percent, 10.0 * 5.0 / 91.0, 1e-12);
  EXPECT_NEAR(*rpe.rot_deg_per_m, 0.0, 1e-12);
}

TEST(RelativePoseErrorTest, RotationStepGivesKnownAngularError) {
  // The estimate's body turns 1 deg about z from k = 50 on (positions exact).
  // Segments with 40 <= i <= 49 (10 of 91): E = (Rz, 0), 1 deg over 10 m.
  // Segments with i >= 50 (41 of 91): both ends turned alike, so
  // E = (I, Rz^T (10, 0, 0) - (10, 0, 0)): no rotation, |E.t| = 10 m * 2 sin(0.5 deg).
  const std::vector<StampedPose> truth = StraightLine(100);
  std::vector<StampedPose> estimate = truth;
  const Eigen::Matrix3d Rz = Eigen::AngleAxisd(M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (std::size_t k = 50; k < estimate.size(); ++k) estimate[k].T_map_body.linear() = Rz;
  const RelativePoseError rpe = Rpe(estimate, truth, 10.0);
  EXPECT_NEAR(*rpe.rot_deg_per_m, 10.0 * (1.0 / 10.0) / 91.0, 1e-12);
  const double chord = 10.0 * 2.0 * std::sin(0.5 * M_PI / 180.0);
  EXPECT_NEAR(*rpe.trans_percent, 41.0 * (100.0 * chord / 10.0) / 91.0, 1e-9);
}

TEST(RelativePoseErrorTest, SegmentEndsAtFirstIndexReachingTheLength) {
  // Truth at 0.75 m spacing: a 10 m segment needs 14 steps (10.5 m) and is
  // divided by the travelled 10.5 m. Estimate scaled by 1.02: 2 % everywhere.
  std::vector<StampedPose> truth;
  std::vector<StampedPose> estimate;
  for (int k = 0; k <= 40; ++k) {
    truth.push_back(testing::MakePose(k, Eigen::Vector3d(0.75 * k, 0, 0)));
    estimate.push_back(testing::MakePose(k, Eigen::Vector3d(1.02 * 0.75 * k, 0, 0)));
  }
  const RelativePoseError rpe = Rpe(estimate, truth, 10.0);
  EXPECT_EQ(rpe.segments, 27u);  // starts 0..26 (26 + 14 = 40)
  EXPECT_NEAR(*rpe.trans_percent, 2.0, 1e-9);
}

TEST(RelativePoseErrorTest, PathShorterThanOneSegmentHasNoValue) {
  const RelativePoseError rpe = Rpe(StraightLine(9), StraightLine(9), 10.0);
  EXPECT_EQ(rpe.segments, 0u);
  EXPECT_FALSE(rpe.trans_percent.has_value());
  EXPECT_FALSE(rpe.rot_deg_per_m.has_value());
  EXPECT_EQ(Rpe(StraightLine(10), StraightLine(10), 10.0).segments, 1u);
}

TEST(RelativePoseErrorTest, RejectsNonPositiveSegment) {
  EXPECT_THROW(Rpe(StraightLine(10), StraightLine(10), 0.0), InputError);
}

}  // namespace
}  // namespace unimap::eval
