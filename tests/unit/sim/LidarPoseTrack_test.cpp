#include "LidarPoseTrack.hpp"

#include <stdexcept>

#include <gtest/gtest.h>

#include "SimTestSupport.hpp"

namespace unimap::sim {
namespace {

TEST(LidarPoseTrack, InterpolatedPosesMatchExactOnesWithinAMicrometre) {
  LidarPoseTrack track(
      test::MovingBody, [](double t) { return test::RotatingMount(t); }, 1e-3);
  const double start = 1.234, end = start + 0.01875;  // one Hokuyo line
  track.Prepare(start, end);
  Eigen::Quaterniond q;
  Eigen::Vector3d p;
  for (double t = start; t <= end; t += 1.7e-5) {
    track.At(t, &q, &p);
    const Eigen::Isometry3d exact = track.Exact(t);
    EXPECT_LT((p - exact.translation()).norm(), 1e-6) << t;
    EXPECT_LT(q.angularDistance(Eigen::Quaterniond(exact.rotation())), 1e-6) << t;
  }
  // Exact at the ends (knots).
  track.At(end, &q, &p);
  EXPECT_LT((p - track.Exact(end).translation()).norm(), 1e-12);
}

TEST(LidarPoseTrack, ZeroKnotIntervalIsExact) {
  LidarPoseTrack track(
      test::MovingBody, [](double t) { return test::RotatingMount(t); }, 0.0);
  track.Prepare(0.0, 0.1);
  Eigen::Quaterniond q;
  Eigen::Vector3d p;
  track.At(0.0377, &q, &p);
  const Eigen::Isometry3d expected = test::MovingBody(0.0377) * test::RotatingMount(0.0377);
  EXPECT_LT((p - expected.translation()).norm(), 1e-15);
  EXPECT_LT(q.angularDistance(Eigen::Quaterniond(expected.rotation())), 1e-12);
}

TEST(LidarPoseTrack, RejectsNegativeInterval) {
  EXPECT_THROW(LidarPoseTrack(test::MovingBody, test::MovingBody, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace unimap::sim
