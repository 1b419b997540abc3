#include "report/MetricLabels.hpp"

#include <array>
#include <map>
#include <utility>

namespace unimap::report {
namespace {

// Keys whose generic name would read badly.
const std::map<std::string, MetricLabel>& KnownLabels() {
  static const std::map<std::string, MetricLabel> labels = {
      {"ate_rmse_m", {"ATE RMSE (SE(3)-aligned)", "m"}},
      {"trajectory_scale", {"Trajectory scale (estimate / truth)", ""}},
      {"drift_percent", {"Translational drift", "%"}},
      {"max_abs_error_m", {"Max position error x / y / z", "m"}},
      {"mean_abs_rot_error_deg", {"Mean rotation error roll / pitch / yaw", "deg"}},
      {"rot_drift_deg_per_m", {"Rotational drift", "deg/m"}},
      {"rpe_trans_percent", {"RPE translation", "%"}},
      {"rpe_rot_deg_per_m", {"RPE rotation", "deg/m"}},
      {"rpe_segments", {"RPE segments", ""}},
      {"final_rot_error_deg", {"Final rotation error", "deg"}},
      {"max_time_diff_s", {"Association tolerance", "s"}},
      {"segment_m", {"RPE segment length", "m"}},
      {"map_error_mean_m", {"Map error, mean (unaligned)", "m"}},
      {"map_error_p95_m", {"Map error, 95th percentile (unaligned)", "m"}},
      {"map_error_max_m", {"Map error, max (unaligned)", "m"}},
      {"map_error_aligned_mean_m", {"Map error, mean (ATE-aligned)", "m"}},
      {"map_error_aligned_p95_m", {"Map error, 95th percentile (ATE-aligned)", "m"}},
      {"map_error_aligned_max_m", {"Map error, max (ATE-aligned)", "m"}},
      {"mean_plane_variance_m2", {"Mean plane variance (no ground truth)", "m²"}},
      {"mean_map_entropy", {"Mean map entropy (no ground truth)", "nats"}},
      {"planar_share", {"Map points on planes", ""}},
      {"map_plane_variance_m2", {"Mean plane variance (no ground truth)", "m²"}},
      {"map_mean_entropy", {"Mean map entropy (no ground truth)", "nats"}},
      {"map_planar_share", {"Map points on planes", ""}},
      {"realtime_factor", {"Real-time factor", "x"}},
      {"processing_s", {"Processing time", "s"}},
      {"data_duration_s", {"Data duration", "s"}},
      {"peak_rss_mb", {"Peak memory (RSS)", "MiB"}},
      {"gpf_threads", {"Particle-filter threads", ""}},
      {"motion", {"Motion model", ""}},
      {"motion_reason", {"Motion model chosen because", ""}},
      {"imu_samples", {"IMU samples", ""}},
      {"imu_gaps", {"IMU gaps", ""}},
      {"imu_out_of_order", {"IMU samples out of order", ""}},
      {"optimisations", {"Pose-graph optimisations", ""}},
      {"optimisation_failures", {"Failed optimisations", ""}},
      {"optimisation_s", {"Optimisation time", "s"}},
      {"key_scans", {"3D scans (key scans)", ""}},
      {"position_rmse_m", {"Position RMSE (unaligned)", "m"}},
      {"rotation_rmse_deg", {"Rotation RMSE (unaligned)", "deg"}},
      {"lost", {"Odometry lost (scans stopped matching the map)", ""}},
  };
  return labels;
}

// Unit suffixes, longest first so that "_deg_per_m" wins over "_m".
const std::array<std::pair<const char*, const char*>, 14>& Suffixes() {
  static const std::array<std::pair<const char*, const char*>, 14> suffixes = {{
      {"_deg_per_m", "deg/m"},
      {"_percent", "%"},
      {"_rad_s", "rad/s"},
      {"_m_s2", "m/s²"},
      {"_m_s", "m/s"},
      {"_deg", "deg"},
      {"_rad", "rad"},
      {"_mib", "MiB"},
      {"_rpm", "rpm"},
      {"_mb", "MiB"},
      {"_hz", "Hz"},
      {"_ms", "ms"},
      {"_m", "m"},
      {"_s", "s"},
  }};
  return suffixes;
}

bool EndsWith(const std::string& text, const std::string& suffix) {
  return text.size() > suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

MetricLabel LabelFor(const std::string& key) {
  const auto known = KnownLabels().find(key);
  if (known != KnownLabels().end()) return known->second;
  const std::size_t dot = key.rfind('.');
  if (dot != std::string::npos) {
    const auto last = KnownLabels().find(key.substr(dot + 1));
    if (last != KnownLabels().end()) return last->second;
  }
  MetricLabel result;
  std::string stem = key;
  for (const auto& [suffix, unit] : Suffixes()) {
    if (EndsWith(key, suffix)) {
      stem = key.substr(0, key.size() - std::string(suffix).size());
      result.unit = unit;
      break;
    }
  }
  for (char& c : stem) {
    if (c == '_' || c == '.') c = ' ';
  }
  if (!stem.empty() && stem[0] >= 'a' && stem[0] <= 'z') stem[0] = static_cast<char>(stem[0] - 'a' + 'A');
  result.label = stem;
  return result;
}

}  // namespace unimap::report
