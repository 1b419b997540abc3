#include "pipeline/TrackingMonitor.hpp"

#include <algorithm>
#include <cmath>

namespace unimap::pipeline {

void TrackingMonitor::Add(double time_s, double inlier_share) {
  if (!std::isfinite(time_s)) return;
  const double share = std::isfinite(inlier_share) ? std::clamp(inlier_share, 0.0, 1.0) : 0.0;
  if (!window_.empty() && time_s < window_.back().time_s) {  // out of order: start again
    window_.clear();
    previous_poor_ = false;
    start_s_ = time_s;
  }
  if (report_.scans++ == 0) {
    report_.first_time_s = time_s;
    start_s_ = time_s;
  }
  // A poor window goes on until the next scan (for at most a window).
  if (previous_poor_) report_.poor_s += std::min(time_s - window_.back().time_s, kWindowS);
  previous_poor_ = false;
  // The scans of the last kWindowS seconds: (time_s - kWindowS, time_s].
  window_.push_back({time_s, share});
  while (window_.front().time_s <= time_s - kWindowS) window_.pop_front();
  // Judged once the monitor has run for a window and the window holds enough scans.
  if (time_s - start_s_ < kWindowS || window_.size() < kMinScans) return;
  // Summed afresh (a window holds a few dozen scans): a running sum would
  // keep rounding residue where every share is 0.
  double sum = 0.0;
  for (const Sample& sample : window_) sum += sample.share;
  const double mean = sum / static_cast<double>(window_.size());
  if (report_.worst_window_time_s < 0.0 || mean < report_.worst_window_share) {
    report_.worst_window_share = mean;
    report_.worst_window_time_s = time_s;
  }
  if (mean < kMinInlierShare) {
    previous_poor_ = true;
    if (report_.first_poor_time_s < 0.0) report_.first_poor_time_s = time_s;
  }
}

}  // namespace unimap::pipeline
