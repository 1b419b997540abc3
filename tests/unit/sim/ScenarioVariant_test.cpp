#include "ScenarioVariant.hpp"

#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "unimap/Errors.hpp"

namespace unimap::sim {
namespace {

const char* kScenario = R"(name: tiny
description: a test
payload: rotating_2d
imu:
  accel_noise_m_s2: 0.02
  gyro_noise_rad_s: 0.002
  accel_bias_walk_m_s2_sqrt_s: 0.0002
  gyro_bias_walk_rad_s_sqrt_s: 0.00002
  accel_bias_m_s2: [0.02, -0.05, 0.04]
  gyro_bias_rad_s: [-0.002, -0.001, 0.001]
trajectory:
  static_start_s: 3
  max_speed_m_s: 0.5
  max_acceleration_m_s2: 0.4
  max_yaw_rate_deg_s: 20
  waypoints:
    - {position: [0, 0, 1], dwell_s: 2}
    - {position: [10, 0, 1], dwell_s: 4}
    - {position: [10, 5, 1], yaw_deg: 90}
world:
  - {type: box, center: [0, 0, 1], size: [30, 30, 3]}
)";

Scenario Tiny() { return ParseScenario(kScenario, "tiny.yaml", "."); }

TEST(ScenarioVariant, NominalLeavesTheScenarioAsIs) {
  const Scenario a = Tiny();
  const Scenario b = ApplyVariant(Tiny(), ScenarioVariant{});
  EXPECT_EQ(b.text, a.text);
  EXPECT_EQ(b.MakeTrajectory().end_time_s(), a.MakeTrajectory().end_time_s());
  EXPECT_EQ(ScenarioVariant{}.Describe(), "nominal");
}

TEST(ScenarioVariant, TwiceTheSpeedCoversTheSamePathInHalfTheMovingTime) {
  ScenarioVariant fast;
  fast.speed_scale = 2.0;
  const WaypointTrajectory slow_trajectory = Tiny().MakeTrajectory();
  const WaypointTrajectory fast_trajectory = ApplyVariant(Tiny(), fast).MakeTrajectory();
  // Static start (3 s) and the first dwell (2 s) are kept; the rest is compressed by 2.
  const double kept_s = 3.0 + 2.0;
  EXPECT_NEAR(fast_trajectory.end_time_s() - kept_s, (slow_trajectory.end_time_s() - kept_s) / 2.0, 1e-9);
  EXPECT_NEAR(fast_trajectory.PathLength(fast_trajectory.end_time_s()),
              slow_trajectory.PathLength(slow_trajectory.end_time_s()), 1e-9);
  EXPECT_NEAR(fast_trajectory.MaxSpeed(fast_trajectory.end_time_s()),
              2.0 * slow_trajectory.MaxSpeed(slow_trajectory.end_time_s()), 1e-9);
  // The same place at corresponding times: arrival at waypoint 2.
  EXPECT_NEAR(fast_trajectory.ArrivalTime(2) - kept_s, (slow_trajectory.ArrivalTime(2) - kept_s) / 2.0, 1e-9);
  EXPECT_NE(ApplyVariant(Tiny(), fast).text.find("# variant: x2 speed"), std::string::npos);
}

TEST(ScenarioVariant, ImuScalesMultiplyNoiseBiasesAndWalks) {
  ScenarioVariant noisy;
  noisy.imu_noise_scale = 2.5;
  noisy.imu_bias_scale = 2.0;
  const ImuNoise a = Tiny().imu.noise;
  const ImuNoise b = ApplyVariant(Tiny(), noisy).imu.noise;
  EXPECT_DOUBLE_EQ(b.accel_noise_m_s2, 2.5 * a.accel_noise_m_s2);
  EXPECT_DOUBLE_EQ(b.gyro_noise_rad_s, 2.5 * a.gyro_noise_rad_s);
  EXPECT_TRUE(b.accel_bias_m_s2.isApprox(2.0 * a.accel_bias_m_s2));
  EXPECT_TRUE(b.gyro_bias_rad_s.isApprox(2.0 * a.gyro_bias_rad_s));
  EXPECT_DOUBLE_EQ(b.accel_bias_walk_m_s2_sqrt_s, 2.0 * a.accel_bias_walk_m_s2_sqrt_s);
  EXPECT_DOUBLE_EQ(b.gyro_bias_walk_rad_s_sqrt_s, 2.0 * a.gyro_bias_walk_rad_s_sqrt_s);
  EXPECT_EQ(noisy.Describe(), "x2.5 IMU noise, x2 IMU bias");
}

TEST(ScenarioVariant, NonPositiveOrNonFiniteScalesAreConfigErrorsNamingTheOption) {
  for (const double bad :
       {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    ScenarioVariant v;
    v.imu_noise_scale = bad;
    try {
      ApplyVariant(Tiny(), v);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find("--imu-noise-scale"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace unimap::sim
