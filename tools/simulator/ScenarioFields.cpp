#include "ScenarioFields.hpp"

#include <cmath>
#include <string>

#include "unimap/Errors.hpp"

namespace unimap::sim {

int YamlLine(const YAML::Node& node) {
  if (!node.IsDefined()) return 0;
  const YAML::Mark mark = node.Mark();
  return mark.line >= 0 ? mark.line + 1 : 0;
}

ScenarioFields::ScenarioFields(const YAML::Node& node, std::string file, std::string prefix)
    : node_(node), file_(std::move(file)), prefix_(std::move(prefix)) {
  if (!node_.IsMap()) throw ConfigError(file_, YamlLine(node_), prefix_, "must be a map of key: value");
}

std::string ScenarioFields::Name(const std::string& key) const { return prefix_.empty() ? key : prefix_ + "." + key; }

int ScenarioFields::LineOf(const std::string& key) const {
  for (const auto& entry : node_) {
    if (entry.first.Scalar() == key) return YamlLine(entry.first);
  }
  return YamlLine(node_);
}

bool ScenarioFields::Has(const std::string& key) const { return node_[key].IsDefined(); }

void ScenarioFields::AllowOnly(std::initializer_list<const char*> allowed) const {
  for (const auto& entry : node_) {
    const std::string key = entry.first.Scalar();
    bool known = false;
    for (const char* name : allowed) known = known || key == name;
    if (!known) {
      std::string list;
      for (const char* name : allowed) list += std::string(list.empty() ? "" : ", ") + name;
      throw ConfigError(file_, YamlLine(entry.first), Name(key), "unknown key (allowed: " + list + ")");
    }
  }
}

double ScenarioFields::ToNumber(const YAML::Node& value, const std::string& key) const {
  double number = 0.0;
  if (!value.IsScalar() || !YAML::convert<double>::decode(value, number) || !std::isfinite(number)) {
    throw ConfigError(file_, YamlLine(value), Name(key), "must be a finite number");
  }
  return number;
}

double ScenarioFields::Number(const std::string& key, double fallback, double min, double max) const {
  if (!Has(key)) return fallback;
  return RequiredNumber(key, min, max);
}

double ScenarioFields::RequiredNumber(const std::string& key, double min, double max) const {
  const double value = ToNumber(Required(key), key);
  if (value < min || value > max) {
    throw ConfigError(
        file_, LineOf(key), Name(key),
        "must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " + std::to_string(value));
  }
  return value;
}

std::int64_t ScenarioFields::Integer(const std::string& key, std::int64_t fallback, std::int64_t min,
                                     std::int64_t max) const {
  if (!Has(key)) return fallback;
  const YAML::Node value = node_[key];
  long long number = 0;
  if (!value.IsScalar() || !YAML::convert<long long>::decode(value, number)) {
    throw ConfigError(file_, YamlLine(value), Name(key), "must be a whole number");
  }
  if (number < min || number > max) {
    throw ConfigError(file_, YamlLine(value), Name(key),
                      "must be in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
  }
  return number;
}

std::uint64_t ScenarioFields::Unsigned(const std::string& key, std::uint64_t fallback) const {
  if (!Has(key)) return fallback;
  const YAML::Node value = node_[key];
  unsigned long long number = 0;
  if (!value.IsScalar() || value.Scalar().find('-') != std::string::npos ||
      !YAML::convert<unsigned long long>::decode(value, number)) {
    throw ConfigError(file_, YamlLine(value), Name(key), "must be a non-negative whole number");
  }
  return number;
}

std::string ScenarioFields::Text(const std::string& key, const std::string& fallback) const {
  if (!Has(key)) return fallback;
  const YAML::Node value = node_[key];
  if (!value.IsScalar()) throw ConfigError(file_, YamlLine(value), Name(key), "must be a plain value");
  return value.Scalar();
}

Eigen::Vector3d ScenarioFields::Vector3(const std::string& key, const Eigen::Vector3d& fallback) const {
  if (!Has(key)) return fallback;
  return RequiredVector3(key);
}

Eigen::Vector3d ScenarioFields::RequiredVector3(const std::string& key) const {
  const YAML::Node value = Required(key);
  if (!value.IsSequence() || value.size() != 3) {
    throw ConfigError(file_, YamlLine(value), Name(key), "must be a list of 3 numbers [x, y, z]");
  }
  return Eigen::Vector3d(ToNumber(value[0], key), ToNumber(value[1], key), ToNumber(value[2], key));
}

ScenarioFields ScenarioFields::Map(const std::string& key) const {
  return ScenarioFields(Required(key), file_, Name(key));
}

YAML::Node ScenarioFields::Required(const std::string& key) const {
  const YAML::Node value = node_[key];
  if (!value.IsDefined() || value.IsNull()) {
    throw ConfigError(file_, LineOf(key), Name(key), "missing (required)");
  }
  return value;
}

}  // namespace unimap::sim
