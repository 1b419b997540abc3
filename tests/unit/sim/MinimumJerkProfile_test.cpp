#include "MinimumJerkProfile.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

namespace unimap::sim {
namespace {

using P = MinimumJerkProfile;

TEST(MinimumJerkProfile, RestToRestEndpoints) {
  EXPECT_DOUBLE_EQ(P::Position(0.0), 0.0);
  EXPECT_DOUBLE_EQ(P::Position(1.0), 1.0);
  EXPECT_DOUBLE_EQ(P::Position(0.5), 0.5);
  EXPECT_DOUBLE_EQ(P::Velocity(0.0), 0.0);
  EXPECT_DOUBLE_EQ(P::Velocity(1.0), 0.0);
  EXPECT_DOUBLE_EQ(P::Acceleration(0.0), 0.0);
  EXPECT_DOUBLE_EQ(P::Acceleration(1.0), 0.0);
  // Clamped outside [0, 1]: rest before and after.
  EXPECT_DOUBLE_EQ(P::Position(-0.3), 0.0);
  EXPECT_DOUBLE_EQ(P::Position(1.7), 1.0);
  EXPECT_DOUBLE_EQ(P::Velocity(-0.3), 0.0);
  EXPECT_DOUBLE_EQ(P::Acceleration(1.7), 0.0);
}

TEST(MinimumJerkProfile, DerivativesMatchCentralDifferences) {
  const double h = 1e-5;
  for (double u = 0.01; u < 0.995; u += 0.01) {
    EXPECT_NEAR(P::Velocity(u), (P::Position(u + h) - P::Position(u - h)) / (2 * h), 1e-8) << u;
    EXPECT_NEAR(P::Acceleration(u), (P::Velocity(u + h) - P::Velocity(u - h)) / (2 * h), 1e-7) << u;
  }
}

TEST(MinimumJerkProfile, PeaksAreTheStatedConstants) {
  double peak_v = 0.0, peak_a = 0.0;
  for (int i = 0; i <= 100000; ++i) {
    const double u = i / 100000.0;
    peak_v = std::max(peak_v, P::Velocity(u));
    peak_a = std::max(peak_a, std::abs(P::Acceleration(u)));
  }
  EXPECT_NEAR(peak_v, P::kPeakVelocity, 1e-9);
  EXPECT_DOUBLE_EQ(P::Velocity(0.5), 1.875);
  EXPECT_NEAR(peak_a, P::kPeakAcceleration, 1e-7);
  EXPECT_NEAR(P::Acceleration(0.5 - std::sqrt(3.0) / 6.0), 10.0 / std::sqrt(3.0), 1e-12);
}

}  // namespace
}  // namespace unimap::sim
