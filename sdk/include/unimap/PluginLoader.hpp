#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "unimap/Export.hpp"
#include "unimap/PayloadPlugin.hpp"

namespace unimap {

// A created plugin. The shared_ptr keeps its library loaded: the library is
// unloaded only after the last copy is destroyed.
struct LoadedPlugin {
  std::shared_ptr<PayloadPlugin> plugin;
  std::filesystem::path library_path;  // the file it came from
  std::uint32_t abi_version = 0;       // as exported by the library
};

// Finds and loads payload plugins (implemented in core/config, Boost.DLL).
class UNIMAP_CORE_API PluginLoader {
 public:
  // UNIMAP_PLUGIN_PATH entries (':'-separated), then the build tree's plugin
  // folder, then the install tree's (relative to the installed library).
  static std::vector<std::filesystem::path> DefaultSearchFolders();
  // libunimap_payload_<name>.so
  static std::string LibraryFileName(const std::string& payload_name);

  PluginLoader();
  explicit PluginLoader(std::vector<std::filesystem::path> folders);

  const std::vector<std::filesystem::path>& folders() const { return folders_; }
  // The library for a payload name, or name_or_path itself when it names an
  // existing file (contains '/' or ends in .so); throws PluginNotFoundError.
  std::filesystem::path Resolve(const std::string& name_or_path) const;
  // Resolves, loads, checks the ABI and creates the plugin; throws
  // PluginNotFoundError, PluginLoadError, NotAPluginError,
  // AbiMismatchError or PluginFactoryError.
  LoadedPlugin Load(const std::string& name_or_path) const;
  // Every libunimap_payload_*.so in the folders; the first of a name wins.
  std::vector<std::filesystem::path> Discover() const;

 private:
  std::vector<std::filesystem::path> folders_;
};

}  // namespace unimap
