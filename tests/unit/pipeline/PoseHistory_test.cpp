#include "pipeline/PoseHistory.hpp"

#include <gtest/gtest.h>

namespace unimap::pipeline {
namespace {

Eigen::Isometry3d Pose(double x, double yaw) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(x, 2 * x, 0);
  T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return T;
}

TEST(PoseHistory, InterpolatesPositionAndRotation) {
  PoseHistory history(10.0);
  history.Add(1.0, Pose(0.0, 0.0));
  history.Add(2.0, Pose(1.0, 0.4));
  const Eigen::Isometry3d mid = history.At(1.25);
  EXPECT_TRUE(mid.translation().isApprox(Eigen::Vector3d(0.25, 0.5, 0), 1e-12));
  EXPECT_NEAR(Eigen::AngleAxisd(mid.linear()).angle(), 0.1, 1e-12);
  EXPECT_TRUE(history.At(0.5).isApprox(Pose(0.0, 0.0), 1e-12));  // before: first pose
  EXPECT_TRUE(history.At(3.0).isApprox(Pose(1.0, 0.4), 1e-12));  // after: last pose
}

TEST(PoseHistory, DropsOldPosesAndIgnoresStaleOnes) {
  PoseHistory history(1.0);
  for (int i = 0; i <= 50; ++i) history.Add(0.1 * i, Pose(0.1 * i, 0.0));
  EXPECT_NEAR(history.At(0.0).translation().x(), 4.0, 1e-9);  // kept back to 5.0 - 1.0 s
  EXPECT_NEAR(history.At(4.05).translation().x(), 4.05, 1e-9);
  history.Add(4.0, Pose(100.0, 0.0));  // older than the latest: ignored
  EXPECT_NEAR(history.At(4.0).translation().x(), 4.0, 1e-9);
  history.Add(5.0, Pose(7.0, 0.0));  // same time: replaced
  EXPECT_NEAR(history.At(5.0).translation().x(), 7.0, 1e-12);
}

}  // namespace
}  // namespace unimap::pipeline
