#include "Simulator.hpp"

#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <memory>

#include "LineScannerSimulator.hpp"
#include "SpinningLidarSimulator.hpp"
#include "WorldLoader.hpp"
#include "io/DatasetWriter.hpp"
#include "unimap/EncoderTrack.hpp"
#include "unimap/Errors.hpp"

namespace unimap::sim {
namespace {

// An independent seed per noise source (SplitMix64 finaliser of seed + stream).
std::uint64_t StreamSeed(std::uint64_t seed, std::uint64_t stream) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (stream + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// The LiDAR pattern the payload's keys describe: "lidar.beams" (line
// scanner) or "lidar.rings" (spinning multi-beam).
std::unique_ptr<LidarSimulator> MakeLidar(const Platform& platform, const Scenario& scenario, const World& world,
                                          LidarPoseTrack poses, std::uint64_t seed) {
  const ParameterMap& p = platform.parameters;
  try {
    if (p.Contains("lidar.beams")) {
      return std::make_unique<LineScannerSimulator>(world, std::move(poses), LineScannerPattern::FromParameters(p),
                                                    scenario.lidar_noise, seed);
    }
    if (p.Contains("lidar.rings")) {
      return std::make_unique<SpinningLidarSimulator>(
          world, std::move(poses), SpinningLidarPattern::FromParameters(p, scenario.azimuth_resolution_deg),
          scenario.lidar_noise, seed);
    }
  } catch (const std::invalid_argument& e) {
    throw ConfigError(platform.file, 0, "lidar", e.what());
  }
  throw ConfigError(platform.file, 0, "lidar",
                    "the payload has neither lidar.beams (line scanner) nor lidar.rings (spinning multi-beam): "
                    "the simulator has no model for its LiDAR");
}

// Writes text to file through a temporary file and a rename.
void WriteAtomically(const std::filesystem::path& file, const std::string& text) {
  const std::filesystem::path partial = file.string() + ".partial";
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out.flush()) throw InputError(partial.string() + ": cannot write");
  }
  std::error_code ec;
  std::filesystem::rename(partial, file, ec);
  if (ec) throw InputError(file.string() + ": cannot rename into place: " + ec.message());
}

std::uintmax_t FolderBytes(const std::filesystem::path& folder) {
  std::uintmax_t bytes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.is_regular_file()) bytes += entry.file_size();
  }
  return bytes;
}

io::DatasetMetadata MakeMetadata(const Scenario& s, const Platform& platform, std::uint64_t seed,
                                 double encoder_rate_hz, double scan_rate_hz) {
  io::DatasetMetadata m;
  m.source = "unimap simulate";
  m.payload = platform.plugin.plugin->Name();
  m.scenario = s.name;
  m.seed = seed;
  m.imu_rate_hz = s.imu.rate_hz;
  m.encoder_rate_hz = encoder_rate_hz;
  m.scan_rate_hz = scan_rate_hz;
  m.gravity_m_s2 = s.imu.gravity_m_s2;
  m.sigma_accel_m_s2 = s.imu.noise.accel_noise_m_s2;
  m.sigma_gyro_rad_s = s.imu.noise.gyro_noise_rad_s;
  m.accel_bias_walk_m_s2_sqrt_s = s.imu.noise.accel_bias_walk_m_s2_sqrt_s;
  m.gyro_bias_walk_rad_s_sqrt_s = s.imu.noise.gyro_bias_walk_rad_s_sqrt_s;
  m.range_noise_m = s.lidar_noise.range_sigma_m;
  m.encoder_resolution_rad = encoder_rate_hz > 0.0 ? s.encoder_resolution_rad : 0.0;
  m.payload_parameters = platform.parameters;
  return m;
}

Eigen::Isometry3d PoseOf(const KinematicState& state) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = state.q_world_body.toRotationMatrix();
  T.translation() = state.position_m;
  return T;
}

}  // namespace

Simulator::Simulator(Scenario scenario, SimulationOptions options)
    : scenario_(std::move(scenario)), options_(std::move(options)) {}

Platform Simulator::LoadPayload(const std::string& name_or_file) {
  const std::filesystem::path path(name_or_file);
  const std::string ext = path.extension().string();
  if (ext == ".yaml" || ext == ".yml" || name_or_file.find('/') != std::string::npos) return LoadPlatform(path);
  return LoadPlatformFromString("plugin: " + name_or_file + "\n", "payload '" + name_or_file + "' (defaults)");
}

