#pragma once
#include <cstddef>
#include <deque>

namespace unimap::pipeline {

// What TrackingMonitor saw over a run.
struct TrackingReport {
  std::size_t scans = 0;              // scans fed (every scan tried against a map)
  double first_time_s = -1.0;         // the first one's time (-1: none)
  double first_poor_time_s = -1.0;    // first scan whose window was poor (-1: none)
  double poor_s = 0.0;                // from each poor window's scan to the next scan fed, at most kWindowS each (s)
  double worst_window_share = 1.0;    // lowest judged window's mean inlier share (1: none judged)
  double worst_window_time_s = -1.0;  // the scan that closed it (-1: none judged)
  bool lost() const { return first_poor_time_s >= 0.0; }
};

// Tells, without ground truth, when the odometry stopped explaining the
// scans: the mean inlier share (ScanMatchResult::inliers: the share of a
// scan's points within the reacquisition's inlier distance of the map at
// the matched pose) of the scans in the window (time - kWindowS, time]
// falls below kMinInlierShare. A scan tried against a map whose match was
// not used counts 0. Windows are judged once the monitor has run for
// kWindowS and when they hold kMinScans scans, so a short recording (less
// than kWindowS) or sparse scans are never judged. The poor time starts
// when the mean falls below, which lags the drop it follows (by up to a
// window).
// docs/robustness.md ("Telling that the odometry was lost") has the
// measurements behind the two values.
class TrackingMonitor {
 public:
  // The window (s): a few seconds of a run that keeps tracking dip only briefly.
  static constexpr double kWindowS = 2.0;
  // Poor below this mean share: most of the scan off the map (ScanMatcher's
  // poor-match share for sweeps).
  static constexpr double kMinInlierShare = 0.5;
  // A window needs this many scans to be judged.
  static constexpr std::size_t kMinScans = 5;

  // One scan at time_s (non-decreasing; an earlier time restarts the
  // window) with its inlier share in [0, 1] (clamped).
  void Add(double time_s, double inlier_share);
  const TrackingReport& report() const { return report_; }

 private:
  struct Sample {
    double time_s;
    double share;
  };
  std::deque<Sample> window_;
  double start_s_ = 0.0;        // the first scan's time since the last restart
  bool previous_poor_ = false;  // the last scan's window was poor (the window then holds that scan last)
  TrackingReport report_;
};

}  // namespace unimap::pipeline
