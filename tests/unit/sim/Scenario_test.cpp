#include "Scenario.hpp"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "unimap/Errors.hpp"

namespace unimap::sim {
namespace {

const char* kValid = R"(name: tiny
description: a test
payload: ../platforms/rotating_hokuyo.yaml
seed: 77
imu:
  rate_hz: 100
  accel_noise_m_s2: 0.03
  gyro_bias_rad_s: [0.1, 0.2, 0.3]
encoder: {rate_hz: 50, counts_per_revolution: 4096}
lidar: {range_noise_m: 0.02, dropout_probability: 0.1, azimuth_resolution_deg: 0.8}
trajectory:
  max_speed_m_s: 0.5
  max_yaw_rate_deg_s: 20
  wobble: {roll_deg: 2}
  waypoints:
    - {position: [0, 0, 1], yaw_deg: 90, dwell_s: 1}
    - {position: [2, 0, 1]}
world:
  - {type: box, center: [0, 0, 1], size: [10, 10, 3]}
)";

// The ConfigError thrown by parsing text, or a failure.
ConfigError ParseError(const std::string& text) {
  try {
    ParseScenario(text, "s.yaml", "configs/scenarios");
  } catch (const ConfigError& e) {
    return e;
  }
  ADD_FAILURE() << "no ConfigError for:\n" << text;
  return ConfigError("", 0, "", "");
}

// kValid with one line replaced.
std::string With(const std::string& from, const std::string& to) {
  std::string text = kValid;
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(Scenario, ParsesEveryBlock) {
  const Scenario s = ParseScenario(kValid, "s.yaml", "configs/scenarios");
  EXPECT_EQ(s.name, "tiny");
  EXPECT_EQ(s.description, "a test");
  EXPECT_EQ(s.payload, "configs/platforms/rotating_hokuyo.yaml");  // resolved against the scenario's folder
  EXPECT_EQ(s.seed, 77u);
  EXPECT_DOUBLE_EQ(s.imu.rate_hz, 100.0);
  EXPECT_DOUBLE_EQ(s.imu.gravity_m_s2, 9.80665);  // default
  EXPECT_DOUBLE_EQ(s.imu.noise.accel_noise_m_s2, 0.03);
  EXPECT_DOUBLE_EQ(s.imu.noise.gyro_noise_rad_s, 0.0);  // default: none
  EXPECT_EQ(s.imu.noise.gyro_bias_rad_s, Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_DOUBLE_EQ(s.encoder_rate_hz, 50.0);
  EXPECT_DOUBLE_EQ(s.encoder_resolution_rad, 2 * M_PI / 4096);
  EXPECT_DOUBLE_EQ(s.lidar_noise.range_sigma_m, 0.02);
  EXPECT_DOUBLE_EQ(s.lidar_noise.dropout_probability, 0.1);
  EXPECT_DOUBLE_EQ(s.azimuth_resolution_deg, 0.8);
  EXPECT_DOUBLE_EQ(s.trajectory.static_start_s, 3.0);  // default
  EXPECT_DOUBLE_EQ(s.trajectory.max_speed_m_s, 0.5);
  EXPECT_NEAR(s.trajectory.max_yaw_rate_rad_s, 20 * M_PI / 180, 1e-15);
  EXPECT_NEAR(s.trajectory.wobble.roll_amplitude_rad, 2 * M_PI / 180, 1e-15);
  ASSERT_EQ(s.waypoints.size(), 2u);
  EXPECT_NEAR(s.waypoints[0].yaw_rad, M_PI / 2, 1e-15);
  EXPECT_DOUBLE_EQ(s.waypoints[0].dwell_s, 1.0);
  EXPECT_EQ(s.waypoints[1].position_m, Eigen::Vector3d(2, 0, 1));
  EXPECT_TRUE(s.world.IsSequence());
  EXPECT_EQ(s.world.size(), 1u);
  EXPECT_EQ(s.text, kValid);
  EXPECT_NEAR(s.MakeTrajectory().PathLength(1e9), 2.0, 1e-12);
}

TEST(Scenario, PluginNamePayloadIsKeptAsIs) {
  const Scenario s = ParseScenario(With("../platforms/rotating_hokuyo.yaml", "fixed_3d"), "s.yaml", "x");
  EXPECT_EQ(s.payload, "fixed_3d");
}

TEST(Scenario, ErrorsNameFileLineAndKey) {
  ConfigError e = ParseError(With("seed: 77", "seed: 77\nbogus: 1"));
  EXPECT_EQ(e.file(), "s.yaml");
  EXPECT_EQ(e.line(), 5);
  EXPECT_EQ(e.key(), "bogus");

  e = ParseError(With("rate_hz: 100", "rate_hz: fast"));
  EXPECT_EQ(e.key(), "imu.rate_hz");
  EXPECT_EQ(e.line(), 6);

  e = ParseError(With("max_speed_m_s: 0.5", "max_speed_m_s: -1"));
  EXPECT_EQ(e.key(), "trajectory.max_speed_m_s");

  e = ParseError(With("- {position: [2, 0, 1]}", "- {position: [2, 0]}"));
  EXPECT_EQ(e.key(), "trajectory.waypoints[1].position");
  EXPECT_EQ(e.line(), 17);

  e = ParseError(With("payload: ../platforms/rotating_hokuyo.yaml\n", ""));
  EXPECT_EQ(e.key(), "payload");

  e = ParseError(With("counts_per_revolution: 4096", "counts_per_revolution: 1"));
  EXPECT_EQ(e.key(), "encoder.counts_per_revolution");

  e = ParseError(With("dropout_probability: 0.1", "dropout_probability: 1.5"));
  EXPECT_EQ(e.key(), "lidar.dropout_probability");

  e = ParseError(With("seed: 77", "seed: -3"));
  EXPECT_EQ(e.key(), "seed");

  e = ParseError("name: [unclosed");
  EXPECT_EQ(e.file(), "s.yaml");
  EXPECT_GT(e.line(), 0);

  e = ParseError(With("world:\n  - {type: box, center: [0, 0, 1], size: [10, 10, 3]}\n", "world: 3\n"));
  EXPECT_EQ(e.key(), "world");
}

TEST(Scenario, MissingFileIsAConfigError) { EXPECT_THROW(LoadScenario("/nonexistent/scenario.yaml"), ConfigError); }

}  // namespace
}  // namespace unimap::sim
