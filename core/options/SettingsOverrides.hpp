#pragma once
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "options/FieldVisitor.hpp"
#include "unimap/Errors.hpp"
#include "unimap/Platform.hpp"

namespace unimap::options {

// Visits every field of one options object (its VisitFields).
using VisitAll = std::function<void(FieldVisitor&)>;

// One field as `unimap config` lists it.
struct FieldRow {
  std::string key;    // dotted key below the section
  std::string value;  // as the file would write it
  std::string unit;   // "" when it has none
};

// A platform file's settings for one section (`mapper:`), applied to the
// fields an options object visits.
class SettingsOverrides {
 public:
  // file names the platform file and section the section ("mapper") in errors.
  SettingsOverrides(std::string file, std::string section, std::vector<ParameterOverride> settings);

  // Throws ConfigError(file, line, section.key, reason) for a setting whose
  // key the object does not have: set elsewhere (saying where), a section
  // given a value (listing its keys) or unknown (naming the closest key).
  void CheckKeys(const VisitAll& visit) const;
  // Writes setting i into the field it names. Throws ConfigError for a value
  // of the wrong type (a number for a bool, a fraction for a count) or one
  // outside the field's type.
  void Apply(std::size_t i, const VisitAll& visit) const;
  // Apply for every setting, in file order.
  void ApplyAll(const VisitAll& visit) const;
  // True when the file sets key.
  bool Sets(const std::string& key) const;
  // The error for setting i.
  ConfigError Error(std::size_t i, const std::string& reason) const;

  const std::vector<ParameterOverride>& settings() const { return settings_; }

 private:
  std::string file_;
  std::string section_;
  std::vector<ParameterOverride> settings_;
};

// Every field the visit reaches, in visit order.
std::vector<FieldRow> ListFields(const VisitAll& visit);

}  // namespace unimap::options
