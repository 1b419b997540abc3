#include "unimap/Platform.hpp"

#include <exception>
#include <system_error>
#include <utility>

#include "ParameterResolver.hpp"
#include "PlatformFile.hpp"
#include "unimap/Errors.hpp"

namespace unimap {
namespace {

// What to hand the loader for `plugin:`. A relative library path is taken
// relative to the platform file's folder when it exists there, so a file can
// name a plugin next to it; names and other paths go to the loader unchanged.
std::string PluginReference(const PlatformFile& file, const std::filesystem::path& base_folder) {
  const std::string& written = file.plugin();
  const std::filesystem::path as_path(written);
  if (written.find('/') == std::string::npos || as_path.is_absolute() || base_folder.empty()) {
    return written;
  }
  const std::filesystem::path beside = base_folder / as_path;
  std::error_code ec;
  return std::filesystem::is_regular_file(beside, ec) ? beside.string() : written;
}

// The line where the file sets key, or 0.
int LineOfOverride(const PlatformFile& file, const std::string& key) {
  for (const ParameterOverride& entry : file.overrides()) {
    if (entry.key == key) return entry.line;
  }
  return 0;
}

// Loads the plugin a parsed platform file names, resolves its parameters and
// configures it.
Platform BuildPlatform(const PlatformFile& file, const std::filesystem::path& base_folder, const PluginLoader& loader) {
  Platform platform;
  platform.file = file.file();
  platform.plugin_name = file.plugin();
  const int plugin_line = file.plugin_line();
  try {
    platform.plugin = loader.Load(PluginReference(file, base_folder));
  } catch (const PluginError& e) {
    throw ConfigError(file.file(), plugin_line, "plugin", e.what());
  }

  PayloadPlugin& plugin = *platform.plugin.plugin;
  ParameterSet set;
  try {
    set = plugin.Defaults();
  } catch (const std::exception& e) {
    throw ConfigError(file.file(), plugin_line, "plugin",
                      "plugin '" + file.plugin() + "' failed to list its parameters: " + e.what());
  }
  if (std::string why; !set.IsValid(&why)) {
    throw ConfigError(file.file(), plugin_line, "plugin",
                      "plugin '" + file.plugin() + "' declares invalid defaults: " + why);
  }

  ResolvedParameters resolved = ParameterResolver(set).Resolve(file);
  try {
    plugin.Configure(resolved.parameters);
  } catch (const ConfigError& e) {
    // The plugin knows the key, the file knows where it was set.
    const int line = e.line() != 0 ? e.line() : LineOfOverride(file, e.key());
    throw ConfigError(e.file().empty() ? file.file() : e.file(), line, e.key(), e.reason());
  } catch (const std::exception& e) {
    throw ConfigError(file.file(), plugin_line, "plugin",
                      "plugin '" + file.plugin() + "' rejected its parameters: " + e.what());
  }
  platform.parameters = std::move(resolved.parameters);
  platform.effective = std::move(resolved.effective);
  platform.mapper_settings = file.mapper_settings();
  return platform;
}

}  // namespace

Platform LoadPlatform(const std::filesystem::path& file, const PluginLoader& loader) {
  return BuildPlatform(PlatformFile::Read(file), file.parent_path(), loader);
}

Platform LoadPlatformFromString(const std::string& yaml_text, const std::string& file_label,
                                const PluginLoader& loader) {
  return BuildPlatform(PlatformFile::Parse(yaml_text, file_label), {}, loader);
}

}  // namespace unimap
