#include "pipeline/TrackingMonitor.hpp"

#include <functional>
#include <limits>

#include <gtest/gtest.h>

namespace unimap::pipeline {
namespace {

// Feeds scans at rate_hz from 0 to end_s (exclusive) with share(t). At 8 Hz
// every time is exact in binary, and a 2 s window (t - 2, t] holds exactly
// 16 scans, so the values below are exact.
void Feed(TrackingMonitor* monitor, double rate_hz, double end_s, const std::function<double(double)>& share) {
  for (int k = 0; k / rate_hz < end_s; ++k) {
    const double t = k / rate_hz;
    monitor->Add(t, share(t));
  }
}

TEST(TrackingMonitor, SteadyTrackingIsNotLost) {
  TrackingMonitor monitor;
  Feed(&monitor, 8.0, 60.0, [](double) { return 0.97; });
  const TrackingReport& r = monitor.report();
  EXPECT_EQ(r.scans, 480u);
  EXPECT_DOUBLE_EQ(r.first_time_s, 0.0);
  EXPECT_FALSE(r.lost());
  EXPECT_DOUBLE_EQ(r.poor_s, 0.0);
  EXPECT_NEAR(r.worst_window_share, 0.97, 1e-12);
  EXPECT_DOUBLE_EQ(r.worst_window_time_s, TrackingMonitor::kWindowS);  // the first judged window
}

TEST(TrackingMonitor, ALossIsFoundWhenTheWindowMeanFallsBelowHalf) {
  // Shares 1 until 10 s, then 0.2. A window ending at t >= 10 s holds G
  // scans before 10 s, G = 8 (12 - t) - 1, and 16 - G after: its mean
  // (G + 0.2 (16 - G)) / 16 is below 0.5 once G <= 5, i.e. from t = 11.25 s.
  TrackingMonitor monitor;
  Feed(&monitor, 8.0, 30.0, [](double t) { return t < 10.0 ? 1.0 : 0.2; });
  const TrackingReport& r = monitor.report();
  ASSERT_TRUE(r.lost());
  EXPECT_DOUBLE_EQ(r.first_poor_time_s, 11.25);
  // Poor from then to the last scan (29.875 s).
  EXPECT_DOUBLE_EQ(r.poor_s, 29.875 - 11.25);
  EXPECT_NEAR(r.worst_window_share, 0.2, 1e-12);
}

TEST(TrackingMonitor, HalfTheWindowOffTheMapIsNotPoorAndMoreIs) {
  // 8 scans of 16 at 0: a mean of exactly 0.5, not below it.
  TrackingMonitor at_half;
  Feed(&at_half, 8.0, 30.0, [](double t) { return t >= 10.0 && t < 11.0 ? 0.0 : 1.0; });
  EXPECT_FALSE(at_half.report().lost());
  EXPECT_DOUBLE_EQ(at_half.report().worst_window_share, 0.5);
  // 9 of 16: 7 / 16, poor when the ninth arrives (11.0 s).
  TrackingMonitor beyond;
  Feed(&beyond, 8.0, 30.0, [](double t) { return t >= 10.0 && t < 11.125 ? 0.0 : 1.0; });
  ASSERT_TRUE(beyond.report().lost());
  EXPECT_DOUBLE_EQ(beyond.report().first_poor_time_s, 11.0);
  EXPECT_DOUBLE_EQ(beyond.report().worst_window_share, 7.0 / 16.0);
}

TEST(TrackingMonitor, ARecoveryEndsThePoorTime) {
  // Zeros from 10 to 20 s: with G ones of 16 the window is poor once G <= 7,
  // G = 8 (12 - t) - 1, from 11.0 s; after 20 s it holds 8 (t - 20) + 1
  // ones, 8 at 20.875 s: no longer poor. Poor from 11.0 to 20.875 s.
  TrackingMonitor monitor;
  Feed(&monitor, 8.0, 40.0, [](double t) { return t >= 10.0 && t < 20.0 ? 0.0 : 1.0; });
  const TrackingReport& r = monitor.report();
  ASSERT_TRUE(r.lost());
  EXPECT_DOUBLE_EQ(r.first_poor_time_s, 11.0);
  EXPECT_DOUBLE_EQ(r.poor_s, 9.875);
  EXPECT_DOUBLE_EQ(r.worst_window_share, 0.0);
}

TEST(TrackingMonitor, APoorWindowCountsAtMostAWindowAcrossAGap) {
  // Zeros throughout with no scan from 10 to 30 s: the gap after the last
  // poor scan before it counts 2 s, not 20.
  TrackingMonitor monitor;
  Feed(&monitor, 8.0, 40.0, [](double) { return 0.0; });
  const double with_scans = monitor.report().poor_s;
  TrackingMonitor gapped;
  for (int k = 0; k / 8.0 < 40.0; ++k) {
    const double t = k / 8.0;
    if (t < 10.0 || t >= 30.0) gapped.Add(t, 0.0);
  }
  // Judged from 2.0 s: 39.875 - 2.0 s with every scan. Without those of
  // 10-30 s: 9.875 - 2.0 s, then 2 s for the gap, and from 30.5 s on (the
  // window holds kMinScans again: 30.0-30.5 s) to 39.875 s.
  EXPECT_DOUBLE_EQ(with_scans, 39.875 - 2.0);
  EXPECT_DOUBLE_EQ(gapped.report().poor_s, (9.875 - 2.0) + 2.0 + (39.875 - 30.5));
}

TEST(TrackingMonitor, ARecordingShorterThanTheWindowIsNotJudged) {
  TrackingMonitor monitor;
  Feed(&monitor, 8.0, 1.9, [](double) { return 0.0; });
  const TrackingReport& r = monitor.report();
  EXPECT_EQ(r.scans, 16u);
  EXPECT_FALSE(r.lost());
  EXPECT_LT(r.worst_window_time_s, 0.0);
}

TEST(TrackingMonitor, TooFewScansInAWindowAreNotJudged) {
  // Two scans a second: a 2 s window holds 4, fewer than kMinScans.
  TrackingMonitor monitor;
  Feed(&monitor, 2.0, 60.0, [](double) { return 0.0; });
  EXPECT_FALSE(monitor.report().lost());
}

TEST(TrackingMonitor, ATimeGoingBackRestartsTheWindow) {
  TrackingMonitor monitor;
  Feed(&monitor, 8.0, 1.9, [](double) { return 0.0; });
  // Back to 0 s with ones: without the restart, the window at 2.0 s would
  // also hold the earlier zeros (a mean of 17 / 32).
  Feed(&monitor, 8.0, 10.0, [](double) { return 1.0; });
  const TrackingReport& r = monitor.report();
  EXPECT_FALSE(r.lost());
  EXPECT_DOUBLE_EQ(r.worst_window_share, 1.0);
}

TEST(TrackingMonitor, SharesAreClampedAndNonFiniteCountsZero) {
  // One scan in four at 3.0, the others at 0: clamped, a mean of 0.25
  // (poor); unclamped it would be 0.75.
  TrackingMonitor clamped;
  int k = 0;
  Feed(&clamped, 8.0, 10.0, [&](double) { return (k++ % 4 == 0) ? 3.0 : 0.0; });
  ASSERT_TRUE(clamped.report().lost());
  EXPECT_DOUBLE_EQ(clamped.report().worst_window_share, 0.25);
  TrackingMonitor nan;
  Feed(&nan, 8.0, 10.0, [](double) { return std::numeric_limits<double>::quiet_NaN(); });
  ASSERT_TRUE(nan.report().lost());
  EXPECT_DOUBLE_EQ(nan.report().worst_window_share, 0.0);
}

}  // namespace
}  // namespace unimap::pipeline
