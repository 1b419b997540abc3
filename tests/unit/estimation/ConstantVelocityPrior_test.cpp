#include "estimation/ConstantVelocityPrior.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace unimap::estimation {
namespace {

// A body moving at a constant body-frame twist: 1.2 m/s forward, 0.3 m/s up
// the body y axis, turning at 0.4 rad/s about z.
Eigen::Isometry3d PoseAt(double t) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  // Integrate the constant twist exactly in closed form for a planar turn
  // (rotation about z, body velocity in the x-y plane).
  const double w = 0.4, vx = 1.2, vy = 0.3;
  const double th = w * t;
  T.linear() = Eigen::AngleAxisd(th, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d((vx * std::sin(th) + vy * (std::cos(th) - 1.0)) / w,
                                    (vx * (1.0 - std::cos(th)) + vy * std::sin(th)) / w, 0.0);
  return T;
}

TEST(ConstantVelocityPriorTest, StandsStillWithTheFastestSpreadUntilTwoPosesAreKnown) {
  MotionPriorOptions options;
  ConstantVelocityPrior prior(options);
  MotionPrediction p = prior.Predict(0.0, 0.5);
  ASSERT_TRUE(p.ok);
  EXPECT_TRUE(p.T_prev_next.isApprox(Eigen::Isometry3d::Identity()));
  prior.Observe(0.0, PoseAt(0.0));
  p = prior.Predict(0.0, 0.5);
  EXPECT_TRUE(p.T_prev_next.isApprox(Eigen::Isometry3d::Identity()));
  // The velocity is unknown: sigma = max_speed_m_s * dt (a sensor may already move).
  EXPECT_NEAR(std::sqrt(p.covariance(0, 0)), options.max_speed_m_s * 0.5, 1e-12);
  EXPECT_NEAR(std::sqrt(p.covariance(5, 5)), options.max_rate_rad_s * 0.5, 1e-12);
  // Once it is known: sigma = velocity_sigma_m_s * dt.
  prior.Observe(0.5, PoseAt(0.5));
  p = prior.Predict(0.5, 1.0);
  EXPECT_NEAR(std::sqrt(p.covariance(0, 0)), options.velocity_sigma_m_s * 0.5, 1e-12);
  EXPECT_NEAR(std::sqrt(p.covariance(5, 5)), options.rate_sigma_rad_s * 0.5, 1e-12);
}

TEST(ConstantVelocityPriorTest, KeepsTheLastTwistOverShortSteps) {
  ConstantVelocityPrior prior(MotionPriorOptions{});
  const double dt = 0.025;
  prior.Observe(1.0, PoseAt(1.0));
  prior.Observe(1.0 + dt, PoseAt(1.0 + dt));
  const MotionPrediction p = prior.Predict(1.0 + dt, 1.0 + 2.0 * dt);
  ASSERT_TRUE(p.ok);
  const Eigen::Isometry3d truth = PoseAt(1.0 + dt).inverse() * PoseAt(1.0 + 2.0 * dt);
  // Under a constant body twist every step has the same increment, which the
  // prior repeats: exact.
  EXPECT_TRUE(p.T_prev_next.linear().isApprox(truth.linear(), 1e-9));
  EXPECT_LT((p.T_prev_next.translation() - truth.translation()).norm(), 1e-9);
  EXPECT_GT((p.T_prev_next.translation() - Eigen::Vector3d::Zero()).norm(), 0.02);  // it moved 3 cm
}

TEST(ConstantVelocityPriorTest, RejectsIntervalsBackwardsAndIgnoresRepeatedTimes) {
  ConstantVelocityPrior prior(MotionPriorOptions{});
  EXPECT_FALSE(prior.Predict(2.0, 1.0).ok);
  prior.Observe(1.0, PoseAt(1.0));
  prior.Observe(1.0, PoseAt(5.0));  // same time: no velocity from it
  EXPECT_TRUE(prior.Predict(1.0, 2.0).T_prev_next.isApprox(Eigen::Isometry3d::Identity()));
}

}  // namespace
}  // namespace unimap::estimation
