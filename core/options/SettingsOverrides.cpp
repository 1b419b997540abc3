#include "options/SettingsOverrides.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <type_traits>
#include <utility>

#include "config/ParameterResolver.hpp"

namespace unimap::options {
namespace {

// The type a field holds, as errors say it.
std::string KindOf(const FieldPointer& field) {
  return std::visit(
      [](auto* p) -> std::string {
        using T = std::remove_pointer_t<decltype(p)>;
        if constexpr (std::is_same_v<T, bool>) return "true or false";
        if constexpr (std::is_same_v<T, double>) return "a number";
        if constexpr (std::is_same_v<T, int>) return "a whole number";
        return "a whole number >= 0";
      },
      field);
}

// Where the fields are and what is set elsewhere.
class KeyCollector : public FieldVisitor {
 public:
  std::set<std::string> fields;
  std::map<std::string, std::string> elsewhere;
  std::vector<std::string> order;

 protected:
  void OnField(const std::string& key, FieldPointer /*value*/, const char* /*unit*/) override {
    fields.insert(key);
    order.push_back(key);
  }
  void OnElsewhere(const std::string& key, const char* where) override { elsewhere.emplace(key, where); }
};

// Writes one value into the field with its key; *reason says why it cannot.
class Writer : public FieldVisitor {
 public:
  Writer(const std::string& key, const ParameterValue& value) : key_(key), value_(value) {}
  bool found = false;
  std::string reason;

 protected:
  void OnField(const std::string& key, FieldPointer field, const char* /*unit*/) override {
    if (key != key_) return;
    found = true;
    const auto* whole = std::get_if<std::int64_t>(&value_);
    const auto* real = std::get_if<double>(&value_);
    const auto* flag = std::get_if<bool>(&value_);
    const std::string wrong = "expected " + KindOf(field) + ", got " + TypeName(value_) + " " + ToString(value_);
    if (auto** d = std::get_if<double*>(&field)) {
      if (whole != nullptr) {
        **d = static_cast<double>(*whole);
      } else if (real != nullptr && std::isfinite(*real)) {
        **d = *real;
      } else {
        reason = wrong;
      }
    } else if (auto** i = std::get_if<int*>(&field)) {
      if (whole != nullptr && *whole >= std::numeric_limits<int>::min() && *whole <= std::numeric_limits<int>::max()) {
        **i = static_cast<int>(*whole);
      } else {
        reason = wrong;
      }
    } else if (auto** u = std::get_if<std::uint64_t*>(&field)) {
      if (whole != nullptr && *whole >= 0) {
        **u = static_cast<std::uint64_t>(*whole);
      } else {
        reason = wrong;
      }
    } else if (auto** b = std::get_if<bool*>(&field)) {
      if (flag != nullptr) {
        **b = *flag;
      } else {
        reason = wrong;
      }
    }
  }

 private:
  const std::string& key_;
  const ParameterValue& value_;
};

// Every field with its value.
class Lister : public FieldVisitor {
 public:
  std::vector<FieldRow> rows;

 protected:
  void OnField(const std::string& key, FieldPointer field, const char* unit) override {
    const ParameterValue value = std::visit(
        [](auto* p) -> ParameterValue {
          using T = std::remove_pointer_t<decltype(p)>;
          if constexpr (std::is_same_v<T, bool>) return *p;
          if constexpr (std::is_same_v<T, double>) return *p;
          return static_cast<std::int64_t>(*p);
        },
        field);
    rows.push_back(FieldRow{key, ToString(value), unit});
  }
};

}  // namespace

SettingsOverrides::SettingsOverrides(std::string file, std::string section, std::vector<ParameterOverride> settings)
    : file_(std::move(file)), section_(std::move(section)), settings_(std::move(settings)) {}

ConfigError SettingsOverrides::Error(std::size_t i, const std::string& reason) const {
  return ConfigError(file_, settings_.at(i).line, section_ + "." + settings_.at(i).key, reason);
}

void SettingsOverrides::CheckKeys(const VisitAll& visit) const {
  KeyCollector keys;
  visit(keys);
  for (std::size_t i = 0; i < settings_.size(); ++i) {
    const std::string& key = settings_[i].key;
    if (keys.fields.count(key) != 0) continue;
    if (const auto it = keys.elsewhere.find(key); it != keys.elsewhere.end()) {
      throw Error(i, "set by " + it->second + ", not in the " + section_ + " section");
    }
    std::string below;
    for (const std::string& known : keys.order) {
      if (known.rfind(key + ".", 0) == 0) below += (below.empty() ? "" : ", ") + known.substr(key.size() + 1);
    }
    if (!below.empty()) throw Error(i, "is a group, not a value; its keys: " + below);
    // The closest key by edit distance, or one with the same last word.
    std::string closest;
    std::size_t best = 4;
    const std::string last = key.substr(key.rfind('.') + 1);
    for (const std::string& known : keys.order) {
      const std::size_t distance = EditDistance(key, known);
      if (distance < best) {
        best = distance;
        closest = known;
      }
    }
    if (closest.empty()) {
      for (const std::string& known : keys.order) {
        if (known.size() > last.size() && known.compare(known.size() - last.size(), last.size(), last) == 0 &&
            known[known.size() - last.size() - 1] == '.') {
          closest = known;
          break;
        }
      }
    }
    throw Error(i, "unknown key" +
                       (closest.empty() ? std::string() : " (did you mean " + section_ + "." + closest + "?)") +
                       "; `unimap config --platform FILE` lists every key");
  }
}

void SettingsOverrides::Apply(std::size_t i, const VisitAll& visit) const {
  Writer writer(settings_.at(i).key, settings_.at(i).value);
  visit(writer);
  if (!writer.found) CheckKeys(visit);  // throws the unknown-key error
  if (!writer.reason.empty()) throw Error(i, writer.reason);
}

void SettingsOverrides::ApplyAll(const VisitAll& visit) const {
  for (std::size_t i = 0; i < settings_.size(); ++i) Apply(i, visit);
}

bool SettingsOverrides::Sets(const std::string& key) const {
  for (const ParameterOverride& setting : settings_) {
    if (setting.key == key) return true;
  }
  return false;
}

std::vector<FieldRow> ListFields(const VisitAll& visit) {
  Lister lister;
  visit(lister);
  return std::move(lister.rows);
}

}  // namespace unimap::options
