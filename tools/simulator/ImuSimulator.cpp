#include "ImuSimulator.hpp"

#include <cmath>
#include <stdexcept>

namespace unimap::sim {

ImuSimulator::ImuSimulator(const ImuConfig& config, std::uint64_t seed)
    : config_(config), rng_(seed), accel_bias_(config.noise.accel_bias_m_s2), gyro_bias_(config.noise.gyro_bias_rad_s) {
  const ImuNoise& n = config_.noise;
  if (!(std::isfinite(config_.rate_hz) && config_.rate_hz > 0.0)) {
    throw std::invalid_argument("IMU rate must be positive");
  }
  if (!std::isfinite(config_.gravity_m_s2)) throw std::invalid_argument("gravity must be finite");
  for (double sigma :
       {n.accel_noise_m_s2, n.gyro_noise_rad_s, n.accel_bias_walk_m_s2_sqrt_s, n.gyro_bias_walk_rad_s_sqrt_s}) {
    if (!(std::isfinite(sigma) && sigma >= 0.0)) throw std::invalid_argument("IMU sigmas must be >= 0");
  }
  if (!accel_bias_.allFinite() || !gyro_bias_.allFinite()) {
    throw std::invalid_argument("IMU initial biases must be finite");
  }
}

ImuSample ImuSimulator::Ideal(const KinematicState& state, double gravity_m_s2) {
  const Eigen::Vector3d g_world(0.0, 0.0, -gravity_m_s2);
  ImuSample sample;
  sample.time_s = state.time_s;
  sample.accel_m_s2 = state.q_world_body.conjugate() * (state.acceleration_m_s2 - g_world);
  sample.gyro_rad_s = state.angular_velocity_body_rad_s;
  return sample;
}

Eigen::Vector3d ImuSimulator::Gaussian(double sigma) {
  if (sigma == 0.0) return Eigen::Vector3d::Zero();
  const double x = normal_(rng_);
  const double y = normal_(rng_);
  const double z = normal_(rng_);
  return sigma * Eigen::Vector3d(x, y, z);
}

ImuSample ImuSimulator::Measure(const KinematicState& state) {
  const ImuNoise& n = config_.noise;
  ImuSample sample = Ideal(state, config_.gravity_m_s2);
  sample.accel_m_s2 += accel_bias_ + Gaussian(n.accel_noise_m_s2);
  sample.gyro_rad_s += gyro_bias_ + Gaussian(n.gyro_noise_rad_s);
  // Bias random walk over one period: sigma_walk * sqrt(dt) per step.
  const double sqrt_dt = std::sqrt(1.0 / config_.rate_hz);
  accel_bias_ += Gaussian(n.accel_bias_walk_m_s2_sqrt_s * sqrt_dt);
  gyro_bias_ += Gaussian(n.gyro_bias_walk_rad_s_sqrt_s * sqrt_dt);
  return sample;
}

}  // namespace unimap::sim
