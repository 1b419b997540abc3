#include "unimap/EncoderTrack.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "unimap/Errors.hpp"

namespace unimap {
namespace {

double WrapTo2Pi(double a) {
  double w = std::fmod(a, 2.0 * M_PI);
  return w < 0.0 ? w + 2.0 * M_PI : w;
}

// Constant-rate rotation sampled at irregular times, wrapped to [0, 2pi).
std::vector<EncoderSample> ConstantRate(double rate_rad_s, double phase_rad, int count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> gap(0.002, 0.03);
  std::vector<EncoderSample> samples;
  double t = 10.0;
  for (int i = 0; i < count; ++i) {
    samples.push_back({t, WrapTo2Pi(phase_rad + rate_rad_s * (t - 10.0))});
    t += gap(rng);
  }
  return samples;
}

TEST(EncoderTrack, InterpolationIsExactForConstantRateAcrossWraps) {
  const double rate = 3.3;  // rad/s: wraps about every 1.9 s
  const auto samples = ConstantRate(rate, 0.4, 2000, 7);
  const EncoderTrack track(samples);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> when(track.start_time_s(), track.end_time_s());
  for (int i = 0; i < 5000; ++i) {
    const double t = when(rng);
    EXPECT_NEAR(track.AngleAt(t), 0.4 + rate * (t - 10.0), 1e-9) << "t=" << t;
  }
}

TEST(EncoderTrack, UnwrapsNegativeRotationInMinusPiPiConvention) {
  std::vector<EncoderSample> samples;
  for (int i = 0; i <= 400; ++i) {
    const double t = 0.01 * i;
    samples.push_back({t, std::remainder(-5.0 * t, 2.0 * M_PI)});  // [-pi, pi]
  }
  const EncoderTrack track(samples);
  EXPECT_NEAR(track.AngleAt(3.995), -5.0 * 3.995, 1e-9);
  EXPECT_NEAR(track.AngleAt(4.0), -20.0, 1e-9);
}

TEST(EncoderTrack, RejectsTimeGoingBackwardsNamingTheSample) {
  std::vector<EncoderSample> samples = {{0.0, 0.0}, {0.1, 0.1}, {0.05, 0.2}};
  try {
    EncoderTrack track(samples);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sample 2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("backwards"), std::string::npos) << e.what();
  }
  EXPECT_THROW(EncoderTrack({{0.0, 0.0}, {0.0, 0.1}}), InputError);  // repeated time
  EXPECT_THROW(EncoderTrack({{0.0, std::nan("")}}), InputError);
}

TEST(EncoderTrack, OutsideCoverageAndGapsThrow) {
  const EncoderTrack track({{1.0, 0.0}, {1.1, 0.1}, {2.0, 1.0}, {2.1, 1.1}}, 0.5);
  EXPECT_THROW(track.AngleAt(0.99), InputError);
  EXPECT_THROW(track.AngleAt(2.11), InputError);
  EXPECT_THROW(track.AngleAt(1.5), InputError);  // inside the 0.9 s gap
  EXPECT_FALSE(track.Covers(1.5));
  EXPECT_TRUE(track.Covers(1.05));
  EXPECT_NEAR(track.AngleAt(1.05), 0.05, 1e-12);
  EXPECT_DOUBLE_EQ(track.AngleAt(2.0), 1.0);  // exactly on a sample next to the gap
  EXPECT_THROW(EncoderTrack().AngleAt(0.0), InputError);
}

TEST(EncoderTrack, AppendAndDropBeforeKeepBracketingSample) {
  EncoderTrack track;
  for (int i = 0; i < 10; ++i) track.Append({0.1 * i, 0.2 * i});
  track.DropBefore(0.45);
  EXPECT_EQ(track.size(), 6u);  // 0.4 .. 0.9
  EXPECT_NEAR(track.AngleAt(0.45), 0.9, 1e-12);
  EXPECT_THROW(track.AngleAt(0.35), InputError);
  EXPECT_THROW(track.Append({0.9, 0.0}), InputError);
}

}  // namespace
}  // namespace unimap
