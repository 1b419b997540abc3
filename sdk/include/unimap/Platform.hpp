#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "unimap/Export.hpp"
#include "unimap/ParameterMap.hpp"
#include "unimap/ParameterSet.hpp"
#include "unimap/PluginLoader.hpp"

namespace unimap {

// Where an effective parameter's value came from.
enum class ParameterSource { kPluginDefault, kPlatformFile };

// One effective parameter with its provenance.
struct EffectiveParameter {
  ParameterSpec spec;
  ParameterValue value;
  ParameterSource source = ParameterSource::kPluginDefault;
  int line = 0;  // line in the platform file when source is kPlatformFile
};

// One setting of a platform file, flattened to its dotted key below its
// section ("extrinsic.body_motor.rpy_deg" under `parameters:`,
// "gpf.num_particles" under `mapper:`).
struct ParameterOverride {
  std::string key;       // dotted key
  ParameterValue value;  // as written: integer, number, bool, string or list of numbers
  int line = 0;          // 1-based line of the key in the file
};

// A platform: the payload plugin a YAML file names, configured with the
// plugin's defaults overridden by the file.
struct Platform {
  std::string file;                                // the platform file (or a label for inline YAML)
  std::string plugin_name;                         // as written under `plugin:`
  LoadedPlugin plugin;                             // configured with `parameters`
  ParameterMap parameters;                         // effective values
  std::vector<EffectiveParameter> effective;       // in the plugin's spec order
  std::vector<ParameterOverride> mapper_settings;  // the file's `mapper:` section in file order,
                                                   // checked and applied by the mapper's options
};

// Reads a platform file, loads its plugin, applies and validates the
// overrides, and configures the plugin. Throws ConfigError naming file,
// line, key and reason (unknown key, wrong type, out of range, missing or
// unloadable plugin, YAML syntax).
UNIMAP_CORE_API Platform LoadPlatform(const std::filesystem::path& file, const PluginLoader& loader = PluginLoader());
// The same from YAML text; file_label names it in errors.
UNIMAP_CORE_API Platform LoadPlatformFromString(const std::string& yaml_text, const std::string& file_label,
                                                const PluginLoader& loader = PluginLoader());

}  // namespace unimap
