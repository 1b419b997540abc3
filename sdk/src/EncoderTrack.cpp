#include "unimap/EncoderTrack.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <sstream>

#include "unimap/Errors.hpp"

namespace unimap {
namespace {

// Wraps an angle difference into [-pi, pi).
double WrapDelta(double delta_rad) {
  double wrapped = std::fmod(delta_rad + M_PI, 2.0 * M_PI);
  if (wrapped < 0.0) wrapped += 2.0 * M_PI;
  return wrapped - M_PI;
}

std::string Describe(double time_s) {
  std::ostringstream out;
  out.precision(17);
  out << time_s;
  return out.str();
}

}  // namespace

EncoderTrack::EncoderTrack(const std::vector<EncoderSample>& samples, double max_gap_s) : max_gap_s_(max_gap_s) {
  if (!(max_gap_s > 0.0)) throw InputError("encoder: max_gap_s must be positive");
  times_s_.reserve(samples.size());
  unwrapped_rad_.reserve(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    try {
      Append(samples[i]);
    } catch (const InputError& e) {
      throw InputError("encoder sample " + std::to_string(i) + ": " + e.what());
    }
  }
}

void EncoderTrack::Append(const EncoderSample& sample) {
  if (!std::isfinite(sample.time_s) || !std::isfinite(sample.angle_rad)) {
    throw InputError("non-finite time or angle");
  }
  if (times_s_.empty()) {
    times_s_.push_back(sample.time_s);
    unwrapped_rad_.push_back(sample.angle_rad);
    last_raw_rad_ = sample.angle_rad;
    return;
  }
  if (!(sample.time_s > times_s_.back())) {
    throw InputError("time going backwards (" + Describe(sample.time_s) + " s after " + Describe(times_s_.back()) +
                     " s)");
  }
  // Unwrap: the true rotation between consecutive samples is less than pi.
  const double step = WrapDelta(sample.angle_rad - last_raw_rad_);
  unwrapped_rad_.push_back(unwrapped_rad_.back() + step);
  times_s_.push_back(sample.time_s);
  last_raw_rad_ = sample.angle_rad;
}

void EncoderTrack::DropBefore(double time_s) {
  // Keep the last sample at or before time_s: it brackets time_s.
  const auto it = std::upper_bound(times_s_.begin(), times_s_.end(), time_s);
  if (it == times_s_.begin()) return;
  const auto keep_from = std::distance(times_s_.begin(), it) - 1;
  times_s_.erase(times_s_.begin(), times_s_.begin() + keep_from);
  unwrapped_rad_.erase(unwrapped_rad_.begin(), unwrapped_rad_.begin() + keep_from);
}

double EncoderTrack::start_time_s() const { return times_s_.front(); }

double EncoderTrack::end_time_s() const { return times_s_.back(); }

bool EncoderTrack::Covers(double time_s) const {
  if (times_s_.empty() || !(time_s >= times_s_.front()) || !(time_s <= times_s_.back())) return false;
  const auto it = std::lower_bound(times_s_.begin(), times_s_.end(), time_s);
  if (*it == time_s) return true;
  return *it - *(it - 1) <= max_gap_s_;
}

double EncoderTrack::AngleAt(double time_s) const {
  if (times_s_.empty()) {
    throw InputError("no encoder samples cover time " + Describe(time_s) + " s");
  }
  if (!(time_s >= times_s_.front()) || !(time_s <= times_s_.back())) {
    throw InputError("time " + Describe(time_s) + " s is outside encoder coverage [" + Describe(times_s_.front()) +
                     ", " + Describe(times_s_.back()) + "] s");
  }
  const auto it = std::lower_bound(times_s_.begin(), times_s_.end(), time_s);
  const std::size_t i1 = static_cast<std::size_t>(std::distance(times_s_.begin(), it));
  if (times_s_[i1] == time_s) return unwrapped_rad_[i1];
  const std::size_t i0 = i1 - 1;
  const double dt = times_s_[i1] - times_s_[i0];
  if (dt > max_gap_s_) {
    throw InputError("time " + Describe(time_s) + " s falls in an encoder gap of " + Describe(dt) + " s");
  }
  // Linear interpolation of the unwrapped angle.
  const double alpha = (time_s - times_s_[i0]) / dt;
  return unwrapped_rad_[i0] + alpha * (unwrapped_rad_[i1] - unwrapped_rad_[i0]);
}

}  // namespace unimap
