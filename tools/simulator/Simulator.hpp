#pragma once
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "Scenario.hpp"
#include "unimap/Platform.hpp"

namespace unimap::sim {

// How to run a scenario.
struct SimulationOptions {
  std::filesystem::path out_dir;                  // dataset folder (created if needed)
  std::optional<std::uint64_t> seed;              // replaces the scenario's seed
  std::optional<std::string> payload;             // platform file or plugin name, replaces the scenario's
  std::optional<double> duration_s;               // stop after this much data (<= the trajectory's duration)
  std::function<void(double fraction)> progress;  // called now and then with the fraction done
  const std::atomic<bool>* stop = nullptr;        // when set (e.g. by a signal): end the data at the last scan
                                                  // written and finish the dataset
};

// What a run produced.
struct SimulationSummary {
  std::string scenario;               // scenario name
  std::string payload;                // payload plugin name
  std::string payload_source;         // the platform file or plugin name used
  std::string world;                  // DescribeWorld() of the scenario's world
  std::uint64_t seed = 0;             // the seed used
  double duration_s = 0.0;            // data time span
  double path_length_m = 0.0;         // distance travelled by the body
  double max_speed_m_s = 0.0;         // highest body speed
  std::uint64_t imu_samples = 0;      // also ground-truth poses
  std::uint64_t encoder_samples = 0;  // 0 without a motor
  std::uint64_t scans = 0;            // records written
  std::uint64_t empty_scans = 0;      // 3D sweeps with no return, not written
  std::uint64_t rays = 0;             // beams fired
  std::uint64_t returns = 0;          // beams that measured a range
  double wall_s = 0.0;                // wall-clock seconds taken
  double cpu_s = 0.0;                 // process CPU seconds taken
  std::uintmax_t bytes = 0;           // size of the dataset folder's files
  bool interrupted = false;           // stopped early by SimulationOptions::stop
};

// Runs a scenario with a payload and writes the dataset (docs/simulation.md):
// the DatasetWriter streams (imu, encoder, scans, groundtruth.tum at the IMU
// rate, metadata.yaml) plus world.yaml (the scenario's `world:` list, for
// WorldLoader) and scenario.yaml (the scenario file as read).
//
// Streams share one clock starting at 0: IMU sample k at k / imu_rate,
// encoder sample k at k / encoder_rate, scan k starting at k * scan period;
// a scan is written only when its last firing is covered by the data (and by
// an encoder sample, for motor payloads). The LiDAR geometry is the payload
// plugin's own model, fed an error-free encoder track:
//   T_world_lidar(t) = T_world_body(t) * plugin.BodyFromLidarAt(true_encoder, t),
// so the recorded (quantised) encoder is the only difference from what the
// mapper assumes.
class Simulator {
 public:
  Simulator(Scenario scenario, SimulationOptions options);
  // Throws ConfigError (scenario, payload, world), PluginError, InputError (I/O).
  SimulationSummary Run();

  // A platform from a payload argument: a YAML file (a path, or a name ending
  // in .yaml/.yml) or a plugin name, meaning the plugin's defaults.
  static Platform LoadPayload(const std::string& name_or_file);

 private:
  Scenario scenario_;
  SimulationOptions options_;
};

}  // namespace unimap::sim
