#include "unimap/Errors.hpp"

#include <sstream>
#include <utility>

namespace unimap {
namespace {

std::string FormatConfigError(const std::string& file, int line, const std::string& key, const std::string& reason) {
  std::ostringstream out;
  if (!file.empty()) {
    out << file;
    if (line > 0) out << ':' << line;
    out << ": ";
  }
  if (!key.empty()) out << "key '" << key << "': ";
  out << reason;
  return out.str();
}

std::string FormatNotFound(const std::string& name, const std::vector<std::filesystem::path>& searched) {
  std::ostringstream out;
  out << "payload plugin '" << name << "' not found; searched:";
  if (searched.empty()) out << " (no folders)";
  for (const auto& folder : searched) out << "\n  " << folder.string();
  out << "\n(set UNIMAP_PLUGIN_PATH to add folders)";
  return out.str();
}

}  // namespace

Error::Error(const std::string& what) : std::runtime_error(what) {}
Error::~Error() = default;

InputError::InputError(const std::string& what) : Error(what) {}
InputError::~InputError() = default;

ConfigError::ConfigError(std::string file, int line, std::string key, std::string reason)
    : Error(FormatConfigError(file, line, key, reason)),
      file_(std::move(file)),
      line_(line),
      key_(std::move(key)),
      reason_(std::move(reason)) {}
ConfigError::~ConfigError() = default;

PluginError::PluginError(const std::string& what) : Error(what) {}
PluginError::~PluginError() = default;

PluginNotFoundError::PluginNotFoundError(const std::string& name, std::vector<std::filesystem::path> searched)
    : PluginError(FormatNotFound(name, searched)), searched_(std::move(searched)) {}
PluginNotFoundError::~PluginNotFoundError() = default;

PluginLoadError::PluginLoadError(const std::string& what) : PluginError(what) {}
PluginLoadError::~PluginLoadError() = default;

NotAPluginError::NotAPluginError(const std::string& what) : PluginError(what) {}
NotAPluginError::~NotAPluginError() = default;

AbiMismatchError::AbiMismatchError(const std::string& library, std::uint32_t found, std::uint32_t expected)
    : PluginError(library + ": built against payload ABI version " + std::to_string(found) +
                  ", this unimap expects version " + std::to_string(expected) +
                  " (rebuild the plugin against this SDK)"),
      found_(found),
      expected_(expected) {}
AbiMismatchError::~AbiMismatchError() = default;

PluginFactoryError::PluginFactoryError(const std::string& what) : PluginError(what) {}
PluginFactoryError::~PluginFactoryError() = default;

}  // namespace unimap
