#include "io/DatasetMetadata.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "io/NumberText.hpp"
#include "io/PartialFile.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

constexpr int kFormatVersion = 1;  // the layout this build reads and writes
// Most payload parameters metadata.yaml may hold: a bound on what YAML
// aliases (`*a` repeating a group) can expand to.
constexpr std::size_t kMaxParameters = 10000;

// Top-level keys in the order they are written.
const char* const kKeys[] = {"format_version",
                             "source",
                             "payload",
                             "scenario",
                             "seed",
                             "duration_s",
                             "imu_rate_hz",
                             "encoder_rate_hz",
                             "scan_rate_hz",
                             "gravity_m_s2",
                             "sigma_accel_m_s2",
                             "sigma_gyro_rad_s",
                             "accel_bias_walk_m_s2_sqrt_s",
                             "gyro_bias_walk_rad_s_sqrt_s",
                             "range_noise_m",
                             "encoder_resolution_rad",
                             "payload_parameters",
                             "camera_from_lidar"};

// The double fields of DatasetMetadata, by key.
std::vector<std::pair<const char*, double DatasetMetadata::*>> DoubleFields() {
  return {{"duration_s", &DatasetMetadata::duration_s},
          {"imu_rate_hz", &DatasetMetadata::imu_rate_hz},
          {"encoder_rate_hz", &DatasetMetadata::encoder_rate_hz},
          {"scan_rate_hz", &DatasetMetadata::scan_rate_hz},
          {"gravity_m_s2", &DatasetMetadata::gravity_m_s2},
          {"sigma_accel_m_s2", &DatasetMetadata::sigma_accel_m_s2},
          {"sigma_gyro_rad_s", &DatasetMetadata::sigma_gyro_rad_s},
          {"accel_bias_walk_m_s2_sqrt_s", &DatasetMetadata::accel_bias_walk_m_s2_sqrt_s},
          {"gyro_bias_walk_rad_s_sqrt_s", &DatasetMetadata::gyro_bias_walk_rad_s_sqrt_s},
          {"range_noise_m", &DatasetMetadata::range_noise_m},
          {"encoder_resolution_rad", &DatasetMetadata::encoder_resolution_rad}};
}

// ---- writing ---------------------------------------------------------------

// A double as a YAML scalar that reads back as exactly this double (never as
// an integer): shortest round-trip digits, ".0" added when they look whole.
std::string YamlDouble(double value) {
  if (std::isnan(value)) return ".nan";
  if (std::isinf(value)) return value > 0 ? ".inf" : "-.inf";
  std::string text;
  AppendNumber(&text, value);
  if (text.find_first_of(".eE") == std::string::npos) text += ".0";
  return text;
}

// Emits one parameter value with its type kept: strings always quoted.
struct ValueEmitter {
  YAML::Emitter* out;
  void operator()(bool v) const { *out << (v ? "true" : "false"); }
  void operator()(std::int64_t v) const { *out << std::to_string(v); }
  void operator()(double v) const { *out << YamlDouble(v); }
  void operator()(const std::string& v) const { *out << YAML::DoubleQuoted << v; }
  void operator()(const std::vector<double>& v) const {
    *out << YAML::Flow << YAML::BeginSeq;
    for (const double x : v) *out << YamlDouble(x);
    *out << YAML::EndSeq;
  }
};

std::vector<std::string> SplitKey(const std::string& key, const std::string& file) {
  std::vector<std::string> parts;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t dot = key.find('.', begin);
    parts.push_back(key.substr(begin, dot == std::string::npos ? std::string::npos : dot - begin));
    if (parts.back().empty()) {
      throw ConfigError(file, 0, key, "a payload parameter key cannot have an empty part");
    }
    if (dot == std::string::npos) return parts;
    begin = dot + 1;
  }
}

