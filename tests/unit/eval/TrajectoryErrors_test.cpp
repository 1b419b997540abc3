#include "eval/TrajectoryErrors.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "EvalFixtures.hpp"
#include "unimap/Errors.hpp"

namespace unimap::eval {
namespace {

using testing::MakePose;

TEST(TrajectoryErrorsTest, AnchorsTheEstimateOnTheTruthStart) {
  // Truth starts at (5, 0, 0) facing +y; the estimate starts at its own
  // origin facing +x and moves 1 m forward then 1 m left in its body frame,
  // while the truth moves the same plus 0.2 m extra forward at the end.
  TrajectoryAssociation a;
  const double yaw0 = M_PI / 2.0;
  a.pairs.push_back({0.0, MakePose(0, {0, 0, 0}).T_map_body, MakePose(0, {5, 0, 0}, 0, 0, yaw0).T_map_body});
  a.pairs.push_back({1.0, MakePose(1, {1, 0, 0}).T_map_body, MakePose(1, {5, 1, 0}, 0, 0, yaw0).T_map_body});
  a.pairs.push_back(
      {2.0, MakePose(2, {1, 1, 0}, 0, 0, 0.1).T_map_body, MakePose(2, {4, 1.2, 0}, 0, 0, yaw0).T_map_body});
  const TrajectoryErrors errors = ComputeTrajectoryErrors(a);
  ASSERT_EQ(errors.poses.size(), 3u);
  // Anchored estimate at k = 2: truth start (5, 0) + R(90 deg) (1, 1) = (4, 1).
  EXPECT_TRUE(errors.poses[2].p_anchored.isApprox(Eigen::Vector3d(4, 1, 0), 1e-12));
  EXPECT_NEAR((errors.poses[2].position_error_m - Eigen::Vector3d(0, -0.2, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(errors.poses[1].position_error_m.norm(), 0.0, 1e-12);
  // Estimate yawed 0.1 rad more than its start; truth did not turn:
  // log(q_est^-1 q_true) = (0, 0, -0.1).
  EXPECT_NEAR((errors.poses[2].rotation_error_rad - Eigen::Vector3d(0, 0, -0.1)).norm(), 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(errors.poses[1].distance_m, 1.0);
  EXPECT_NEAR(errors.poses[2].distance_m, 1.0 + std::hypot(1.0, 0.2), 1e-12);
}

TEST(TrajectoryErrorsTest, NeedsAtLeastOnePair) {
  EXPECT_THROW(ComputeTrajectoryErrors(TrajectoryAssociation{}), InputError);
}

}  // namespace
}  // namespace unimap::eval
