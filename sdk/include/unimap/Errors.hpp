#pragma once
// Typed exceptions thrown at the plugin, configuration and input boundaries.
// Numeric code inside the core returns result structs instead.
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "unimap/Export.hpp"

namespace unimap {

// Base of every error unimap throws on purpose.
class UNIMAP_SDK_API Error : public std::runtime_error {
 public:
  explicit Error(const std::string& what);
  ~Error() override;
};

// Input data breaks a documented precondition (NaN point, time going
// backwards, time outside encoder coverage, empty scan, ...).
class UNIMAP_SDK_API InputError : public Error {
 public:
  explicit InputError(const std::string& what);
  ~InputError() override;
};

// A configuration problem. what() reads "file:line: key 'k': reason"; the
// parts that are unknown (empty file, line 0, empty key) are left out.
class UNIMAP_SDK_API ConfigError : public Error {
 public:
  ConfigError(std::string file, int line, std::string key, std::string reason);
  ~ConfigError() override;
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& key() const { return key_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string file_;
  int line_;
  std::string key_;
  std::string reason_;
};

// Base of plugin loading failures; names the library (or payload) involved.
class UNIMAP_SDK_API PluginError : public Error {
 public:
  explicit PluginError(const std::string& what);
  ~PluginError() override;
};

// No library for the payload in any searched folder.
class UNIMAP_SDK_API PluginNotFoundError : public PluginError {
 public:
  PluginNotFoundError(const std::string& name, std::vector<std::filesystem::path> searched);
  ~PluginNotFoundError() override;
  const std::vector<std::filesystem::path>& searched() const { return searched_; }

 private:
  std::vector<std::filesystem::path> searched_;
};

// The file exists but the dynamic loader refused it (not a shared library,
// missing dependency, ...).
class UNIMAP_SDK_API PluginLoadError : public PluginError {
 public:
  explicit PluginLoadError(const std::string& what);
  ~PluginLoadError() override;
};

// A loadable library that does not export the unimap plugin symbols.
class UNIMAP_SDK_API NotAPluginError : public PluginError {
 public:
  explicit NotAPluginError(const std::string& what);
  ~NotAPluginError() override;
};

// The plugin was built against another PayloadPlugin ABI.
class UNIMAP_SDK_API AbiMismatchError : public PluginError {
 public:
  AbiMismatchError(const std::string& library, std::uint32_t found, std::uint32_t expected);
  ~AbiMismatchError() override;
  std::uint32_t found() const { return found_; }
  std::uint32_t expected() const { return expected_; }

 private:
  std::uint32_t found_;
  std::uint32_t expected_;
};

// The plugin's factory threw or returned nothing.
class UNIMAP_SDK_API PluginFactoryError : public PluginError {
 public:
  explicit PluginFactoryError(const std::string& what);
  ~PluginFactoryError() override;
};

}  // namespace unimap