// payload_parameters as nested maps: "a.b.c: 1" becomes a: {b: {c: 1}}. The
// map is sorted, so the keys sharing a prefix are contiguous and each group
// is opened once.
void EmitParameters(YAML::Emitter& out, const ParameterMap& parameters, const std::string& file) {
  const auto& values = parameters.values();
  for (const auto& [key, value] : values) {
    for (std::size_t dot = key.find('.'); dot != std::string::npos; dot = key.find('.', dot + 1)) {
      if (values.count(key.substr(0, dot)) != 0) {
        throw ConfigError(file, 0, key, "'" + key.substr(0, dot) + "' is both a value and a group of values");
      }
    }
  }
  out << YAML::BeginMap;
  std::vector<std::string> open;  // path of the groups currently open
  for (const auto& [key, value] : values) {
    const std::vector<std::string> parts = SplitKey(key, file);
    std::size_t common = 0;
    while (common < open.size() && common + 1 < parts.size() && open[common] == parts[common]) {
      ++common;
    }
    for (; open.size() > common; open.pop_back()) out << YAML::EndMap;
    for (std::size_t i = common; i + 1 < parts.size(); ++i) {
      out << YAML::Key << parts[i] << YAML::Value << YAML::BeginMap;
      open.push_back(parts[i]);
    }
    out << YAML::Key << parts.back() << YAML::Value;
    std::visit(ValueEmitter{&out}, value);
  }
  for (; !open.empty(); open.pop_back()) out << YAML::EndMap;
  out << YAML::EndMap;
}

// ---- reading ---------------------------------------------------------------

int LineOf(const YAML::Node& node) { return node.Mark().line >= 0 ? node.Mark().line + 1 : 0; }

// Quotes or a !!str tag make a scalar a string whatever it reads.
bool IsQuoted(const YAML::Node& node) { return node.Tag() == "!" || node.Tag() == "tag:yaml.org,2002:str"; }

std::string KindOf(const YAML::Node& node) {
  if (node.IsMap()) return "a map";
  if (node.IsSequence()) return "a list";
  if (node.IsNull()) return "nothing";
  return "'" + node.Scalar() + "'";
}

template <typename Integer>
bool ParseInteger(const std::string& text, Integer* value) {
  const char* begin = text.c_str();
  const char* end = begin + text.size();
  if (begin != end && *begin == '+') ++begin;
  if (begin == end || *begin == '+' || (*begin == '-' && begin != text.c_str())) return false;
  const std::from_chars_result result = std::from_chars(begin, end, *value);
  return result.ec == std::errc() && result.ptr == end;
}

// A plain scalar typed as in platform files: integer, else decimal number
// (also YAML's .nan / .inf / -.inf), else true/false, else the text.
ParameterValue TypedScalar(const std::string& text) {
  std::int64_t whole = 0;
  if (ParseInteger(text, &whole)) return whole;
  double real = 0.0;
  if (text.find_first_not_of("0123456789+-.eE") == std::string::npos && ParseNumber(text, &real)) {
    return real;
  }
  const std::string bare = text.empty() || (text[0] != '+' && text[0] != '-') ? text : text.substr(1);
  if (bare == ".nan" || bare == ".NaN" || bare == ".NAN") return std::nan("");
  if (bare == ".inf" || bare == ".Inf" || bare == ".INF") {
    return text[0] == '-' ? -HUGE_VAL : HUGE_VAL;
  }
  if (text == "true" || text == "True" || text == "TRUE") return true;
  if (text == "false" || text == "False" || text == "FALSE") return false;
  return text;
}

// Reads one metadata.yaml; every error names the file, line and key.
struct Parser {
  const std::string& file;

