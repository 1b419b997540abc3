#pragma once
#include <cstddef>
#include <limits>
#include <vector>

#include "unimap/EncoderSample.hpp"
#include "unimap/Export.hpp"

namespace unimap {

// Motor encoder readings as a continuous angle over time. Raw angles may wrap
// in any convention; consecutive samples are assumed less than pi apart in
// true rotation, so the track unwraps them. The angle between samples is
// linearly interpolated, which is exact for constant-rate rotation whatever
// the sample spacing.
class UNIMAP_SDK_API EncoderTrack {
 public:
  // An empty track: covers no time.
  EncoderTrack() = default;
  // Throws InputError naming the sample index for a non-finite value or a
  // time that does not increase. max_gap_s: longer gaps are not covered.
  explicit EncoderTrack(const std::vector<EncoderSample>& samples,
                        double max_gap_s = std::numeric_limits<double>::infinity());

  // Appends one reading (same checks as the constructor).
  void Append(const EncoderSample& sample);
  // Drops samples no longer needed to answer times >= time_s.
  void DropBefore(double time_s);

  bool empty() const { return times_s_.empty(); }
  std::size_t size() const { return times_s_.size(); }
  double start_time_s() const;  // first sample time; requires !empty()
  double end_time_s() const;    // last sample time; requires !empty()
  // True when AngleAt(time_s) would return a value.
  bool Covers(double time_s) const;
  // Unwrapped angle (rad) at time_s; throws InputError outside
  // [start_time_s, end_time_s] or inside a gap longer than max_gap_s.
  double AngleAt(double time_s) const;

 private:
  double max_gap_s_ = std::numeric_limits<double>::infinity();
  std::vector<double> times_s_;
  std::vector<double> unwrapped_rad_;
  double last_raw_rad_ = 0.0;
};

}  // namespace unimap
