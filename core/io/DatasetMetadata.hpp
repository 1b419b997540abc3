#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "unimap/ParameterMap.hpp"

namespace unimap::io {

// metadata.yaml of a dataset folder (docs/dataset-format.md). Read and
// written only by LoadDatasetMetadata / SaveDatasetMetadata.
struct DatasetMetadata {
  int format_version = 1;                    // layout version of the folder; readers refuse newer ones
  std::string source;                        // who wrote it: "unimap simulate", "kitti", "carmen", "rosbag", ...
  std::string payload;                       // payload plugin name the scans are for ("rotating_2d")
  std::string scenario;                      // simulated scenario name, empty for real data
  std::uint64_t seed = 0;                    // random seed of a simulation
  double duration_s = 0.0;                   // time span of the data
  double imu_rate_hz = 0.0;                  // 0: no IMU stream
  double encoder_rate_hz = 0.0;              // 0: no encoder stream
  double scan_rate_hz = 0.0;                 // nominal scans per second
  double gravity_m_s2 = 9.80665;             // magnitude of gravity in the world frame (along -z)
  double sigma_accel_m_s2 = 0.0;             // accelerometer white noise per sample used (simulation)
  double sigma_gyro_rad_s = 0.0;             // gyroscope white noise per sample used (simulation)
  double accel_bias_walk_m_s2_sqrt_s = 0.0;  // accelerometer bias random walk (m/s^2 per sqrt(s))
  double gyro_bias_walk_rad_s_sqrt_s = 0.0;  // gyroscope bias random walk (rad/s per sqrt(s))
  double range_noise_m = 0.0;                // LiDAR range noise sigma used (simulation)
  double encoder_resolution_rad = 0.0;       // encoder quantisation step used (simulation), 0 = none
  ParameterMap payload_parameters;           // the payload's effective parameters the data was made with
  std::vector<double> camera_from_lidar;     // KITTI: Tr = T_cam_lidar, 3x4 row-major (12 values); empty: none
};

// Reads DIR/metadata.yaml; throws ConfigError naming the file, line and key
// (unreadable file, YAML syntax, unknown or duplicate key, wrong type,
// missing format_version or payload, format_version newer than 1 -- checked
// before anything else). Omitted optional keys keep the struct's defaults.
DatasetMetadata LoadDatasetMetadata(const std::filesystem::path& file);
// Writes metadata atomically ("<file>.partial" + rename); every double reads
// back bit-exactly and every parameter keeps its type. Throws InputError on
// I/O failure, ConfigError for format_version != 1 or a payload parameter
// key nested YAML cannot hold (an empty dotted part, or a key that is also
// the group of another: "a" and "a.b").
void SaveDatasetMetadata(const DatasetMetadata& metadata, const std::filesystem::path& file);

}  // namespace unimap::io
