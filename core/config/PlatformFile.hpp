#pragma once
// Internal to libunimap_config (exported for its tests only, not installed):
// the one place that reads platform-file YAML.
// Everything downstream sees plain structs, never yaml-cpp.
#include <filesystem>
#include <string>
#include <vector>

#include "unimap/Export.hpp"
#include "unimap/ParameterValue.hpp"
#include "unimap/Platform.hpp"

namespace unimap {

// The contents of a platform file, syntax-checked but not yet validated
// against any plugin:
//   plugin: <payload name or library path>
//   parameters: { <key>: <value or nested map>, ... }
//   mapper: { <section>: { <key>: <value> }, ... }   (optional: tuning)
class UNIMAP_CORE_API PlatformFile {
 public:
  // Parses YAML text; file_label names the text in errors. Throws ConfigError
  // (file_label, line, key, reason) on a YAML syntax error, a top level that
  // is not a map, a top-level key other than plugin/parameters, a missing or
  // non-scalar `plugin`, a duplicate key, a missing value, or a list that is
  // not a flat list of numbers.
  static PlatformFile Parse(const std::string& yaml_text, const std::string& file_label);
  // Reads and parses a file; throws ConfigError when it cannot be read.
  static PlatformFile Read(const std::filesystem::path& file);

  // The file name (or label) used in errors.
  const std::string& file() const { return file_; }
  // The `plugin:` value as written.
  const std::string& plugin() const { return plugin_; }
  // 1-based line of the `plugin:` key.
  int plugin_line() const { return plugin_line_; }
  // Overrides in file order; keys are unique.
  const std::vector<ParameterOverride>& overrides() const { return overrides_; }
  // The `mapper:` section's settings in file order (keys below `mapper.`,
  // unique); checked against the mapper's options, not here.
  const std::vector<ParameterOverride>& mapper_settings() const { return mapper_settings_; }

 private:
  std::string file_;
  std::string plugin_;
  int plugin_line_ = 0;
  std::vector<ParameterOverride> overrides_;
  std::vector<ParameterOverride> mapper_settings_;
};

// Converts one plain YAML scalar to a value: int64 if it is entirely an
// integer, else double if entirely a decimal number, else true/false, else
// the text itself. Exposed for tests.
UNIMAP_CORE_API ParameterValue ParseScalar(const std::string& text);

}  // namespace unimap
