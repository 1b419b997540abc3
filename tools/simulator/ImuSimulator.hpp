#pragma once
#include <cstdint>
#include <random>

#include <Eigen/Core>

#include "Trajectory.hpp"
#include "unimap/ImuSample.hpp"

namespace unimap::sim {

// IMU error model (per axis, the same for x, y, z).
struct ImuNoise {
  double accel_noise_m_s2 = 0.0;                              // white noise sigma per sample
  double gyro_noise_rad_s = 0.0;                              // white noise sigma per sample
  double accel_bias_walk_m_s2_sqrt_s = 0.0;                   // bias random walk: sigma of the change over 1 s
  double gyro_bias_walk_rad_s_sqrt_s = 0.0;                   // bias random walk: sigma of the change over 1 s
  Eigen::Vector3d accel_bias_m_s2 = Eigen::Vector3d::Zero();  // bias at the first sample
  Eigen::Vector3d gyro_bias_rad_s = Eigen::Vector3d::Zero();  // bias at the first sample
};

// What the IMU is and how it errs.
struct ImuConfig {
  double rate_hz = 200.0;         // samples per second (> 0)
  double gravity_m_s2 = 9.80665;  // g_world = (0, 0, -gravity)
  ImuNoise noise;                 // error model
};

// Simulates IMU readings from kinematic states (the body frame is the IMU
// frame). Sample k, at the IMU period dt = 1 / rate_hz:
//   accel_k = R^T (a_world - g_world) + b_a,k + n_a,k,   n_a,k ~ N(0, sigma_a^2 I)
//   gyro_k  = omega_body + b_g,k + n_g,k,                n_g,k ~ N(0, sigma_g^2 I)
//   b_k+1   = b_k + sigma_walk sqrt(dt) w_k,             w_k ~ N(0, I)
// Deterministic for a seed (std::mt19937_64).
class ImuSimulator {
 public:
  // Throws std::invalid_argument for a non-positive rate or a negative sigma.
  ImuSimulator(const ImuConfig& config, std::uint64_t seed);

  // The error-free reading of a state: f_body = R^T (a_world - g_world), omega_body.
  static ImuSample Ideal(const KinematicState& state, double gravity_m_s2);
  // The next reading (time = state.time_s), then the biases take one random-walk step.
  ImuSample Measure(const KinematicState& state);

  // Biases that the next Measure() adds.
  const Eigen::Vector3d& accel_bias() const { return accel_bias_; }
  const Eigen::Vector3d& gyro_bias() const { return gyro_bias_; }
  const ImuConfig& config() const { return config_; }

 private:
  // A vector of three independent N(0, sigma^2) draws (zeros when sigma = 0).
  Eigen::Vector3d Gaussian(double sigma);

  ImuConfig config_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  Eigen::Vector3d accel_bias_;
  Eigen::Vector3d gyro_bias_;
};

}  // namespace unimap::sim
