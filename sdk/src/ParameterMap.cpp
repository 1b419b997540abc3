#include "unimap/ParameterMap.hpp"

#include "unimap/Errors.hpp"

namespace unimap {
namespace {

[[noreturn]] void ThrowType(const std::string& key, const std::string& expected, const ParameterValue& value) {
  throw ConfigError("", 0, key, "expected " + expected + ", got " + TypeName(value) + " " + ToString(value));
}

}  // namespace

void ParameterMap::Set(const std::string& key, ParameterValue value) { values_[key] = std::move(value); }

bool ParameterMap::Contains(const std::string& key) const { return values_.count(key) > 0; }

const ParameterValue& ParameterMap::At(const std::string& key) const {
  const auto it = values_.find(key);
  if (it == values_.end()) throw ConfigError("", 0, key, "missing parameter");
  return it->second;
}

bool ParameterMap::GetBool(const std::string& key) const {
  const ParameterValue& value = At(key);
  if (const auto* b = std::get_if<bool>(&value)) return *b;
  ThrowType(key, "bool", value);
}

std::int64_t ParameterMap::GetInt(const std::string& key) const {
  const ParameterValue& value = At(key);
  if (const auto* i = std::get_if<std::int64_t>(&value)) return *i;
  ThrowType(key, "integer", value);
}

double ParameterMap::GetDouble(const std::string& key) const {
  const ParameterValue& value = At(key);
  if (const auto* d = std::get_if<double>(&value)) return *d;
  if (const auto* i = std::get_if<std::int64_t>(&value)) return static_cast<double>(*i);
  ThrowType(key, "number", value);
}

const std::string& ParameterMap::GetString(const std::string& key) const {
  const ParameterValue& value = At(key);
  if (const auto* s = std::get_if<std::string>(&value)) return *s;
  ThrowType(key, "string", value);
}

std::vector<double> ParameterMap::GetVector(const std::string& key, std::size_t expected_size) const {
  const ParameterValue& value = At(key);
  const auto* list = std::get_if<std::vector<double>>(&value);
  if (list == nullptr) ThrowType(key, "list of " + std::to_string(expected_size) + " numbers", value);
  if (list->size() != expected_size) {
    throw ConfigError("", 0, key,
                      "expected " + std::to_string(expected_size) + " numbers, got " + std::to_string(list->size()));
  }
  return *list;
}

Eigen::Vector3d ParameterMap::GetVector3(const std::string& key) const {
  const std::vector<double> v = GetVector(key, 3);
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

}  // namespace unimap
