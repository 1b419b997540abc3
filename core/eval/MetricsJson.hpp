#pragma once
// metrics.json: the TrajectoryMetrics fields as one flat JSON object.
#include <string>
#include <vector>

#include "eval/MetricRows.hpp"
#include "eval/TrajectoryMetrics.hpp"

namespace unimap::eval {

// The JSON text (nlohmann-json; keys = TrajectoryMetrics field names,
// vectors as [x, y, z] arrays, numbers in shortest round-trip form,
// non-finite numbers and empty optionals as null), then the extra metrics'
// keys in order.
std::string MetricsToJson(const TrajectoryMetrics& metrics, const std::vector<ExtraMetric>& extra = {});

// Every key MetricsToJson writes, in output order.
std::vector<std::string> MetricsJsonKeys();

}  // namespace unimap::eval
