// Boost.DLL speaks std::filesystem here (supported since Boost 1.71); this
// is the only translation unit of libunimap_config that includes Boost.DLL.
#define BOOST_DLL_USE_STD_FS
#include "unimap/PluginLoader.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <exception>
#include <map>
#include <system_error>
#include <utility>

#include <boost/dll/runtime_symbol_info.hpp>
#include <boost/dll/shared_library.hpp>

#include "unimap/Errors.hpp"
#include "unimap/PluginExport.hpp"
#include "unimap/Version.hpp"

namespace unimap {
namespace {

namespace fs = std::filesystem;

constexpr const char* kAbiSymbol = "unimap_payload_abi_version";       // const std::uint32_t
constexpr const char* kFactoryAlias = "unimap_create_payload_plugin";  // BOOST_DLL_ALIAS
constexpr const char* kLibraryPrefix = "libunimap_payload_";
constexpr const char* kLibrarySuffix = ".so";

// True when text starts with prefix.
bool StartsWith(const std::string& text, const std::string& prefix) {
  return text.size() >= prefix.size() && text.compare(0, prefix.size(), prefix) == 0;
}

// True when text ends with suffix.
bool EndsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// True for an existing regular file (or a symlink to one); never throws.
bool IsFile(const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

// The folder holding this library (libunimap_config.so); empty if unknown.
fs::path ThisLibraryFolder() {
  boost::dll::fs::error_code ec;
  const fs::path location = boost::dll::this_line_location(ec);
  return ec ? fs::path() : location.parent_path();
}

// The path made absolute when possible (it names the library in errors and
// LoadedPlugin), else unchanged.
fs::path Absolute(const fs::path& path) {
  std::error_code ec;
  fs::path absolute = fs::absolute(path, ec);
  return ec ? path : absolute.lexically_normal();
}

// The first folder / file_name that is a file, or empty.
fs::path FindIn(const std::vector<fs::path>& folders, const std::string& file_name) {
  for (const fs::path& folder : folders) {
    if (folder.empty()) continue;
    const fs::path candidate = folder / file_name;
    if (IsFile(candidate)) return candidate;
  }
  return {};
}

}  // namespace

std::vector<fs::path> PluginLoader::DefaultSearchFolders() {
  std::vector<fs::path> folders;
  if (const char* env = std::getenv("UNIMAP_PLUGIN_PATH")) {
    const std::string value(env);
    std::size_t begin = 0;
    while (begin <= value.size()) {
      std::size_t end = value.find(':', begin);
      if (end == std::string::npos) end = value.size();
      if (end > begin) folders.emplace_back(value.substr(begin, end - begin));  // empty entries ignored
      begin = end + 1;
    }
  }
  folders.emplace_back(UNIMAP_BUILD_PLUGIN_DIR);
  if (const fs::path here = ThisLibraryFolder(); !here.empty()) {
    folders.push_back(here / UNIMAP_INSTALL_PLUGIN_SUBDIR);
  }
  // A folder listed twice is searched once, at its first position.
  std::vector<fs::path> unique;
  for (const fs::path& folder : folders) {
    bool seen = false;
    for (const fs::path& kept : unique) {
      seen = seen || kept.lexically_normal() == folder.lexically_normal();
    }
    if (!seen) unique.push_back(folder);
  }
  return unique;
}

std::string PluginLoader::LibraryFileName(const std::string& payload_name) {
  return kLibraryPrefix + payload_name + kLibrarySuffix;
}

PluginLoader::PluginLoader() : folders_(DefaultSearchFolders()) {}

PluginLoader::PluginLoader(std::vector<fs::path> folders) : folders_(std::move(folders)) {}

fs::path PluginLoader::Resolve(const std::string& name_or_path) const {
  if (name_or_path.find('/') != std::string::npos) {  // a path: used as written
    const fs::path path(name_or_path);
    if (IsFile(path)) return path;
    throw PluginNotFoundError(name_or_path, {path.parent_path()});
  }
  if (name_or_path.empty()) throw PluginNotFoundError(name_or_path, folders_);
  if (EndsWith(name_or_path, kLibrarySuffix)) {  // a file name: here, else in the folders
    if (IsFile(name_or_path)) return fs::path(name_or_path);
    const fs::path found = FindIn(folders_, name_or_path);
    if (!found.empty()) return found;
    throw PluginNotFoundError(name_or_path, folders_);
  }
  const fs::path found = FindIn(folders_, LibraryFileName(name_or_path));
  if (found.empty()) throw PluginNotFoundError(name_or_path, folders_);
  return found;
}

LoadedPlugin PluginLoader::Load(const std::string& name_or_path) const {
  const fs::path file = Absolute(Resolve(name_or_path));
  const std::string quoted = "'" + file.string() + "'";

  auto library = std::make_shared<boost::dll::shared_library>();
  boost::dll::fs::error_code ec;
  // rtld_now: an unresolved symbol fails here, not later in the middle of a run.
  library->load(file, ec, boost::dll::load_mode::rtld_now | boost::dll::load_mode::rtld_local);
  if (ec || !library->is_loaded()) {
    const char* text = dlerror();  // Boost.DLL leaves dlopen's message in place on failure
    std::string reason = text != nullptr ? std::string(text) : ec.message();
    const std::string own_prefix = file.string() + ": ";  // dlerror repeats the path
    if (StartsWith(reason, own_prefix)) reason.erase(0, own_prefix.size());
    throw PluginLoadError("cannot load plugin library " + quoted + ": " + reason);
  }

  if (!library->has(kAbiSymbol)) {
    throw NotAPluginError(quoted + " is not a unimap payload plugin: it does not export " + kAbiSymbol +
                          " (build it with UNIMAP_EXPORT_PAYLOAD_PLUGIN)");
  }
  const std::uint32_t abi_version = library->get<const std::uint32_t>(kAbiSymbol);
  if (abi_version != kPayloadAbiVersion) {
    throw AbiMismatchError(file.string(), abi_version, kPayloadAbiVersion);
  }
  if (!library->has(kFactoryAlias)) {
    throw NotAPluginError(quoted + " is not a unimap payload plugin: it does not export the factory " + kFactoryAlias +
                          " (build it with UNIMAP_EXPORT_PAYLOAD_PLUGIN)");
  }
  PayloadPluginFactory& factory = library->get_alias<PayloadPluginFactory>(kFactoryAlias);

  std::unique_ptr<PayloadPlugin> created;
  try {
    created = factory();
  } catch (const std::exception& e) {
    throw PluginFactoryError("the factory of plugin " + quoted + " threw: " + e.what());
  } catch (...) {
    throw PluginFactoryError("the factory of plugin " + quoted + " threw something that is not a std::exception");
  }
  if (!created) {
    throw PluginFactoryError("the factory of plugin " + quoted + " returned no plugin (nullptr)");
  }

  LoadedPlugin loaded;
  loaded.library_path = file;
  loaded.abi_version = abi_version;
  // The deleter owns a reference to the library and drops it only after the
  // object is destroyed: the code of the object's destructor (and of every
  // virtual method) stays mapped while any copy of the shared_ptr lives.
  loaded.plugin = std::shared_ptr<PayloadPlugin>(created.release(), [library](PayloadPlugin* object) mutable {
    delete object;
    library.reset();
  });
  return loaded;
}

std::vector<fs::path> PluginLoader::Discover() const {
  std::map<std::string, fs::path> by_name;  // file name -> first path; sorted by name
  for (const fs::path& folder : folders_) {
    std::error_code ec;  // missing or unreadable folders hold no plugins
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
      const fs::directory_entry& entry = *it;
      const std::string name = entry.path().filename().string();
      if (StartsWith(name, kLibraryPrefix) && EndsWith(name, kLibrarySuffix) &&
          name.size() > std::string(kLibraryPrefix).size() + std::string(kLibrarySuffix).size() &&
          IsFile(entry.path())) {
        by_name.emplace(name, entry.path());  // keeps the first folder's file
      }
    }
  }
  std::vector<fs::path> found;
  found.reserve(by_name.size());
  for (const auto& [name, path] : by_name) found.push_back(path);
  return found;
}

}  // namespace unimap
