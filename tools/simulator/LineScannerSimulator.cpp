#include "LineScannerSimulator.hpp"

#include <cmath>
#include <stdexcept>

#include "unimap/LineScan.hpp"

namespace unimap::sim {
namespace {
constexpr double kDegToRad = M_PI / 180.0;
}  // namespace

LineScannerPattern LineScannerPattern::FromParameters(const ParameterMap& parameters) {
  LineScannerPattern p;
  p.scan_rate_hz = parameters.GetDouble("lidar.scan_rate_hz");
  p.fov_deg = parameters.GetDouble("lidar.fov_deg");
  p.beams = static_cast<int>(parameters.GetInt("lidar.beams"));
  p.min_range_m = parameters.GetDouble("lidar.min_range_m");
  p.max_range_m = parameters.GetDouble("lidar.max_range_m");
  return p;
}

LineScannerSimulator::LineScannerSimulator(const World& world, LidarPoseTrack poses, const LineScannerPattern& pattern,
                                           LidarNoise noise, std::uint64_t seed)
    : LidarSimulator(world, std::move(poses), noise, seed), pattern_(pattern) {
  if (!(pattern_.scan_rate_hz > 0.0 && std::isfinite(pattern_.scan_rate_hz))) {
    throw std::invalid_argument("line scanner rate must be positive");
  }
  if (!(pattern_.fov_deg > 0.0 && pattern_.fov_deg <= 360.0)) {
    throw std::invalid_argument("line scanner field of view must be in (0, 360] deg");
  }
  if (pattern_.beams < 2) throw std::invalid_argument("line scanner needs at least 2 beams");
  if (!(pattern_.min_range_m >= 0.0 && pattern_.max_range_m > pattern_.min_range_m &&
        std::isfinite(pattern_.max_range_m))) {
    throw std::invalid_argument("line scanner range limits must satisfy 0 <= min < max");
  }
  angle_min_rad_ = -0.5 * pattern_.fov_deg * kDegToRad;
  angle_step_rad_ = pattern_.fov_deg * kDegToRad / static_cast<double>(pattern_.beams - 1);
  // The mirror turns 2 pi per line: a beam step of angle_step takes angle_step / (2 pi rate).
  beam_interval_s_ = angle_step_rad_ / (2.0 * M_PI * pattern_.scan_rate_hz);
  directions_lidar_.reserve(static_cast<std::size_t>(pattern_.beams));
  for (int i = 0; i < pattern_.beams; ++i) {
    const double a = angle_min_rad_ + static_cast<double>(i) * angle_step_rad_;
    directions_lidar_.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
}

double LineScannerSimulator::scan_period_s() const { return 1.0 / pattern_.scan_rate_hz; }

double LineScannerSimulator::scan_span_s() const { return static_cast<double>(pattern_.beams - 1) * beam_interval_s_; }

io::ScanRecord LineScannerSimulator::Simulate(double start_time_s) {
  LineScan line;
  line.start_time_s = start_time_s;
  line.angle_min_rad = angle_min_rad_;
  line.angle_increment_rad = angle_step_rad_;
  line.time_increment_s = beam_interval_s_;
  line.range_min_m = pattern_.min_range_m;
  line.range_max_m = pattern_.max_range_m;
  line.ranges_m.resize(directions_lidar_.size());
  poses().Prepare(start_time_s, start_time_s + scan_span_s());
  Eigen::Quaterniond q_world_lidar;
  Eigen::Vector3d p_world_lidar;
  float intensity = 0.0f;
  for (std::size_t i = 0; i < directions_lidar_.size(); ++i) {
    poses().At(start_time_s + static_cast<double>(i) * beam_interval_s_, &q_world_lidar, &p_world_lidar);
    const Eigen::Vector3d dir_world = q_world_lidar * directions_lidar_[i];
    line.ranges_m[i] =
        static_cast<float>(Fire(p_world_lidar, dir_world, pattern_.min_range_m, pattern_.max_range_m, &intensity));
  }
  return line;
}

}  // namespace unimap::sim
