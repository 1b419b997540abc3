#include "estimation/WheelOdometryPrior.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace unimap::estimation {
namespace {

// Odometry on a 5 m circle at 1 m/s, 50 Hz.
OdometrySample Reading(double t) {
  OdometrySample s;
  s.time_s = t;
  const double th = t / 5.0;
  s.T_odom_body.linear() = Eigen::AngleAxisd(th, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  s.T_odom_body.translation() = Eigen::Vector3d(5.0 * std::sin(th), 5.0 * (1.0 - std::cos(th)), 0.0);
  return s;
}

WheelOdometryPrior Filled(const MotionPriorOptions& options) {
  WheelOdometryPrior prior(options);
  for (int k = 0; k <= 100; ++k) prior.AddOdometry(Reading(0.02 * k));
  return prior;
}

TEST(WheelOdometryPriorTest, IncrementBetweenReadingsIsExact) {
  const WheelOdometryPrior prior = Filled(MotionPriorOptions{});
  EXPECT_TRUE(prior.ReadyFor(2.0));
  EXPECT_FALSE(prior.ReadyFor(2.01));
  const MotionPrediction p = prior.Predict(0.4, 1.2);  // both on readings
  ASSERT_TRUE(p.ok) << p.reason;
  const Eigen::Isometry3d truth = Reading(0.4).T_odom_body.inverse() * Reading(1.2).T_odom_body;
  EXPECT_TRUE(p.T_prev_next.isApprox(truth, 1e-12));
}

TEST(WheelOdometryPriorTest, InterpolatesBetweenReadings) {
  const WheelOdometryPrior prior = Filled(MotionPriorOptions{});
  const MotionPrediction p = prior.Predict(0.41, 1.23);
  ASSERT_TRUE(p.ok);
  const Eigen::Isometry3d truth = Reading(0.41).T_odom_body.inverse() * Reading(1.23).T_odom_body;
  // Linear interpolation of a 5 m-radius arc over a 2 cm step: the chord is
  // off the arc by at most r (1 - cos(dth / 2)) = 5 * (1 - cos(0.002)) = 10 um.
  EXPECT_LT((p.T_prev_next.translation() - truth.translation()).norm(), 2e-5);
  EXPECT_TRUE(p.T_prev_next.linear().isApprox(truth.linear(), 1e-9));
}

TEST(WheelOdometryPriorTest, SigmaGrowsWithDistanceAndTurnAboveTheFloor) {
  MotionPriorOptions options;
  const WheelOdometryPrior prior = Filled(options);
  const MotionPrediction still = prior.Predict(1.0, 1.0);
  ASSERT_TRUE(still.ok);
  EXPECT_NEAR(std::sqrt(still.covariance(0, 0)), options.odometry_min_sigma_m, 1e-12);
  EXPECT_NEAR(std::sqrt(still.covariance(3, 3)), options.odometry_min_sigma_rad, 1e-12);
  const MotionPrediction moved = prior.Predict(0.0, 2.0);  // a 2 m arc turning 0.4 rad
  const double chord = 2.0 * 5.0 * std::sin(0.2);
  EXPECT_NEAR(std::sqrt(moved.covariance(0, 0)), options.odometry_sigma_per_m * chord, 1e-9);
  EXPECT_NEAR(std::sqrt(moved.covariance(5, 5)),
              options.odometry_sigma_rad_per_rad * 0.4 + options.odometry_sigma_rad_per_m * chord, 1e-9);
}

TEST(WheelOdometryPriorTest, GapsAndBadReadingsGiveNoPrediction) {
  MotionPriorOptions options;
  options.max_odometry_gap_s = 0.1;
  WheelOdometryPrior prior(options);
  prior.AddOdometry(Reading(0.0));
  prior.AddOdometry(Reading(0.05));
  prior.AddOdometry(Reading(0.5));  // a 0.45 s gap
  prior.AddOdometry(Reading(0.4));  // backwards: skipped
  OdometrySample nan = Reading(0.6);
  nan.T_odom_body.translation().x() = std::nan("");
  prior.AddOdometry(nan);  // not finite: skipped
  EXPECT_EQ(prior.rejected(), 2u);
  EXPECT_TRUE(prior.Predict(0.0, 0.05).ok);
  const MotionPrediction gap = prior.Predict(0.0, 0.3);
  EXPECT_FALSE(gap.ok);
  EXPECT_NE(gap.reason.find("no wheel odometry"), std::string::npos) << gap.reason;
  EXPECT_FALSE(prior.Predict(0.05, 0.02).ok);  // backwards interval
  // An interval starting before the first reading starts at it.
  EXPECT_TRUE(prior.Predict(-1.0, 0.05).T_prev_next.isApprox(Reading(0.05).T_odom_body, 1e-12));
}

}  // namespace
}  // namespace unimap::estimation
