#include "unimap/ParameterSet.hpp"

#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

#include "unimap/Errors.hpp"

namespace unimap {
namespace {

std::string RangeText(const ParameterSpec& spec) {
  std::ostringstream out;
  out << "[" << spec.min_value << ", " << spec.max_value << "]";
  return out.str();
}

bool CheckNumber(const ParameterSpec& spec, double value, std::string* why) {
  if (!std::isfinite(value)) {
    *why = "value " + ToString(value) + " is not finite";
    return false;
  }
  if (value < spec.min_value || value > spec.max_value) {
    *why = "value " + ToString(value) + " is out of range " + RangeText(spec);
    return false;
  }
  return true;
}

}  // namespace

void ParameterSet::Add(ParameterSpec spec) {
  if (spec.key.empty()) throw std::logic_error("ParameterSet::Add: empty key");
  if (Find(spec.key) != nullptr) throw std::logic_error("ParameterSet::Add: duplicate key " + spec.key);
  specs_.push_back(std::move(spec));
}

const ParameterSpec* ParameterSet::Find(const std::string& key) const {
  for (const auto& spec : specs_) {
    if (spec.key == key) return &spec;
  }
  return nullptr;
}

ParameterMap ParameterSet::DefaultMap() const {
  ParameterMap map;
  for (const auto& spec : specs_) map.Set(spec.key, spec.default_value);
  return map;
}

bool ParameterSet::Coerce(const std::string& key, const ParameterValue& value, ParameterValue* out,
                          std::string* why) const {
  std::string local_why;
  if (why == nullptr) why = &local_why;
  const ParameterSpec* spec = Find(key);
  if (spec == nullptr) {
    *why = "unknown parameter";
    return false;
  }
  const ParameterValue& expected = spec->default_value;
  const auto type_error = [&]() {
    *why = "expected " + TypeName(expected) + ", got " + TypeName(value) + " " + ToString(value);
    return false;
  };
  if (std::holds_alternative<bool>(expected)) {
    if (!std::holds_alternative<bool>(value)) return type_error();
    *out = value;
    return true;
  }
  if (std::holds_alternative<std::int64_t>(expected)) {
    const auto* i = std::get_if<std::int64_t>(&value);
    if (i == nullptr) return type_error();
    if (!CheckNumber(*spec, static_cast<double>(*i), why)) return false;
    *out = value;
    return true;
  }
  if (std::holds_alternative<double>(expected)) {
    double number = 0.0;
    if (const auto* d = std::get_if<double>(&value)) {
      number = *d;
    } else if (const auto* i = std::get_if<std::int64_t>(&value)) {
      number = static_cast<double>(*i);
    } else {
      return type_error();
    }
    if (!CheckNumber(*spec, number, why)) return false;
    *out = number;
    return true;
  }
  if (std::holds_alternative<std::string>(expected)) {
    const auto* s = std::get_if<std::string>(&value);
    if (s == nullptr) return type_error();
    if (!spec->choices.empty()) {
      bool allowed = false;
      std::string list;
      for (const auto& choice : spec->choices) {
        allowed = allowed || choice == *s;
        list += (list.empty() ? "" : ", ") + choice;
      }
      if (!allowed) {
        *why = "'" + *s + "' is not one of: " + list;
        return false;
      }
    }
    *out = value;
    return true;
  }
  const auto& expected_list = std::get<std::vector<double>>(expected);
  const auto* list = std::get_if<std::vector<double>>(&value);
  if (list == nullptr) return type_error();
  if (list->size() != expected_list.size()) {
    *why =
        "expected a list of " + std::to_string(expected_list.size()) + " numbers, got " + std::to_string(list->size());
    return false;
  }
  for (const double element : *list) {
    if (!CheckNumber(*spec, element, why)) return false;
  }
  *out = value;
  return true;
}

bool ParameterSet::IsValid(std::string* why) const {
  std::string local_why;
  if (why == nullptr) why = &local_why;
  for (const auto& spec : specs_) {
    if (spec.description.empty()) {
      *why = "parameter '" + spec.key + "' has no description";
      return false;
    }
    if (spec.min_value > spec.max_value) {
      *why = "parameter '" + spec.key + "' has min > max";
      return false;
    }
    ParameterValue coerced;
    std::string reason;
    if (!Coerce(spec.key, spec.default_value, &coerced, &reason) || coerced != spec.default_value) {
      *why = "default of '" + spec.key + "': " + (reason.empty() ? "changes type" : reason);
      return false;
    }
  }
  return true;
}

void ParameterSet::Validate(const ParameterMap& map) const {
  for (const auto& [key, value] : map.values()) {
    ParameterValue coerced;
    std::string why;
    if (!Coerce(key, value, &coerced, &why)) throw ConfigError("", 0, key, why);
  }
  for (const auto& spec : specs_) {
    if (!map.Contains(spec.key)) throw ConfigError("", 0, spec.key, "missing parameter");
  }
}

}  // namespace unimap
