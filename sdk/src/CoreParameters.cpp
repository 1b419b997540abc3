#include "unimap/CoreParameters.hpp"

#include "unimap/Errors.hpp"

namespace unimap {
namespace {

constexpr const char* kN = "scans_per_3d_scan";
constexpr const char* kM = "scans_3d_per_submap";
constexpr const char* kI = "scans_3d_per_optimization";
constexpr const char* kSigmaA = "sigma_accel_m_s2";
constexpr const char* kSigmaG = "sigma_gyro_rad_s";
constexpr const char* kResolution = "distance_map_resolution_m";
constexpr const char* kMaxRange = "distance_map_max_range_m";

int ReadCount(const ParameterMap& map, const char* key) {
  const std::int64_t value = map.GetInt(key);
  if (value < 1 || value > 100000) throw ConfigError("", 0, key, "must be in [1, 100000]");
  return static_cast<int>(value);
}

}  // namespace

void CoreParameters::AddTo(ParameterSet* set) const {
  set->Add({kN, "N", "scans accumulated into one 3D scan (count)", std::int64_t{scans_per_3d_scan}, 1, 100000, {}});
  set->Add({kM,
            "M",
            "3D scans inserted into the matching submap before the growing one takes over (count)",
            std::int64_t{scans_3d_per_submap},
            1,
            100000,
            {}});
  set->Add({kI,
            "I",
            "3D scans between pose-graph optimisations (count)",
            std::int64_t{scans_3d_per_optimization},
            1,
            100000,
            {}});
  set->Add({kSigmaA,
            "sigma_a",
            "accelerometer white noise, standard deviation per sample (m/s^2)",
            sigma_accel_m_s2,
            1e-6,
            10.0,
            {}});
  set->Add({kSigmaG,
            "sigma_g",
            "gyroscope white noise, standard deviation per sample (rad/s)",
            sigma_gyro_rad_s,
            1e-7,
            1.0,
            {}});
  set->Add({kResolution, "", "distance-map voxel edge (m)", distance_map_resolution_m, 0.01, 2.0, {}});
  set->Add(
      {kMaxRange, "", "distance-map box half-size around the sensor (m)", distance_map_max_range_m, 1.0, 500.0, {}});
}

CoreParameters CoreParameters::FromMap(const ParameterMap& map) {
  CoreParameters p;
  p.scans_per_3d_scan = ReadCount(map, kN);
  p.scans_3d_per_submap = ReadCount(map, kM);
  p.scans_3d_per_optimization = ReadCount(map, kI);
  p.sigma_accel_m_s2 = map.GetDouble(kSigmaA);
  p.sigma_gyro_rad_s = map.GetDouble(kSigmaG);
  p.distance_map_resolution_m = map.GetDouble(kResolution);
  p.distance_map_max_range_m = map.GetDouble(kMaxRange);
  std::string why;
  if (!p.IsValid(&why)) throw ConfigError("", 0, "", why);
  return p;
}

const std::vector<std::string>& CoreParameters::Keys() {
  static const std::vector<std::string> keys = {kN, kM, kI, kSigmaA, kSigmaG, kResolution, kMaxRange};
  return keys;
}

bool CoreParameters::IsValid(std::string* why) const {
  std::string local_why;
  if (why == nullptr) why = &local_why;
  if (scans_per_3d_scan < 1 || scans_3d_per_submap < 1 || scans_3d_per_optimization < 1) {
    *why = "N, M and I must be at least 1";
    return false;
  }
  if (!(sigma_accel_m_s2 > 0.0) || !(sigma_gyro_rad_s > 0.0)) {
    *why = "sigma_accel_m_s2 and sigma_gyro_rad_s must be positive";
    return false;
  }
  if (!(distance_map_resolution_m > 0.0) || !(distance_map_resolution_m * 4.0 <= distance_map_max_range_m)) {
    *why = "distance_map_resolution_m must be positive and at most a quarter of distance_map_max_range_m";
    return false;
  }
  return true;
}

}  // namespace unimap
