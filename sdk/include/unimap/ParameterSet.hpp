#pragma once
#include <limits>
#include <string>
#include <vector>

#include "unimap/Export.hpp"
#include "unimap/ParameterMap.hpp"
#include "unimap/ParameterValue.hpp"

namespace unimap {

// What one parameter is: its key, default, meaning and valid range.
struct ParameterSpec {
  std::string key;                                              // dotted key as written in a platform file
  std::string symbol;                                           // the paper's symbol ("N", "sigma_a"), or empty
  std::string description;                                      // one line, with the unit
  ParameterValue default_value;                                 // its type is the parameter's type
  double min_value = -std::numeric_limits<double>::infinity();  // inclusive, numbers and list elements
  double max_value = std::numeric_limits<double>::infinity();   // inclusive, numbers and list elements
  std::vector<std::string> choices;                             // allowed words for a string (empty: any)
};

// Every parameter a payload understands. Plugins build it in Defaults().
class UNIMAP_SDK_API ParameterSet {
 public:
  // Adds a parameter; a duplicate key is a programming error (std::logic_error).
  void Add(ParameterSpec spec);
  // The spec for a key, or nullptr.
  const ParameterSpec* Find(const std::string& key) const;
  // All specs in the order they were added.
  const std::vector<ParameterSpec>& specs() const { return specs_; }
  // Every key with its default value.
  ParameterMap DefaultMap() const;

  // Converts value to the spec's type (an integer becomes a number) and
  // checks size, range and choices; false with *why on failure.
  bool Coerce(const std::string& key, const ParameterValue& value, ParameterValue* out, std::string* why) const;
  // Every default passes Coerce unchanged and every key is non-empty.
  bool IsValid(std::string* why) const;
  // Throws ConfigError (key, reason) unless map has exactly the known keys,
  // each of the spec's type and in range.
  void Validate(const ParameterMap& map) const;

 private:
  std::vector<ParameterSpec> specs_;
};

}  // namespace unimap
