#include "pipeline/TrackingMonitor.hpp"

#include <functional>
#include <limits>

#include <gtest/gtest.h>

namespace unimap::pipeline {
namespace {

// Feeds scans at rate_hz from 0 to end_s (exclusive) with share(t).
void Feed(TrackingMonitor* monitor, double rate_hz, double end_s, const std::function<double(double)>& share) {
  for (int k = 0; k / rate_hz < end_s; ++k) {
    const double t = k / rate_hz;
    monitor->Add(t, share(t));
  }
}

TEST(TrackingMonitor, SteadyTrackingIsNotLost) {
  TrackingMonitor monitor;
  Feed(&monitor, 40.0, 60.0, [](double) { return 0.97; });
  const TrackingReport& r = monitor.report();
  EXPECT_EQ(r.scans, 2400u);
  EXPECT_FALSE(r.lost());
  EXPECT_DOUBLE_EQ(r.poor_s, 0.0);
  EXPECT_NEAR(r.worst_window_share, 0.97, 1e-9);
  EXPECT_GE(r.worst_window_time_s, TrackingMonitor::kWindowS);
}

TEST(TrackingMonitor, ALossIsFoundWhenTheWindowMeanFallsBelowHalf) {
  // Shares 1 until 10 s, then 0.2, at 10 Hz. A window ending at t holds the
  // 21 scans of [t - 2, t]: with G of them before 10 s its mean is
  // (G + 0.2 (21 - G)) / 21, below 0.5 once G <= 7, i.e. from t = 11.3 s.
  TrackingMonitor monitor;
  Feed(&monitor, 10.0, 30.0, [](double t) { return t < 10.0 ? 1.0 : 0.2; });
  const TrackingReport& r = monitor.report();
  ASSERT_TRUE(r.lost());
  // Within one scan of the analytic 11.3 s (the window's edge is a rounded time).
  EXPECT_NEAR(r.first_poor_time_s, 11.3, 0.1 + 1e-9);
  // Poor from then to the last scan (29.9 s).
  EXPECT_NEAR(r.poor_s, 29.9 - r.first_poor_time_s, 1e-9);
  EXPECT_NEAR(r.worst_window_share, 0.2, 1e-9);
}

TEST(TrackingMonitor, ABriefDipIsNotALoss) {
  // Half a second with nothing matched in a 2 s window: 16 of 21 scans at 1.
  TrackingMonitor monitor;
  Feed(&monitor, 10.0, 30.0, [](double t) { return t >= 10.0 && t < 10.45 ? 0.0 : 1.0; });
  const TrackingReport& r = monitor.report();
  EXPECT_FALSE(r.lost());
  EXPECT_NEAR(r.worst_window_share, 16.0 / 21.0, 1e-9);
}

TEST(TrackingMonitor, ARecoveryEndsThePoorTime) {
  TrackingMonitor monitor;
  Feed(&monitor, 10.0, 40.0, [](double t) { return t >= 10.0 && t < 20.0 ? 0.0 : 1.0; });
  const TrackingReport& r = monitor.report();
  ASSERT_TRUE(r.lost());
  // Zeros from 10 s: the mean (G / 21) is below 0.5 once G <= 10, from 11.0 s;
  // ones from 20 s: G' ones give G' / 21 >= 0.5 from G' = 11, at 21.0 s.
  EXPECT_NEAR(r.first_poor_time_s, 11.0, 0.1 + 1e-9);
  EXPECT_NEAR(r.poor_s, 10.0, 0.2 + 1e-9);
  EXPECT_DOUBLE_EQ(r.worst_window_share, 0.0);
}

TEST(TrackingMonitor, ARecordingShorterThanTheWindowIsNotJudged) {
  TrackingMonitor monitor;
  Feed(&monitor, 10.0, 1.5, [](double) { return 0.0; });
  const TrackingReport& r = monitor.report();
  EXPECT_EQ(r.scans, 15u);
  EXPECT_FALSE(r.lost());
  EXPECT_LT(r.worst_window_time_s, 0.0);
}

TEST(TrackingMonitor, TooFewScansInAWindowAreNotJudged) {
  // One scan a second: a 2 s window never holds kMinScans.
  TrackingMonitor monitor;
  Feed(&monitor, 1.0, 60.0, [](double) { return 0.0; });
  EXPECT_FALSE(monitor.report().lost());
}

TEST(TrackingMonitor, ATimeGoingBackRestartsTheWindow) {
  TrackingMonitor monitor;
  Feed(&monitor, 10.0, 1.9, [](double) { return 0.0; });
  // Back to 0 s: the zeros before are dropped, so 1.9 s of ones is not judged
  // and the later ones stay good.
  Feed(&monitor, 10.0, 10.0, [](double) { return 1.0; });
  const TrackingReport& r = monitor.report();
  EXPECT_FALSE(r.lost());
  EXPECT_DOUBLE_EQ(r.worst_window_share, 1.0);
}

TEST(TrackingMonitor, SharesAreClampedAndNonFiniteCountsZero) {
  TrackingMonitor monitor;
  Feed(&monitor, 10.0, 10.0, [](double t) { return t < 5.0 ? 3.0 : std::numeric_limits<double>::quiet_NaN(); });
  const TrackingReport& r = monitor.report();
  ASSERT_TRUE(r.lost());
  EXPECT_DOUBLE_EQ(r.worst_window_share, 0.0);
}

}  // namespace
}  // namespace unimap::pipeline