  [[noreturn]] void Fail(const YAML::Node& node, const std::string& key, const std::string& reason) const {
    throw ConfigError(file, LineOf(node), key, reason);
  }
  ParameterValue Leaf(const YAML::Node& value, const std::string& key) const {
    if (value.IsNull()) Fail(value, key, "no value given");
    if (value.IsScalar()) return IsQuoted(value) ? value.Scalar() : TypedScalar(value.Scalar());
    if (!value.IsSequence()) Fail(value, key, "expected a value, got " + KindOf(value));
    std::vector<double> numbers;
    for (std::size_t i = 0; i < value.size(); ++i) {
      const YAML::Node element = value[i];
      const ParameterValue parsed = element.IsScalar() && !IsQuoted(element) ? TypedScalar(element.Scalar()) : false;
      if (const auto* real = std::get_if<double>(&parsed)) {
        numbers.push_back(*real);
      } else if (const auto* integer = std::get_if<std::int64_t>(&parsed)) {
        numbers.push_back(static_cast<double>(*integer));
      } else {
        Fail(element, key,
             "expected a list of numbers, but element " + std::to_string(i + 1) + " is " + KindOf(element));
      }
    }
    return numbers;
  }
  double Double(const YAML::Node& value, const std::string& key) const {
    const ParameterValue parsed = IsQuoted(value) ? ParameterValue(false) : Leaf(value, key);
    if (const auto* real = std::get_if<double>(&parsed)) return *real;
    if (const auto* integer = std::get_if<std::int64_t>(&parsed)) {
      return static_cast<double>(*integer);
    }
    Fail(value, key, "expected a number, got " + KindOf(value));
  }
  std::string String(const YAML::Node& value, const std::string& key) const {
    if (!value.IsScalar()) Fail(value, key, "expected a string, got " + KindOf(value));
    return value.Scalar();
  }
  // payload_parameters, flattened into *out; lines remembers where each key
  // was set; groups holds the maps being walked (an alias to one of them is
  // a cycle, which would recurse forever).
  void Parameters(const YAML::Node& map, const std::string& prefix, ParameterMap* out,
                  std::map<std::string, int>* lines, std::vector<YAML::Node>* groups) const {
    groups->push_back(map);
    for (auto it = map.begin(); it != map.end(); ++it) {
      const YAML::Node key_node = it->first;
      if (!key_node.IsScalar() || key_node.Scalar().empty() || key_node.Scalar().find('.') != std::string::npos) {
        Fail(key_node, prefix, "a parameter name must be a plain word without '.', got " + KindOf(key_node));
      }
      const std::string key = prefix.empty() ? key_node.Scalar() : prefix + "." + key_node.Scalar();
      const auto [previous, inserted] = lines->emplace(key, LineOf(key_node));
      if (!inserted) {
        Fail(key_node, key, "set twice (first on line " + std::to_string(previous->second) + ")");
      }
      if (lines->size() > kMaxParameters) {
        Fail(key_node, key,
             "more than " + std::to_string(kMaxParameters) + " payload parameters (YAML aliases expanding?)");
      }
      for (const YAML::Node& group : *groups) {
        if (it->second.is(group)) Fail(key_node, key, "a YAML alias refers to a group that contains it (a cycle)");
      }
      if (it->second.IsMap()) {
        if (it->second.size() == 0) Fail(key_node, key, "empty group: no value given");
        Parameters(it->second, key, out, lines, groups);
      } else {
        out->Set(key, Leaf(it->second, key));
      }
    }
    groups->pop_back();
  }
};

