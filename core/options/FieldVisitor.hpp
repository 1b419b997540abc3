#pragma once
// The fields of an options struct, visited by name: one VisitFields per
// struct, beside it, is the only place that names its keys for the
// platform file's `mapper:` section (SettingsOverrides applies and lists
// them). Algorithm code never sees YAML.
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace unimap::options {

// A field's storage.
using FieldPointer = std::variant<double*, int*, bool*, std::uint64_t*>;

// Receives each field of a struct under its dotted key ("gpf.num_particles").
class FieldVisitor {
 public:
  virtual ~FieldVisitor() = default;

  // One field: its name within the current section and its unit ("m",
  // "rad", "count", "" when it has none).
  template <class T>
  void Field(const char* name, T* value, const char* unit) {
    OnField(Key(name), FieldPointer(value), unit);
  }
  // The fields fields() visits, under name.
  template <class Fn>
  void Section(const char* name, Fn&& fields) {
    sections_.emplace_back(name);
    fields();
    sections_.pop_back();
  }
  // A field of the struct that is set elsewhere (where: a platform parameter
  // or a command-line option), so that setting it here is an error saying so.
  void SetElsewhere(const char* name, const char* where) { OnElsewhere(Key(name), where); }

 protected:
  virtual void OnField(const std::string& key, FieldPointer value, const char* unit) = 0;
  virtual void OnElsewhere(const std::string& /*key*/, const char* /*where*/) {}

 private:
  std::string Key(const char* name) const {
    std::string key;
    for (const std::string& section : sections_) key += section + ".";
    return key + name;
  }
  std::vector<std::string> sections_;
};

}  // namespace unimap::options
