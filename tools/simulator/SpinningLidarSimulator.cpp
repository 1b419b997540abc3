#include "SpinningLidarSimulator.hpp"

#include <cmath>
#include <stdexcept>

#include "unimap/RawScan.hpp"

namespace unimap::sim {
namespace {
constexpr double kDegToRad = M_PI / 180.0;
}  // namespace

SpinningLidarPattern SpinningLidarPattern::FromParameters(const ParameterMap& parameters,
                                                          double azimuth_resolution_deg) {
  SpinningLidarPattern p;
  p.rings = static_cast<int>(parameters.GetInt("lidar.rings"));
  const std::vector<double> fov = parameters.GetVector("lidar.vertical_fov_deg", 2);
  p.vertical_fov_min_deg = fov[0];
  p.vertical_fov_max_deg = fov[1];
  p.spin_rate_hz = parameters.GetDouble("lidar.spin_rate_hz");
  p.clockwise = parameters.GetBool("lidar.clockwise");
  p.min_range_m = parameters.GetDouble("lidar.min_range_m");
  p.max_range_m = parameters.GetDouble("lidar.max_range_m");
  p.azimuth_resolution_deg = azimuth_resolution_deg;
  return p;
}

SpinningLidarSimulator::SpinningLidarSimulator(const World& world, LidarPoseTrack poses,
                                               const SpinningLidarPattern& pattern, LidarNoise noise,
                                               std::uint64_t seed)
    : LidarSimulator(world, std::move(poses), noise, seed), pattern_(pattern) {
  const auto& p = pattern_;
  if (p.rings < 1 || p.rings > 65535) throw std::invalid_argument("spinning LiDAR rings must be in [1, 65535]");
  if (!(p.vertical_fov_min_deg >= -90.0 && p.vertical_fov_min_deg <= p.vertical_fov_max_deg &&
        p.vertical_fov_max_deg <= 90.0)) {
    throw std::invalid_argument("spinning LiDAR vertical field of view must satisfy -90 <= min <= max <= 90");
  }
  if (!(p.spin_rate_hz > 0.0 && std::isfinite(p.spin_rate_hz))) {
    throw std::invalid_argument("spinning LiDAR spin rate must be positive");
  }
  if (!(p.azimuth_resolution_deg > 0.0 && p.azimuth_resolution_deg <= 90.0)) {
    throw std::invalid_argument("spinning LiDAR azimuth resolution must be in (0, 90] deg");
  }
  if (!(p.min_range_m >= 0.0 && p.max_range_m > p.min_range_m && std::isfinite(p.max_range_m))) {
    throw std::invalid_argument("spinning LiDAR range limits must satisfy 0 <= min < max");
  }
  firings_ = static_cast<std::size_t>(std::lround(360.0 / p.azimuth_resolution_deg));
  firing_interval_s_ = 1.0 / (static_cast<double>(firings_) * p.spin_rate_hz);
  const double sense = p.clockwise ? -1.0 : 1.0;
  const auto rings = static_cast<std::size_t>(p.rings);
  directions_lidar_.reserve(firings_ * rings);
  for (std::size_t j = 0; j < firings_; ++j) {
    const double azimuth = sense * 2.0 * M_PI * static_cast<double>(j) / static_cast<double>(firings_);
    for (std::size_t k = 0; k < rings; ++k) {
      const double elevation_deg =
          rings == 1
              ? 0.5 * (p.vertical_fov_min_deg + p.vertical_fov_max_deg)
              : p.vertical_fov_min_deg + static_cast<double>(k) * (p.vertical_fov_max_deg - p.vertical_fov_min_deg) /
                                             static_cast<double>(rings - 1);
      const double el = elevation_deg * kDegToRad;
      directions_lidar_.emplace_back(std::cos(el) * std::cos(azimuth), std::cos(el) * std::sin(azimuth), std::sin(el));
    }
  }
}

double SpinningLidarSimulator::scan_period_s() const { return 1.0 / pattern_.spin_rate_hz; }

double SpinningLidarSimulator::scan_span_s() const { return static_cast<double>(firings_ - 1) * firing_interval_s_; }

io::ScanRecord SpinningLidarSimulator::Simulate(double start_time_s) {
  RawScan scan;
  scan.start_time_s = start_time_s;
  scan.end_time_s = start_time_s + scan_span_s();
  scan.has_point_time = true;
  scan.points.reserve(directions_lidar_.size());
  poses().Prepare(scan.start_time_s, scan.end_time_s);
  const auto rings = static_cast<std::size_t>(pattern_.rings);
  Eigen::Quaterniond q_world_lidar;
  Eigen::Vector3d p_world_lidar;
  float intensity = 0.0f;
  for (std::size_t j = 0; j < firings_; ++j) {
    const double t = start_time_s + static_cast<double>(j) * firing_interval_s_;
    poses().At(t, &q_world_lidar, &p_world_lidar);
    const Eigen::Matrix3d R_world_lidar = q_world_lidar.toRotationMatrix();
    for (std::size_t k = 0; k < rings; ++k) {
      const Eigen::Vector3d& d_lidar = directions_lidar_[j * rings + k];
      const double range =
          Fire(p_world_lidar, R_world_lidar * d_lidar, pattern_.min_range_m, pattern_.max_range_m, &intensity);
      if (std::isnan(range)) continue;
      Point point;
      point.position_m = range * d_lidar;
      point.time_s = t;
      point.intensity = intensity;
      point.ring = static_cast<std::uint16_t>(k);
      scan.points.push_back(point);
    }
  }
  return scan;
}

}  // namespace unimap::sim