DatasetMetadata ParseDatasetMetadata(const std::string& yaml_text, const std::string& file) {
  const Parser parser{file};
  DatasetMetadata metadata;
  try {
    const YAML::Node root = YAML::Load(yaml_text);
    if (!root.IsMap()) parser.Fail(root, "", "expected a map of metadata keys, got " + KindOf(root));
    // The version first: a newer layout may well have keys this build does not know.
    const YAML::Node version = root["format_version"];
    if (!version) throw ConfigError(file, 0, "format_version", "missing");
    std::int64_t number = 0;
    if (!version.IsScalar() || IsQuoted(version) || !ParseInteger(version.Scalar(), &number)) {
      parser.Fail(version, "format_version", "expected a whole number, got " + KindOf(version));
    }
    if (number > kFormatVersion) {
      parser.Fail(version, "format_version",
                  "dataset format version " + std::to_string(number) + " is newer than this build reads (" +
                      std::to_string(kFormatVersion) + "); update unimap");
    }
    if (number < 1) parser.Fail(version, "format_version", "must be 1 or more");
    metadata.format_version = static_cast<int>(number);
    const auto double_fields = DoubleFields();
    std::map<std::string, int> seen;
    for (auto it = root.begin(); it != root.end(); ++it) {
      const YAML::Node key_node = it->first;
      const YAML::Node value = it->second;
      const std::string key = key_node.IsScalar() ? key_node.Scalar() : std::string();
      if (std::find(std::begin(kKeys), std::end(kKeys), key) == std::end(kKeys)) {
        parser.Fail(key_node, key, "unknown key (docs/dataset-format.md lists the keys)");
      }
      const auto [previous, inserted] = seen.emplace(key, LineOf(key_node));
      if (!inserted) {
        parser.Fail(key_node, key, "set twice (first on line " + std::to_string(previous->second) + ")");
      }
      if (key == "source") metadata.source = parser.String(value, key);
      if (key == "payload") metadata.payload = parser.String(value, key);
      if (key == "scenario") metadata.scenario = parser.String(value, key);
      if (key == "seed" && (!value.IsScalar() || IsQuoted(value) || !ParseInteger(value.Scalar(), &metadata.seed))) {
        parser.Fail(value, key, "expected a whole number >= 0, got " + KindOf(value));
      }
      for (const auto& [name, field] : double_fields) {
        if (key == name) metadata.*field = parser.Double(value, key);
      }
      if (key == "camera_from_lidar") {
        if (!value.IsSequence() || value.size() != 12) {
          parser.Fail(value, key, "expected a list of 12 numbers (3x4 row-major), got " + KindOf(value));
        }
        for (std::size_t i = 0; i < 12; ++i) metadata.camera_from_lidar.push_back(parser.Double(value[i], key));
      }
      if (key == "payload_parameters" && !value.IsNull()) {
        if (!value.IsMap()) parser.Fail(value, key, "expected a map, got " + KindOf(value));
        std::map<std::string, int> lines;
        std::vector<YAML::Node> groups;
        parser.Parameters(value, "", &metadata.payload_parameters, &lines, &groups);
      }
    }
    if (seen.count("payload") == 0) throw ConfigError(file, 0, "payload", "missing");
  } catch (const YAML::Exception& e) {
    throw ConfigError(file, e.mark.line >= 0 ? e.mark.line + 1 : 0, "", "YAML syntax error: " + e.msg);
  }
  return metadata;
}

}  // namespace

DatasetMetadata LoadDatasetMetadata(const std::filesystem::path& file) {
  const std::string label = file.string();
  std::ifstream in(file, std::ios::binary);
  if (!in.is_open()) throw ConfigError(label, 0, "", "cannot open the dataset metadata file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw ConfigError(label, 0, "", "cannot read the dataset metadata file");
  return ParseDatasetMetadata(text.str(), label);
}

void SaveDatasetMetadata(const DatasetMetadata& metadata, const std::filesystem::path& file) {
  const std::string label = file.string();
  if (metadata.format_version != kFormatVersion) {
    throw ConfigError(label, 0, "format_version",
                      "this build writes format version " + std::to_string(kFormatVersion) + ", not " +
                          std::to_string(metadata.format_version));
  }
  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << kKeys[0] << YAML::Value << std::to_string(metadata.format_version);
  out << YAML::Key << "source" << YAML::Value << YAML::DoubleQuoted << metadata.source;
  out << YAML::Key << "payload" << YAML::Value << YAML::DoubleQuoted << metadata.payload;
  out << YAML::Key << "scenario" << YAML::Value << YAML::DoubleQuoted << metadata.scenario;
  out << YAML::Key << "seed" << YAML::Value << std::to_string(metadata.seed);
  for (const auto& [key, field] : DoubleFields()) {
    out << YAML::Key << key << YAML::Value << YamlDouble(metadata.*field);
  }
  out << YAML::Key << "payload_parameters" << YAML::Value;
  EmitParameters(out, metadata.payload_parameters, label);
  if (!metadata.camera_from_lidar.empty()) {
    if (metadata.camera_from_lidar.size() != 12) {
      throw ConfigError(label, 0, "camera_from_lidar", "needs 12 values (3x4 row-major)");
    }
    out << YAML::Key << "camera_from_lidar" << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (const double v : metadata.camera_from_lidar) out << YamlDouble(v);
    out << YAML::EndSeq;
  }
  out << YAML::EndMap;
  if (!out.good()) throw InputError(label + ": cannot format the metadata: " + out.GetLastError());
  PartialFile partial(file);
  partial.Write("# unimap dataset metadata (docs/dataset-format.md)\n");
  partial.Write(out.c_str(), out.size());
  partial.Write("\n");
  partial.Commit();
}

}  // namespace unimap::io
