#include "report/RunSections.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

#include "eval/MetricRows.hpp"
#include "eval/TrajectoryMetrics.hpp"
#include "report/MetricLabels.hpp"

namespace unimap::report {
namespace {

using Json = nlohmann::ordered_json;

std::string WithSeparators(long long value) {
  const std::string digits = std::to_string(value < 0 ? -value : value);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return value < 0 ? "-" + out : out;
}

std::string Number(double value) {
  if (!std::isfinite(value)) return "n/a";
  char buffer[64];
  if (std::abs(value) >= 1000.0) {
    return WithSeparators(std::llround(value));
  }
  std::snprintf(buffer, sizeof(buffer), "%.4g", value);
  const std::string text = buffer;
  return text == "-0" ? "0" : text;
}

// A displayed value: named after key (relative to its table), shown with the JSON path json_path.
Json Row(const std::string& key, const std::string& json_path, const Json& value) {
  const MetricLabel label = LabelFor(key);
  return Json{{"label", label.label}, {"value", DisplayValue(value)}, {"unit", label.unit}, {"key", json_path}};
}

bool IsStringArray(const Json& value) {
  if (!value.is_array()) return false;
  for (const Json& item : value) {
    if (!item.is_string()) return false;
  }
  return true;
}

// Rows of an object's values, nested objects flattened to "prefix.key";
// string arrays named "messages" go to messages instead.
void Flatten(const Json& object, const std::string& prefix, const std::string& source, Json* rows, Json* messages) {
  for (const auto& [key, value] : object.items()) {
    const std::string path = prefix.empty() ? key : prefix + "." + key;
    if (key == "messages" && IsStringArray(value)) {
      for (const Json& text : value) messages->push_back(Json{{"source", source}, {"text", text}});
    } else if (value.is_object()) {
      Flatten(value, path, source, rows, messages);
    } else {
      rows->push_back(Row(path, source + "." + path, value));
    }
  }
}

// The headline figures: run.json key paths and metrics.json keys, those present.
Json Cards(const Json& run, const Json& metrics) {
  struct Card {
    const Json* file;
    std::vector<std::string> path;
  };
  const std::vector<Card> cards = {
      {&run, {"payload"}},
      {&run, {"motion"}},
      {&run, {"realtime_factor"}},
      {&run, {"data_duration_s"}},
      {&run, {"peak_rss_mb"}},
      {&run, {"mapping", "submaps"}},
      {&run, {"mapping", "loop_closures"}},
      {&metrics, {"ate_rmse_m"}},
      {&run, {"position_rmse_m"}},
      {&metrics, {"map_error_aligned_mean_m"}},
      {&run, {"mapping", "map_quality", "mean_plane_variance_m2"}},
      {&run, {"mapping", "map_quality", "mean_map_entropy"}},
      {&run, {"localizer", "tracking", "lost"}},
  };
  Json out = Json::array();
  for (const Card& card : cards) {
    const Json* node = card.file;
    for (const std::string& key : card.path) {
      const auto it = node->is_object() ? node->find(key) : node->end();
      node = it != node->end() ? &*it : nullptr;
      if (node == nullptr) break;
    }
    if (node == nullptr || node->is_null() || node->is_object()) continue;
    std::string key;
    for (const std::string& part : card.path) key += (key.empty() ? "" : ".") + part;
    out.push_back(Row(card.path.back(), key, *node));
  }
  return out;
}

Json Parameters(const Json& run) {
  Json out = Json::array();
  const auto it = run.find("parameters");
  if (it == run.end() || !it->is_object()) return out;
  for (const auto& [key, p] : it->items()) {
    if (!p.is_object()) {
      out.push_back(Json{{"key", key}, {"symbol", ""}, {"value", DisplayValue(p)}, {"source", ""}, {"meaning", ""}});
      continue;
    }
    out.push_back(Json{{"key", key},
                       {"symbol", p.contains("symbol") ? DisplayValue(p["symbol"]) : ""},
                       {"value", p.contains("value") ? DisplayValue(p["value"]) : ""},
                       {"source", p.contains("source") ? DisplayValue(p["source"]) : ""},
                       {"meaning", p.contains("meaning") ? DisplayValue(p["meaning"]) : ""}});
  }
  return out;
}

Json MetricTable(const Json& metrics) {
  std::vector<eval::MetricRow> described = eval::DescribeMetrics(eval::TrajectoryMetrics{});
  Json out = Json::array();
  for (const auto& [key, value] : metrics.items()) {
    Json row = Row(key, key, value);
    std::string meaning;
    for (const eval::MetricRow& d : described) {
      if (d.key == key) meaning = d.meaning;
    }
    row["meaning"] = meaning;
    out.push_back(row);
  }
  return out;
}

}  // namespace

std::string DisplayValue(const Json& value) {
  if (value.is_null()) return "n/a";
  if (value.is_boolean()) return value.get<bool>() ? "yes" : "no";
  if (value.is_number_integer()) return WithSeparators(value.get<long long>());
  if (value.is_number_unsigned()) return WithSeparators(static_cast<long long>(value.get<unsigned long long>()));
  if (value.is_number()) return Number(value.get<double>());
  if (value.is_string()) return value.get<std::string>();
  if (value.is_array()) {
    std::string out;
    for (const Json& item : value) out += (out.empty() ? "" : " / ") + DisplayValue(item);
    return out;
  }
  return value.dump();
}

Json RunSections(const Json& run, const Json& metrics) {
  Json sections = Json::array();
  Json messages = Json::array();
  Json top_rows = Json::array();
  for (const auto& [key, value] : run.items()) {
    if (key == "parameters") continue;
    if (value.is_object()) {
      Json rows = Json::array();
      Flatten(value, "", key, &rows, &messages);
      if (!rows.empty()) {
        sections.push_back(Json{{"title", LabelFor(key).label}, {"key", key}, {"rows", rows}});
      }
    } else if (key == "messages" && IsStringArray(value)) {
      for (const Json& text : value) messages.push_back(Json{{"source", "run"}, {"text", text}});
    } else {
      top_rows.push_back(Row(key, key, value));
    }
  }
  if (!top_rows.empty()) sections.insert(sections.begin(), Json{{"title", "Run"}, {"key", ""}, {"rows", top_rows}});
  return Json{{"cards", Cards(run, metrics)},
              {"sections", sections},
              {"parameters", Parameters(run)},
              {"messages", messages},
              {"metrics", MetricTable(metrics)}};
}

}  // namespace unimap::report
