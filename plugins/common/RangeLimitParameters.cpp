#include "RangeLimitParameters.hpp"

#include "unimap/Errors.hpp"

namespace unimap::payload {
namespace {
constexpr const char* kMinRange = "lidar.min_range_m";
constexpr const char* kMaxRange = "lidar.max_range_m";
}  // namespace

void RangeLimitParameters::AddTo(const RangeLimits& defaults, ParameterSet* set) {
  set->Add({kMinRange,
            "",
            "shortest valid return; closer ones are dropped and counted (m)",
            defaults.min_range_m,
            0.0,
            1000.0,
            {}});
  set->Add({kMaxRange,
            "",
            "longest valid return; farther ones are dropped and counted (m)",
            defaults.max_range_m,
            0.01,
            10000.0,
            {}});
}

RangeLimits RangeLimitParameters::FromMap(const ParameterMap& map) {
  RangeLimits limits;
  limits.min_range_m = map.GetDouble(kMinRange);
  limits.max_range_m = map.GetDouble(kMaxRange);
  if (!(limits.min_range_m >= 0.0)) throw ConfigError("", 0, kMinRange, "must be at least 0");
  if (!(limits.max_range_m > limits.min_range_m)) {
    throw ConfigError("", 0, kMaxRange, "must be greater than lidar.min_range_m");
  }
  return limits;
}

}  // namespace unimap::payload