SimulationSummary Simulator::Run() {
  const auto wall_start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  const Scenario& s = scenario_;
  const std::string payload_source = options_.payload.value_or(s.payload);
  const Platform platform = LoadPayload(payload_source);
  const PayloadPlugin& plugin = *platform.plugin.plugin;
  const World world = LoadWorld(s.world, s.world_file);
  const WaypointTrajectory trajectory = s.MakeTrajectory();
  const std::uint64_t seed = options_.seed.value_or(s.seed);

  double duration = trajectory.end_time_s();
  if (options_.duration_s) {
    if (!(*options_.duration_s > 0.0 && *options_.duration_s <= duration)) {
      throw ConfigError(s.file, 0, "--duration-s",
                        "requested " + std::to_string(*options_.duration_s) + " s; must be in (0, " +
                            std::to_string(duration) + "] s, the trajectory's duration");
    }
    duration = *options_.duration_s;
  }

  // Motor encoder: the recorded one is quantised, the true track feeds the geometry.
  const bool uses_encoder = plugin.UsesEncoder();
  EncoderConfig encoder_config{s.encoder_rate_hz, s.encoder_resolution_rad, MotorMotion{}, 0.0};
  if (uses_encoder) {
    try {
      encoder_config.motion = MotorMotion::FromMap(platform.parameters);
    } catch (const ConfigError& e) {
      throw ConfigError(platform.file, 0, e.key(),
                        std::string("the payload uses a motor encoder; to simulate it: ") + e.reason());
    }
  }
  const EncoderSimulator encoder(encoder_config);
  EncoderTrack true_track;
  const MountQuery T_body_lidar_at = [&plugin, &true_track](double t) { return plugin.BodyFromLidarAt(true_track, t); };
  const MotionQuery T_world_body_at = [&trajectory](double t) { return PoseOf(trajectory.At(t)); };
  std::unique_ptr<LidarSimulator> lidar =
      MakeLidar(platform, s, world, LidarPoseTrack(T_world_body_at, T_body_lidar_at, s.pose_knot_interval_s),
                StreamSeed(seed, 1));
  ImuSimulator imu(s.imu, StreamSeed(seed, 0));

  const double encoder_rate = uses_encoder ? s.encoder_rate_hz : 0.0;
  io::DatasetWriter writer(options_.out_dir,
                           MakeMetadata(s, platform, seed, encoder_rate, 1.0 / lidar->scan_period_s()));
  SimulationSummary summary;
  std::size_t imu_k = 0, encoder_k = 0;
  // Every stream up to (and including) time t.
  auto advance_imu = [&](double t) {
    for (double ti = static_cast<double>(imu_k) / s.imu.rate_hz; ti <= t;
         ti = static_cast<double>(++imu_k) / s.imu.rate_hz) {
      const KinematicState state = trajectory.At(ti);
      writer.WriteImu(imu.Measure(state));
      writer.WriteGroundTruth(StampedPose{ti, PoseOf(state)});
    }
  };
  auto write_encoder_sample = [&]() {
    const double te = encoder.SampleTime(encoder_k++);
    true_track.Append(EncoderSample{te, encoder.TrueAngle(te)});
    writer.WriteEncoder(encoder.Measure(te));
  };
  // Scans must end within the data and, for a motor, at or before the last encoder sample.
  const double scan_limit =
      uses_encoder ? std::floor(duration * s.encoder_rate_hz + 1e-9) / s.encoder_rate_hz : duration;
  double next_report = 0.0;
  double last_end_s = 0.0;  // end of the last scan simulated
  for (std::size_t k = 0;; ++k) {
    const double start = static_cast<double>(k) * lidar->scan_period_s();
    const double end = start + lidar->scan_span_s();
    if (end > scan_limit) break;
    if (options_.stop != nullptr && options_.stop->load()) {
      // The data ends where the scans written so far end (the whole scan_limit else).
      summary.interrupted = true;
      duration = std::min(duration, last_end_s);
      break;
    }
    last_end_s = end;
    while (uses_encoder && (true_track.empty() || true_track.end_time_s() < end)) write_encoder_sample();
    advance_imu(end);
    true_track.DropBefore(start);
    const io::ScanRecord scan = lidar->Simulate(start);
    const auto* raw = std::get_if<RawScan>(&scan);
    if (raw != nullptr && raw->points.empty()) {
      ++summary.empty_scans;
    } else {
      writer.WriteScan(scan);
      ++summary.scans;
    }
    if (options_.progress && end >= next_report) {
      options_.progress(end / duration);
      next_report = end + 0.01 * duration;
    }
  }
  advance_imu(duration);
  while (uses_encoder && encoder.SampleTime(encoder_k) <= duration) write_encoder_sample();
  writer.Finish();
  if (options_.progress) options_.progress(1.0);

  WriteAtomically(options_.out_dir / "scenario.yaml", s.text);
  YAML::Emitter world_yaml;
  world_yaml << s.world;
  WriteAtomically(options_.out_dir / "world.yaml",
                  "# The world of scenario '" + s.name + "' (" + s.file +
                      "): the primitives list WorldLoader reads (docs/simulation.md).\n" + world_yaml.c_str() + "\n");

  summary.scenario = s.name;
  summary.payload = plugin.Name();
  summary.payload_source = payload_source;
  summary.world = DescribeWorld(world);
  summary.seed = seed;
  summary.duration_s = duration;
  summary.path_length_m = trajectory.PathLength(duration);
  summary.max_speed_m_s = trajectory.MaxSpeed(duration);
  summary.imu_samples = imu_k;
  summary.encoder_samples = encoder_k;
  summary.rays = lidar->rays();
  summary.returns = lidar->returns();
  summary.bytes = FolderBytes(options_.out_dir);
  summary.cpu_s = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  summary.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return summary;
}

}  // namespace unimap::sim
