#pragma once
#include <vector>

#include <Eigen/Core>

#include "LidarSimulator.hpp"
#include "unimap/ParameterMap.hpp"

namespace unimap::sim {

// A spinning multi-beam LiDAR's firing pattern (Velodyne VLP-16 class), as
// the payload keys "lidar.rings", "lidar.vertical_fov_deg",
// "lidar.spin_rate_hz", "lidar.clockwise", "lidar.min_range_m",
// "lidar.max_range_m" describe it, plus the simulated azimuth resolution.
struct SpinningLidarPattern {
  int rings = 16;                       // beams stacked vertically (>= 1)
  double vertical_fov_min_deg = -15.0;  // elevation of ring 0
  double vertical_fov_max_deg = 15.0;   // elevation of the last ring
  double spin_rate_hz = 10.0;           // head revolutions per second; one scan per revolution
  bool clockwise = true;                // seen from +z (azimuth decreases with time)
  double azimuth_resolution_deg = 0.4;  // azimuth between firings (simulation choice; VLP-16: 0.2)
  double min_range_m = 0.4;             // shorter returns are invalid
  double max_range_m = 100.0;           // longer returns are invalid

  // Reads the six payload keys; the azimuth resolution is given. Throws
  // ConfigError naming a missing or mistyped key.
  static SpinningLidarPattern FromParameters(const ParameterMap& parameters, double azimuth_resolution_deg);
};

// Simulates a spinning multi-beam LiDAR. Firing j of a revolution
// (j = 0 .. S-1, S = round(360 / azimuth_resolution)) fires every ring at
// once, at azimuth s * j * 2 pi / S (s = -1 clockwise, +1 otherwise; azimuth
// atan2(y, x) in the LiDAR frame) and time start + j / (S spin_rate); ring k
// is at elevation min + k (max - min) / (rings - 1) (the mean for one ring).
// Writes RawScan records: returned points in the LiDAR frame with per-point
// time and ring; start/end time are the first and last firing.
class SpinningLidarSimulator final : public LidarSimulator {
 public:
  // Throws std::invalid_argument for a pattern out of range.
  SpinningLidarSimulator(const World& world, LidarPoseTrack poses, const SpinningLidarPattern& pattern,
                         LidarNoise noise, std::uint64_t seed);

  double scan_period_s() const override;
  double scan_span_s() const override;
  io::ScanRecord Simulate(double start_time_s) override;

  const SpinningLidarPattern& pattern() const { return pattern_; }
  // Firings per revolution (S).
  std::size_t firings() const { return firings_; }

 private:
  SpinningLidarPattern pattern_;
  std::size_t firings_ = 0;
  double firing_interval_s_ = 0.0;
  std::vector<Eigen::Vector3d> directions_lidar_;  // firing-major: [j * rings + k]
};

}  // namespace unimap::sim
