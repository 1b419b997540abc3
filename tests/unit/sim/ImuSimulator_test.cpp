#include "ImuSimulator.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "WaypointTrajectory.hpp"

namespace unimap::sim {
namespace {

constexpr double kDeg = M_PI / 180.0;

// Per-axis sample mean and variance of a stream of 3-vectors.
struct AxisStats {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Vector3d sum_sq = Eigen::Vector3d::Zero();
  double n = 0.0;
  void Add(const Eigen::Vector3d& x) {
    sum += x;
    sum_sq += x.cwiseProduct(x);
    n += 1.0;
  }
  Eigen::Vector3d Mean() const { return sum / n; }
  Eigen::Vector3d Variance() const { return (sum_sq - sum.cwiseProduct(sum) / n) / (n - 1.0); }
};

ImuConfig NoisyConfig() {
  ImuConfig c;
  c.rate_hz = 200.0;
  c.noise.accel_noise_m_s2 = 0.05;
  c.noise.gyro_noise_rad_s = 0.01;
  c.noise.accel_bias_walk_m_s2_sqrt_s = 0.002;
  c.noise.gyro_bias_walk_rad_s_sqrt_s = 0.0005;
  c.noise.accel_bias_m_s2 = Eigen::Vector3d(0.1, -0.05, 0.2);
  c.noise.gyro_bias_rad_s = Eigen::Vector3d(0.01, 0.02, -0.015);
  return c;
}

// A body at rest, tilted (so gravity shows on every axis).
KinematicState Resting(double t) {
  KinematicState s;
  s.time_s = t;
  s.q_world_body = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized());
  return s;
}

// Statistics over N = 2e5 samples. A sample variance of N Gaussian draws has
// relative standard deviation sqrt(2 / N) = 0.32 % (chi-square with N degrees
// of freedom); the tolerance is 5 of those, a 5-sigma band. Means: 5 sigma / sqrt(N).
TEST(ImuSimulator, WhiteNoiseAndBiasWalkMatchConfiguredSigmas) {
  const ImuConfig c = NoisyConfig();
  ImuSimulator imu(c, 42);
  const int n = 200000;
  const double dt = 1.0 / c.rate_hz;
  AxisStats accel_noise, gyro_noise, accel_walk, gyro_walk;
  for (int k = 0; k < n; ++k) {
    const KinematicState state = Resting(k * dt);
    const ImuSample ideal = ImuSimulator::Ideal(state, c.gravity_m_s2);
    const Eigen::Vector3d ba = imu.accel_bias(), bg = imu.gyro_bias();
    const ImuSample m = imu.Measure(state);
    accel_noise.Add(m.accel_m_s2 - ideal.accel_m_s2 - ba);
    gyro_noise.Add(m.gyro_rad_s - ideal.gyro_rad_s - bg);
    accel_walk.Add(imu.accel_bias() - ba);
    gyro_walk.Add(imu.gyro_bias() - bg);
  }
  const double var_tol = 5.0 * std::sqrt(2.0 / n);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(accel_noise.Variance()[axis] / std::pow(c.noise.accel_noise_m_s2, 2), 1.0, var_tol);
    EXPECT_NEAR(gyro_noise.Variance()[axis] / std::pow(c.noise.gyro_noise_rad_s, 2), 1.0, var_tol);
    EXPECT_NEAR(accel_walk.Variance()[axis] / (std::pow(c.noise.accel_bias_walk_m_s2_sqrt_s, 2) * dt), 1.0, var_tol);
    EXPECT_NEAR(gyro_walk.Variance()[axis] / (std::pow(c.noise.gyro_bias_walk_rad_s_sqrt_s, 2) * dt), 1.0, var_tol);
    EXPECT_NEAR(accel_noise.Mean()[axis], 0.0, 5.0 * c.noise.accel_noise_m_s2 / std::sqrt(n));
    EXPECT_NEAR(gyro_noise.Mean()[axis], 0.0, 5.0 * c.noise.gyro_noise_rad_s / std::sqrt(n));
  }
}

