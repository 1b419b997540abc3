#pragma once
#include <cstddef>
#include <filesystem>
#include <string>

#include "io/DatasetLimits.hpp"

namespace unimap::io {

// A recording read directly (DatasetReader's raw-input constructor): the
// checks a dataset folder's stream makes while it is read (the value's
// plausibility, |time| and the step from the previous item), for one
// stream, naming the input, the stream and the item.
class LiveStreamCheck {
 public:
  // stream: "imu", "encoder", ...; max_step_s: the largest step between items.
  LiveStreamCheck(const char* stream, double max_step_s) : stream_(stream), max_step_s_(max_step_s) {}

  // Throws InputError ("INPUT: imu item 301 (time 12.5 s): <why>") when
  // `problem` (a DatasetLimits::*Problem text) is not empty, |time_s| is
  // beyond limits.max_abs_time_s or time_s is more than max_step_s after the
  // previous item's.
  void Check(const std::filesystem::path& input, const DatasetLimits& limits, double time_s,
             const std::string& problem);

 private:
  const char* stream_;
  double max_step_s_;
  std::size_t count_ = 0;  // items checked
  double last_s_ = 0.0;    // time of the previous item
  bool has_last_ = false;
};

}  // namespace unimap::io
