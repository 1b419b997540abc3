#pragma once
// The metrics as human-readable rows (terminal table and HTML report).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "eval/TrajectoryMetrics.hpp"

namespace unimap::eval {

// One displayed metric.
struct MetricRow {
  std::string key;      // the metrics.json key
  std::string value;    // formatted value ("n/a" for an undefined one)
  std::string meaning;  // one-line definition with unit
};

// A metric beyond the trajectory's (e.g. the map error): its metrics.json
// value and its displayed row.
struct ExtraMetric {
  nlohmann::ordered_json value;  // its metrics.json value (a number, or null)
  MetricRow row;                 // key, display value, meaning
};

// Rows for every metrics.json key, in the same order, values rounded for
// display (4 significant decimals; the JSON keeps full precision).
std::vector<MetricRow> DescribeMetrics(const TrajectoryMetrics& metrics);

}  // namespace unimap::eval
