// End to end: a small scenario simulated with each payload plugin, read back
// with DatasetReader, and every returned point checked against the world.
#include "Simulator.hpp"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "WorldLoader.hpp"
#include "io/DatasetReader.hpp"
#include "unimap/EncoderTrack.hpp"
#include "unimap/Errors.hpp"
#include "unimap/LineScan.hpp"

namespace unimap::sim {
namespace {

// Noise-free, unquantised: the data must be exactly consistent.
const char* kRoom = R"(name: room
payload: fixed_3d
seed: 5
imu: {rate_hz: 200}
encoder: {rate_hz: 100, counts_per_revolution: 0}
lidar: {azimuth_resolution_deg: 1.0}
trajectory:
  static_start_s: 0.5
  max_speed_m_s: 1.0
  max_acceleration_m_s2: 1.0
  max_yaw_rate_deg_s: 60
  wobble: {roll_deg: 2, pitch_deg: 2, roll_period_s: 1.5, pitch_period_s: 2.0, ramp_s: 0.5}
  waypoints:
    - {position: [-2, 0, 1.2], yaw_deg: 0}
    - {position: [1, 1, 1.6], yaw_deg: 60, dwell_s: 0.5}
world:
  - {type: box, center: [0, 0, 1.5], size: [12, 8, 4]}
  - {type: box, center: [3, -2, 1], size: [1, 1, 2]}
  - {type: cylinder, base: [-3, 2.5, -0.5], axis: [0, 0, 1], radius: 0.3, height: 3}
  - {type: sphere, center: [0, -3, 3], radius: 0.5}
)";

std::filesystem::path OutDir(const std::string& name) {
  return std::filesystem::path(::testing::TempDir()) / ("unimap_sim_" + name + "_" + std::to_string(getpid()));
}

// Ground-truth pose at t: linear translation, slerp rotation between samples.
Eigen::Isometry3d PoseAt(const std::vector<StampedPose>& poses, double t) {
  std::size_t i = 1;
  while (i + 1 < poses.size() && poses[i].time_s < t) ++i;
  const StampedPose& a = poses[i - 1];
  const StampedPose& b = poses[i];
  const double s = (t - a.time_s) / (b.time_s - a.time_s);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::Quaterniond(a.T_map_body.rotation())
                   .slerp(s, Eigen::Quaterniond(b.T_map_body.rotation()))
                   .toRotationMatrix();
  T.translation() = (1 - s) * a.T_map_body.translation() + s * b.T_map_body.translation();
  return T;
}

class SimulatorPayloadTest : public ::testing::TestWithParam<std::string> {};

TEST_P(SimulatorPayloadTest, DatasetIsConsistentWithTheWorldAndTheTruth) {
  const Scenario scenario = ParseScenario(kRoom, "room.yaml", ".");
  SimulationOptions options;
  options.out_dir = OutDir(GetParam());
  options.payload = GetParam();
  options.seed = 123;
  const SimulationSummary summary = Simulator(scenario, options).Run();
  const double duration = scenario.MakeTrajectory().end_time_s();
  EXPECT_EQ(summary.payload, GetParam());
  EXPECT_DOUBLE_EQ(summary.duration_s, duration);
  EXPECT_EQ(summary.imu_samples, static_cast<std::uint64_t>(std::floor(duration * 200)) + 1);
  EXPECT_GT(summary.scans, 0u);
  EXPECT_NEAR(summary.path_length_m, std::sqrt(9.0 + 1.0 + 0.16), 1e-9);

  io::DatasetReader reader(options.out_dir);
  const io::DatasetMetadata& meta = reader.metadata();
  EXPECT_EQ(meta.source, "unimap simulate");
  EXPECT_EQ(meta.payload, GetParam());
  EXPECT_EQ(meta.scenario, "room");
  EXPECT_EQ(meta.seed, 123u);
  EXPECT_DOUBLE_EQ(meta.imu_rate_hz, 200.0);
  const Platform platform = Simulator::LoadPayload(GetParam());
  EXPECT_EQ(meta.payload_parameters, platform.parameters);
  const PayloadPlugin& plugin = *platform.plugin.plugin;
  EXPECT_DOUBLE_EQ(meta.encoder_rate_hz, plugin.UsesEncoder() ? 100.0 : 0.0);

  std::vector<StampedPose> truth;
  while (auto pose = reader.NextGroundTruth()) truth.push_back(*pose);
  ASSERT_EQ(truth.size(), summary.imu_samples);
  std::uint64_t imu = 0;
  while (reader.NextImu()) ++imu;
  EXPECT_EQ(imu, summary.imu_samples);
  EncoderTrack encoder;
  while (auto sample = reader.NextEncoder()) encoder.Append(*sample);
  EXPECT_EQ(encoder.size(), summary.encoder_samples);

  // Every return, placed with the truth and the payload's own model fed the
  // recorded encoder, lies on a surface of the world.
  const World world = LoadWorld(YAML::LoadFile((options.out_dir / "world.yaml").string()), "world.yaml");
  EXPECT_EQ(world.size(), 4u);
  std::uint64_t scans = 0, points = 0;
  double worst = 0.0;
  while (auto record = reader.NextScan()) {
    ++scans;
    const RawScan raw = std::holds_alternative<LineScan>(*record) ? LineScanToRawScan(std::get<LineScan>(*record)).scan
                                                                  : std::get<RawScan>(*record);
    for (const Point& p : raw.points) {
      const Eigen::Vector3d p_world =
          PoseAt(truth, p.time_s) * plugin.BodyFromLidarAt(encoder, p.time_s) * p.position_m;
      worst = std::max(worst, world.SurfaceDistance(p_world));
      ++points;
    }
  }
  EXPECT_EQ(scans, summary.scans);
  EXPECT_EQ(points, summary.returns);
  EXPECT_LT(worst, 1e-4);  // ground-truth interpolation between 5 ms samples: ~3e-5 m
  std::ifstream copy(options.out_dir / "scenario.yaml");
  std::stringstream text;
  text << copy.rdbuf();
  EXPECT_EQ(text.str(), kRoom);
  std::filesystem::remove_all(options.out_dir);
}

INSTANTIATE_TEST_SUITE_P(Payloads, SimulatorPayloadTest, ::testing::Values("rotating_2d", "rotating_3d", "fixed_3d"));

TEST(Simulator, DurationOptionTruncatesAndIsChecked) {
  const Scenario scenario = ParseScenario(kRoom, "room.yaml", ".");
  SimulationOptions options;
  options.out_dir = OutDir("short");
  options.payload = "rotating_2d";
  options.duration_s = 2.0;
  const SimulationSummary summary = Simulator(scenario, options).Run();
  EXPECT_DOUBLE_EQ(summary.duration_s, 2.0);
  EXPECT_EQ(summary.imu_samples, 401u);
  EXPECT_EQ(summary.encoder_samples, 201u);
  // Lines start every 25 ms and last 18.75 ms: those ending by 2 s.
  EXPECT_EQ(summary.scans, 80u);
  EXPECT_EQ(summary.seed, 5u);  // the scenario's
  std::filesystem::remove_all(options.out_dir);

  options.duration_s = 1e6;
  EXPECT_THROW(Simulator(scenario, options).Run(), ConfigError);
}

TEST(Simulator, UnknownPayloadIsAnError) {
  const Scenario scenario = ParseScenario(kRoom, "room.yaml", ".");
  SimulationOptions options;
  options.out_dir = OutDir("bad");
  options.payload = "no_such_payload";
  EXPECT_THROW(Simulator(scenario, options).Run(), Error);
  options.payload = "/nonexistent/platform.yaml";
  EXPECT_THROW(Simulator(scenario, options).Run(), ConfigError);
}

}  // namespace
}  // namespace unimap::sim
