#pragma once
#include <cstdint>
#include <random>

#include <Eigen/Core>

#include "LidarPoseTrack.hpp"
#include "World.hpp"
#include "io/ScanRecord.hpp"

namespace unimap::sim {

// Measurement errors of a simulated LiDAR.
struct LidarNoise {
  double range_sigma_m = 0.0;        // Gaussian range noise sigma (>= 0)
  double dropout_probability = 0.0;  // chance a beam returns nothing, in [0, 1)
};

// A LiDAR scan pattern cast into a World. Every beam is cast from the LiDAR
// pose at its own firing time, T_world_lidar(t_i) = T_world_body(t_i) *
// T_body_lidar(t_i) (LidarPoseTrack), and measured as
//   r_i = r_true + n_i, n_i ~ N(0, sigma^2), no return with the dropout
//   probability, or when r_true or r_i falls outside [min_range, max_range].
// Subclasses fix the firing order and the record type (LineScan / RawScan).
class LidarSimulator {
 public:
  // world must outlive the simulator. Throws std::invalid_argument for bad noise.
  LidarSimulator(const World& world, LidarPoseTrack poses, LidarNoise noise, std::uint64_t seed);
  virtual ~LidarSimulator() = default;
  LidarSimulator(const LidarSimulator&) = delete;
  LidarSimulator& operator=(const LidarSimulator&) = delete;

  // Time between the first firings of consecutive scans.
  virtual double scan_period_s() const = 0;
  // Time from the first to the last firing of one scan.
  virtual double scan_span_s() const = 0;
  // The scan whose first firing is at start_time_s. Errors of the pose
  // queries (e.g. InputError outside encoder coverage) propagate.
  virtual io::ScanRecord Simulate(double start_time_s) = 0;

  // Beams fired so far (dropouts included) and returns measured.
  std::uint64_t rays() const { return rays_; }
  std::uint64_t returns() const { return returns_; }

 protected:
  // One beam from origin along the unit direction dir_world (world frame):
  // the measured range, or NaN for no return; *intensity gets 100 |cos| of
  // the incidence angle (0 without a return).
  double Fire(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir_world, double min_range_m, double max_range_m,
              float* intensity);
  LidarPoseTrack& poses() { return poses_; }

 private:
  const World& world_;
  LidarPoseTrack poses_;
  LidarNoise noise_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
  std::uint64_t rays_ = 0;
  std::uint64_t returns_ = 0;
};

}  // namespace unimap::sim
