#include "EncoderSimulator.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "unimap/EncoderTrack.hpp"

namespace unimap::sim {
namespace {

constexpr double kTwoPi = 2.0 * M_PI;

TEST(EncoderSimulator, WrapsIntoZeroToTwoPi) {
  EXPECT_DOUBLE_EQ(EncoderSimulator::Wrap(0.0), 0.0);
  EXPECT_NEAR(EncoderSimulator::Wrap(kTwoPi + 0.25), 0.25, 1e-12);
  EXPECT_NEAR(EncoderSimulator::Wrap(-0.25), kTwoPi - 0.25, 1e-12);
  EXPECT_NEAR(EncoderSimulator::Wrap(7 * kTwoPi + 1.0), 1.0, 1e-11);
  EXPECT_LT(EncoderSimulator::Wrap(-1e-18), kTwoPi);  // never 2 pi itself
  EXPECT_GE(EncoderSimulator::Wrap(-1e-18), 0.0);
}

TEST(EncoderSimulator, QuantisesToTheNearestCount) {
  const double res = kTwoPi / 4096;
  EXPECT_DOUBLE_EQ(EncoderSimulator::Quantise(10.4 * res, res), 10 * res);
  EXPECT_DOUBLE_EQ(EncoderSimulator::Quantise(10.6 * res, res), 11 * res);
  EXPECT_DOUBLE_EQ(EncoderSimulator::Quantise(kTwoPi - 0.2 * res, res), 0.0);  // rounds up to 2 pi = 0
  EXPECT_DOUBLE_EQ(EncoderSimulator::Quantise(1.2345, 0.0), 1.2345);           // no quantisation
  for (double a = -20.0; a < 20.0; a += 0.0137) {
    const double q = EncoderSimulator::Quantise(a, res);
    ASSERT_GE(q, 0.0);
    ASSERT_LT(q, kTwoPi);
    const double counts = q / res;
    EXPECT_NEAR(counts, std::round(counts), 1e-6) << a;
    EXPECT_LE(std::abs(std::remainder(q - a, kTwoPi)), 0.5 * res + 1e-12) << a;
  }
}

// A constant-rate motor's encoder config.
EncoderConfig Spinning(double rate_hz, double resolution_rad, double rpm, double initial_rad) {
  EncoderConfig config;
  config.rate_hz = rate_hz;
  config.resolution_rad = resolution_rad;
  config.motion.rate_rpm = rpm;
  config.initial_angle_rad = initial_rad;
  return config;
}

TEST(EncoderSimulator, TurnsAtTheMotorRate) {
  const EncoderSimulator enc(Spinning(100.0, 0.0, 30.0, 0.5));
  EXPECT_DOUBLE_EQ(enc.SampleTime(250), 2.5);
  EXPECT_NEAR(enc.TrueAngle(0.0), 0.5, 1e-15);
  EXPECT_NEAR(enc.TrueAngle(1.0) - enc.TrueAngle(0.0), M_PI, 1e-12);  // 30 rpm = half a turn per second
  EXPECT_NEAR(enc.Measure(2.0).angle_rad, 0.5, 1e-12);                // one full turn later
  EXPECT_DOUBLE_EQ(enc.Measure(2.0).time_s, 2.0);
}

// Recorded samples are wrapped and quantised; unwrapped by the SDK's
// EncoderTrack they follow the true angle to within half a count.
TEST(EncoderSimulator, SamplesUnwrapBackToTheTrueAngle) {
  const double res = kTwoPi / 1024;
  const EncoderSimulator enc(Spinning(100.0, res, 45.0, 1.0));
  std::vector<EncoderSample> samples;
  for (std::size_t k = 0; k <= 1000; ++k) samples.push_back(enc.Measure(enc.SampleTime(k)));
  for (const EncoderSample& s : samples) {
    ASSERT_GE(s.angle_rad, 0.0);
    ASSERT_LT(s.angle_rad, kTwoPi);
  }
  const EncoderTrack track(samples);
  const double offset = track.AngleAt(0.0) - enc.TrueAngle(0.0);  // whole turns chosen by the unwrap
  EXPECT_NEAR(std::remainder(offset, kTwoPi), 0.0, 0.5 * res + 1e-12);
  for (double t = 0.0; t <= 10.0; t += 0.01) {
    EXPECT_NEAR(track.AngleAt(t), enc.TrueAngle(t) + std::round(offset / kTwoPi) * kTwoPi, 0.5 * res + 1e-9) << t;
  }
}

TEST(EncoderSimulator, RejectsBadConfig) {
  EXPECT_THROW(EncoderSimulator(Spinning(0.0, 0.0, 30.0, 0.0)), std::invalid_argument);
  EXPECT_THROW(EncoderSimulator(Spinning(100.0, -1.0, 30.0, 0.0)), std::invalid_argument);
  EXPECT_THROW(EncoderSimulator(Spinning(100.0, 0.0, 0.0, 0.0)), std::invalid_argument);
  EncoderConfig servo;
  servo.motion.kind = MotorMotion::Kind::kOscillating;
  servo.motion.max_deg = servo.motion.min_deg;  // empty range
  EXPECT_THROW(EncoderSimulator{servo}, std::invalid_argument);
}

// A servo reports its angle as it is (no wrap), quantised; unwrapped by the
// SDK's EncoderTrack it follows the true angle to within half a count.
TEST(EncoderSimulator, ServoReadingsAreNotWrapped) {
  EncoderConfig servo;
  servo.rate_hz = 50.0;
  servo.resolution_rad = kTwoPi / 4096;
  servo.motion.kind = MotorMotion::Kind::kOscillating;
  servo.motion.min_deg = -45.0;
  servo.motion.max_deg = 45.0;
  servo.motion.period_s = 2.0;
  const EncoderSimulator enc(servo);
  EXPECT_NEAR(enc.TrueAngle(0.0), -M_PI / 4.0, 1e-12);
  EXPECT_NEAR(enc.TrueAngle(1.0), M_PI / 4.0, 1e-12);
  std::vector<EncoderSample> samples;
  double lowest = 1e9;
  for (std::size_t k = 0; k <= 500; ++k) {
    samples.push_back(enc.Measure(enc.SampleTime(k)));
    lowest = std::min(lowest, samples.back().angle_rad);
  }
  EXPECT_NEAR(lowest, -M_PI / 4.0, 0.5 * servo.resolution_rad + 1e-12);  // negative: not wrapped
  const EncoderTrack track(samples);
  for (double t = 0.0; t <= 10.0; t += 0.013) {
    EXPECT_NEAR(track.AngleAt(t), enc.TrueAngle(t), 0.5 * servo.resolution_rad + 2e-3) << t;
  }
}

}  // namespace
}  // namespace unimap::sim