// The same from the readings alone: m_k+1 - m_k = (b_k+1 - b_k) + n_k+1 - n_k
// has variance 2 sigma^2 + sigma_walk^2 dt. The differences are an MA(1)
// sequence (lag-1 correlation -1/2), whose sample variance has relative
// standard deviation sqrt(3 / N); tolerance 5 of those.
TEST(ImuSimulator, ReadingDifferencesHaveTheExpectedVariance) {
  const ImuConfig c = NoisyConfig();
  ImuSimulator imu(c, 7);
  const int n = 200000;
  const double dt = 1.0 / c.rate_hz;
  AxisStats accel_diff, gyro_diff;
  ImuSample previous = imu.Measure(Resting(0.0));
  for (int k = 1; k <= n; ++k) {
    const ImuSample m = imu.Measure(Resting(k * dt));
    accel_diff.Add(m.accel_m_s2 - previous.accel_m_s2);
    gyro_diff.Add(m.gyro_rad_s - previous.gyro_rad_s);
    previous = m;
  }
  const auto& nz = c.noise;
  const double accel_expected = 2 * nz.accel_noise_m_s2 * nz.accel_noise_m_s2 +
                                nz.accel_bias_walk_m_s2_sqrt_s * nz.accel_bias_walk_m_s2_sqrt_s * dt;
  const double gyro_expected = 2 * nz.gyro_noise_rad_s * nz.gyro_noise_rad_s +
                               nz.gyro_bias_walk_rad_s_sqrt_s * nz.gyro_bias_walk_rad_s_sqrt_s * dt;
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(accel_diff.Variance()[axis] / accel_expected, 1.0, 5.0 * std::sqrt(3.0 / n));
    EXPECT_NEAR(gyro_diff.Variance()[axis] / gyro_expected, 1.0, 5.0 * std::sqrt(3.0 / n));
  }
}

TEST(ImuSimulator, InitialBiasShowsInTheMeanReading) {
  ImuConfig c = NoisyConfig();
  c.noise.accel_bias_walk_m_s2_sqrt_s = 0.0;
  c.noise.gyro_bias_walk_rad_s_sqrt_s = 0.0;
  ImuSimulator imu(c, 3);
  const int n = 20000;
  AxisStats accel, gyro;
  for (int k = 0; k < n; ++k) {
    const KinematicState state = Resting(k / c.rate_hz);
    const ImuSample ideal = ImuSimulator::Ideal(state, c.gravity_m_s2);
    const ImuSample m = imu.Measure(state);
    accel.Add(m.accel_m_s2 - ideal.accel_m_s2);
    gyro.Add(m.gyro_rad_s - ideal.gyro_rad_s);
  }
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(accel.Mean()[axis], c.noise.accel_bias_m_s2[axis], 5 * c.noise.accel_noise_m_s2 / std::sqrt(n));
    EXPECT_NEAR(gyro.Mean()[axis], c.noise.gyro_bias_rad_s[axis], 5 * c.noise.gyro_noise_rad_s / std::sqrt(n));
  }
}

TEST(ImuSimulator, SpecificForceAtRestIsMinusGravityInTheBodyFrame) {
  const KinematicState state = Resting(0.0);
  const ImuSample ideal = ImuSimulator::Ideal(state, 9.81);
  EXPECT_LT((state.q_world_body * ideal.accel_m_s2 - Eigen::Vector3d(0, 0, 9.81)).norm(), 1e-12);
  EXPECT_EQ(ideal.gyro_rad_s, Eigen::Vector3d::Zero());
}

TEST(ImuSimulator, SameSeedSameReadings) {
  ImuSimulator a(NoisyConfig(), 11), b(NoisyConfig(), 11), c(NoisyConfig(), 12);
  const ImuSample ma = a.Measure(Resting(0.0)), mb = b.Measure(Resting(0.0)), mc = c.Measure(Resting(0.0));
  EXPECT_EQ(ma.accel_m_s2, mb.accel_m_s2);
  EXPECT_EQ(ma.gyro_rad_s, mb.gyro_rad_s);
  EXPECT_NE(ma.accel_m_s2, mc.accel_m_s2);
}

