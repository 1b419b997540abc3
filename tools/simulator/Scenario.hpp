#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "EncoderSimulator.hpp"
#include "ImuSimulator.hpp"
#include "LidarSimulator.hpp"
#include "WaypointTrajectory.hpp"

namespace unimap::sim {

// A simulation scenario (configs/scenarios/NAME.yaml, docs/simulation.md):
// the world, the body's trajectory, the default payload and the sensor
// errors. The payload's own geometry and rates come from its platform file.
struct Scenario {
  std::string file;                      // where it was read from (label in errors)
  std::string name;                      // `name:`, e.g. "tunnel"
  std::string description;               // `description:`, one line
  std::string payload;                   // default payload: platform file (resolved against the
                                         // scenario's folder) or plugin name (its defaults)
  std::uint64_t seed = 1;                // random seed of every noise source
  ImuConfig imu;                         // `imu:` rate, gravity and error model
  double encoder_rate_hz = 100.0;        // `encoder.rate_hz`
  double encoder_resolution_rad = 0.0;   // 2 pi / `encoder.counts_per_revolution` (0: not quantised)
  LidarNoise lidar_noise;                // `lidar.range_noise_m`, `lidar.dropout_probability`
  double azimuth_resolution_deg = 0.4;   // `lidar.azimuth_resolution_deg` (spinning LiDARs)
  double pose_knot_interval_s = 1e-3;    // `lidar.pose_knot_interval_s` (LidarPoseTrack)
  std::vector<Waypoint> waypoints;       // `trajectory.waypoints`
  WaypointTrajectoryOptions trajectory;  // `trajectory.*` limits, static start and wobble
  YAML::Node world;                      // the `world:` list of primitives (WorldLoader)
  std::string world_file;                // label used for world errors (= file)
  std::string text;                      // the scenario file's text, as read

  // The trajectory through the waypoints; throws ConfigError naming the
  // file and `trajectory` when the waypoints or limits are invalid.
  WaypointTrajectory MakeTrajectory() const;
};

// Reads a scenario file; throws ConfigError (file, line, key, reason) for
// YAML syntax, unknown or missing keys, wrong types and out-of-range values.
Scenario LoadScenario(const std::filesystem::path& file);
// The same from text; relative payload paths resolve against base_dir.
Scenario ParseScenario(const std::string& yaml_text, const std::string& file_label,
                       const std::filesystem::path& base_dir);

}  // namespace unimap::sim
