#include "eval/MetricsJson.hpp"

#include <charconv>
#include <cmath>
#include <functional>
#include <utility>

namespace unimap::eval {
namespace {

using Formatter = std::function<std::string(const TrajectoryMetrics&)>;

std::string Optional(const std::optional<double>& value) {
  return value ? JsonNumber(*value) : std::string("null");
}

std::string Vector(const Eigen::Vector3d& v) {
  return "[" + JsonNumber(v.x()) + ", " + JsonNumber(v.y()) + ", " + JsonNumber(v.z()) + "]";
}

// (key, formatter) for every field, in output order.
const std::vector<std::pair<std::string, Formatter>>& Fields() {
  using M = TrajectoryMetrics;
  static const std::vector<std::pair<std::string, Formatter>> fields = {
      {"ate_rmse_m", [](const M& m) { return JsonNumber(m.ate_rmse_m); }},
      {"trajectory_scale", [](const M& m) { return Optional(m.trajectory_scale); }},
      {"path_length_m", [](const M& m) { return JsonNumber(m.path_length_m); }},
      {"drift_percent", [](const M& m) { return Optional(m.drift_percent); }},
      {"max_abs_error_m", [](const M& m) { return Vector(m.max_abs_error_m); }},
      {"mean_abs_rot_error_deg", [](const M& m) { return Vector(m.mean_abs_rot_error_deg); }},
      {"rot_drift_deg_per_m", [](const M& m) { return Optional(m.rot_drift_deg_per_m); }},
      {"rpe_trans_percent", [](const M& m) { return Optional(m.rpe_trans_percent); }},
      {"rpe_rot_deg_per_m", [](const M& m) { return Optional(m.rpe_rot_deg_per_m); }},
      {"rpe_segments", [](const M& m) { return std::to_string(m.rpe_segments); }},
      {"final_position_error_m", [](const M& m) { return JsonNumber(m.final_position_error_m); }},
      {"final_rot_error_deg", [](const M& m) { return JsonNumber(m.final_rot_error_deg); }},
      {"poses_associated", [](const M& m) { return std::to_string(m.poses_associated); }},
      {"poses_skipped", [](const M& m) { return std::to_string(m.poses_skipped); }},
      {"poses_outside_truth_span", [](const M& m) { return std::to_string(m.poses_outside_truth_span); }},
      {"poses_in_truth_gaps", [](const M& m) { return std::to_string(m.poses_in_truth_gaps); }},
      {"duration_s", [](const M& m) { return JsonNumber(m.duration_s); }},
      {"max_time_diff_s", [](const M& m) { return JsonNumber(m.max_time_diff_s); }},
      {"segment_m", [](const M& m) { return JsonNumber(m.segment_m); }},
  };
  return fields;
}

}  // namespace

std::string JsonNumber(double value) {
  if (!std::isfinite(value)) return "null";
  if (value == 0.0) return "0";  // also turns -0 into 0
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

std::string MetricsToJson(const TrajectoryMetrics& metrics, const std::vector<ExtraMetric>& extra) {
  std::vector<std::pair<std::string, std::string>> entries;
  for (const auto& field : Fields()) entries.emplace_back(field.first, field.second(metrics));
  for (const ExtraMetric& m : extra) entries.emplace_back(m.row.key, m.json);
  std::string json = "{\n";
  for (std::size_t i = 0; i < entries.size(); ++i) {
    json += "  \"" + entries[i].first + "\": " + entries[i].second;
    json += i + 1 < entries.size() ? ",\n" : "\n";
  }
  return json + "}\n";
}

std::vector<std::string> MetricsJsonKeys() {
  std::vector<std::string> keys;
  for (const auto& field : Fields()) keys.push_back(field.first);
  return keys;
}

}  // namespace unimap::eval
