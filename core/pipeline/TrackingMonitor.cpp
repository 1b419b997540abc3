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
  }
  if (report_.scans++ == 0) report_.first_time_s = time_s;
  // A poor window goes on until this scan: the time between them counts as poor.
  if (previous_poor_) report_.poor_s += time_s - previous_time_s_;
  window_.push_back({time_s, share});
  // Keep the scans of the last kWindowS seconds (the oldest exactly at the edge included).
  while (window_.size() > 1 && window_[1].time_s <= time_s - kWindowS) window_.pop_front();
  previous_time_s_ = time_s;
  const bool full = time_s - window_.front().time_s >= kWindowS && window_.size() >= kMinScans;
  previous_poor_ = false;
  if (!full) return;
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
