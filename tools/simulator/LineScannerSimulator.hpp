#pragma once
#include <vector>

#include <Eigen/Core>

#include "LidarSimulator.hpp"
#include "unimap/ParameterMap.hpp"

namespace unimap::sim {

// A 2D line scanner's firing pattern (Hokuyo UTM-30LX class), as the payload
// keys "lidar.scan_rate_hz", "lidar.fov_deg", "lidar.beams",
// "lidar.min_range_m", "lidar.max_range_m" describe it.
struct LineScannerPattern {
  double scan_rate_hz = 40.0;  // lines per second (mirror revolutions per second)
  double fov_deg = 270.0;      // first to last beam, centred on the scanner's +x
  int beams = 1081;            // beams per line, first and last included (>= 2)
  double min_range_m = 0.1;    // shorter returns are invalid
  double max_range_m = 30.0;   // longer returns are invalid

  // Reads the five keys; throws ConfigError naming a missing or mistyped key.
  static LineScannerPattern FromParameters(const ParameterMap& parameters);
};

// Simulates a line scanner: beam i points at angle_min + i * step in the
// scanner's x-y plane (angle_min = -fov/2, step = fov / (beams - 1)) and fires
// at start + i * step / (2 pi scan_rate) (the mirror turns once per line).
// Writes LineScan records, NaN range for no return.
class LineScannerSimulator final : public LidarSimulator {
 public:
  // Throws std::invalid_argument for a pattern out of range.
  LineScannerSimulator(const World& world, LidarPoseTrack poses, const LineScannerPattern& pattern, LidarNoise noise,
                       std::uint64_t seed);

  double scan_period_s() const override;
  double scan_span_s() const override;
  io::ScanRecord Simulate(double start_time_s) override;

  const LineScannerPattern& pattern() const { return pattern_; }

 private:
  LineScannerPattern pattern_;
  double angle_min_rad_;
  double angle_step_rad_;
  double beam_interval_s_;
  std::vector<Eigen::Vector3d> directions_lidar_;  // unit beam directions, scanner frame
};

}  // namespace unimap::sim
