#include "eval/MetricsJson.hpp"

#include <cmath>
#include <functional>
#include <utility>

#include <nlohmann/json.hpp>

namespace unimap::eval {
namespace {

using Json = nlohmann::ordered_json;
using Formatter = std::function<Json(const TrajectoryMetrics&)>;

// Non-finite numbers and empty optionals are null.
Json Number(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

Json Optional(const std::optional<double>& value) { return value ? Number(*value) : Json(nullptr); }

Json Vector(const Eigen::Vector3d& v) { return Json::array({Number(v.x()), Number(v.y()), Number(v.z())}); }

// (key, formatter) for every field, in output order.
const std::vector<std::pair<std::string, Formatter>>& Fields() {
  using M = TrajectoryMetrics;
  static const std::vector<std::pair<std::string, Formatter>> fields = {
      {"ate_rmse_m", [](const M& m) { return Number(m.ate_rmse_m); }},
      {"trajectory_scale", [](const M& m) { return Optional(m.trajectory_scale); }},
      {"path_length_m", [](const M& m) { return Number(m.path_length_m); }},
      {"drift_percent", [](const M& m) { return Optional(m.drift_percent); }},
      {"max_abs_error_m", [](const M& m) { return Vector(m.max_abs_error_m); }},
      {"mean_abs_rot_error_deg", [](const M& m) { return Vector(m.mean_abs_rot_error_deg); }},
      {"rot_drift_deg_per_m", [](const M& m) { return Optional(m.rot_drift_deg_per_m); }},
      {"rpe_trans_percent", [](const M& m) { return Optional(m.rpe_trans_percent); }},
      {"rpe_rot_deg_per_m", [](const M& m) { return Optional(m.rpe_rot_deg_per_m); }},
      {"rpe_segments", [](const M& m) { return Json(m.rpe_segments); }},
      {"final_position_error_m", [](const M& m) { return Number(m.final_position_error_m); }},
      {"final_rot_error_deg", [](const M& m) { return Number(m.final_rot_error_deg); }},
      {"poses_associated", [](const M& m) { return Json(m.poses_associated); }},
      {"poses_skipped", [](const M& m) { return Json(m.poses_skipped); }},
      {"poses_outside_truth_span", [](const M& m) { return Json(m.poses_outside_truth_span); }},
      {"poses_in_truth_gaps", [](const M& m) { return Json(m.poses_in_truth_gaps); }},
      {"duration_s", [](const M& m) { return Number(m.duration_s); }},
      {"max_time_diff_s", [](const M& m) { return Number(m.max_time_diff_s); }},
      {"segment_m", [](const M& m) { return Number(m.segment_m); }},
  };
  return fields;
}

}  // namespace

std::string MetricsToJson(const TrajectoryMetrics& metrics, const std::vector<ExtraMetric>& extra) {
  Json json = Json::object();
  for (const auto& field : Fields()) json[field.first] = field.second(metrics);
  for (const ExtraMetric& m : extra) json[m.row.key] = m.value;
  return json.dump(2) + "\n";
}

std::vector<std::string> MetricsJsonKeys() {
  std::vector<std::string> keys;
  for (const auto& field : Fields()) keys.push_back(field.first);
  return keys;
}

}  // namespace unimap::eval
