#pragma once
#include <string>
#include <vector>

#include "unimap/Export.hpp"
#include "unimap/ParameterMap.hpp"
#include "unimap/ParameterSet.hpp"

namespace unimap {

// The paper's per-platform parameters (Table 1). Every payload plugin
// declares them, with defaults that suit its sensor.
struct UNIMAP_SDK_API CoreParameters {
  int scans_per_3d_scan = 1;               // N: scans accumulated into one 3D scan
  int scans_3d_per_submap = 20;            // M: 3D scans in the matching submap before it is switched
  int scans_3d_per_optimization = 10;      // I: 3D scans between pose-graph optimisations
  double sigma_accel_m_s2 = 0.02;          // sigma_a: accelerometer white noise per sample (m/s^2)
  double sigma_gyro_rad_s = 0.002;         // sigma_g: gyroscope white noise per sample (rad/s)
  double distance_map_resolution_m = 0.1;  // distance-map voxel edge (m)
  double distance_map_max_range_m = 20.0;  // half-size of the distance-map box around the sensor (m)

  // Adds the seven keys to a payload's set, with this object's values as defaults.
  void AddTo(ParameterSet* set) const;
  // Reads the seven keys from effective parameters; throws ConfigError.
  static CoreParameters FromMap(const ParameterMap& map);
  // The seven keys, in declaration order.
  static const std::vector<std::string>& Keys();
  // Values in range (counts >= 1, sigmas > 0, resolution < max range).
  bool IsValid(std::string* why) const;
};

}  // namespace unimap