// State derivative for RK4: q' = q (0, omega) / 2, v' = R f + g, p' = v.
struct Nominal {
  Eigen::Quaterniond q;
  Eigen::Vector3d v, p;
};
Nominal Derivative(const Nominal& x, const ImuSample& m, const Eigen::Vector3d& g) {
  const Eigen::Quaterniond omega(0.0, m.gyro_rad_s.x(), m.gyro_rad_s.y(), m.gyro_rad_s.z());
  Nominal d;
  d.q.coeffs() = 0.5 * (x.q * omega).coeffs();
  d.v = x.q.normalized() * m.accel_m_s2 + g;
  d.p = x.v;
  return d;
}
Nominal Step(const Nominal& x, const Nominal& d, double h) {
  Nominal y;
  y.q.coeffs() = x.q.coeffs() + h * d.q.coeffs();
  y.v = x.v + h * d.v;
  y.p = x.p + h * d.p;
  return y;
}

// Noise-free readings integrated (RK4 with step 2 / rate: samples k, k+1,
// k+2 are the stage times t, t + h/2, t + h) from the analytic start state
// reproduce the trajectory: under 1 cm after 60 s of motion.
TEST(ImuSimulator, NoiseFreeReadingsIntegrateBackToTheTrajectory) {
  std::vector<Waypoint> w = {{Eigen::Vector3d(0, 0, 1), 0.0, 0.0},  {Eigen::Vector3d(10, 1, 2), 0.5, 2.0},
                             {Eigen::Vector3d(12, 6, 1), 2.0, 0.0}, {Eigen::Vector3d(3, 8, 3), 3.0, 1.0},
                             {Eigen::Vector3d(-2, 0, 1), 6.0, 0.0}, {Eigen::Vector3d(6, -3, 2), 4.0, 0.0},
                             {Eigen::Vector3d(0, 0, 1), 0.0, 10.0}};
  WaypointTrajectoryOptions o;
  o.max_speed_m_s = 1.5;
  o.max_acceleration_m_s2 = 1.0;
  o.max_yaw_rate_rad_s = 40 * kDeg;
  o.static_start_s = 0.5;
  o.wobble = {3 * kDeg, 2 * kDeg, 4.0, 6.0, 2.0};
  const WaypointTrajectory traj(w, o);
  ASSERT_GE(traj.end_time_s(), 60.0);

  ImuConfig c;
  c.rate_hz = 200.0;
  ImuSimulator imu(c, 1);
  const Eigen::Vector3d g(0, 0, -c.gravity_m_s2);
  const KinematicState s0 = traj.At(0.0);
  Nominal x{s0.q_world_body, s0.velocity_m_s, s0.position_m};
  ImuSample m0 = imu.Measure(traj.At(0.0));
  const int steps = 6000;  // 60 s at h = 10 ms
  const double h = 2.0 / c.rate_hz;
  for (int k = 0; k < steps; ++k) {
    const ImuSample m1 = imu.Measure(traj.At((2 * k + 1) / c.rate_hz));
    const ImuSample m2 = imu.Measure(traj.At((2 * k + 2) / c.rate_hz));
    const Nominal k1 = Derivative(x, m0, g);
    const Nominal k2 = Derivative(Step(x, k1, h / 2), m1, g);
    const Nominal k3 = Derivative(Step(x, k2, h / 2), m1, g);
    const Nominal k4 = Derivative(Step(x, k3, h), m2, g);
    x.q.coeffs() += h / 6 * (k1.q.coeffs() + 2 * k2.q.coeffs() + 2 * k3.q.coeffs() + k4.q.coeffs());
    x.q.normalize();
    x.v += h / 6 * (k1.v + 2 * k2.v + 2 * k3.v + k4.v);
    x.p += h / 6 * (k1.p + 2 * k2.p + 2 * k3.p + k4.p);
    m0 = m2;
  }
  const KinematicState truth = traj.At(60.0);
  EXPECT_LT((x.p - truth.position_m).norm(), 0.01);
  EXPECT_LT((x.v - truth.velocity_m_s).norm(), 1e-3);
  EXPECT_LT(x.q.angularDistance(truth.q_world_body), 1e-5);
  EXPECT_GT(traj.PathLength(60.0), 30.0);  // it really moved
}

TEST(ImuSimulator, RejectsBadConfig) {
  ImuConfig c;
  c.rate_hz = 0.0;
  EXPECT_THROW(ImuSimulator(c, 1), std::invalid_argument);
  c = ImuConfig();
  c.noise.gyro_noise_rad_s = -1.0;
  EXPECT_THROW(ImuSimulator(c, 1), std::invalid_argument);
}

}  // namespace
}  // namespace unimap::sim
