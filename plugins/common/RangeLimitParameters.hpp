#pragma once
#include "unimap/Deskew.hpp"
#include "unimap/ParameterMap.hpp"
#include "unimap/ParameterSet.hpp"

namespace unimap::payload {

// The scanner's valid range window as platform keys "lidar.min_range_m" and
// "lidar.max_range_m" (shared by every payload; returns outside are dropped
// and counted by DeskewScan).
struct RangeLimitParameters {
  // Adds the two keys with `defaults` as default values.
  static void AddTo(const RangeLimits& defaults, ParameterSet* set);
  // Reads the two keys; throws ConfigError unless 0 <= min < max.
  static RangeLimits FromMap(const ParameterMap& map);
};

}  // namespace unimap::payload
