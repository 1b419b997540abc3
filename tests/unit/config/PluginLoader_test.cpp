#include "unimap/PluginLoader.hpp"

#include <link.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <typeinfo>
#include <vector>

#include <gtest/gtest.h>

#include "unimap/Errors.hpp"
#include "unimap/Version.hpp"

namespace unimap {
namespace {

namespace fs = std::filesystem;

const fs::path kTestPluginDir = UNIMAP_BROKEN_PLUGIN_DIR;  // test_valid and the broken ones
const std::string kValidFile = "libunimap_payload_test_valid.so";

// Passes when text contains part; the failure message shows both.
::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

// The file a test plugin was built to.
fs::path TestPlugin(const std::string& name) { return kTestPluginDir / PluginLoader::LibraryFileName(name); }

// Sets (or unsets, for nullopt) UNIMAP_PLUGIN_PATH for one scope.
class ScopedPluginPath {
 public:
  explicit ScopedPluginPath(const std::optional<std::string>& value) {
    if (const char* old = std::getenv("UNIMAP_PLUGIN_PATH")) old_ = old;
    if (value) {
      setenv("UNIMAP_PLUGIN_PATH", value->c_str(), 1);
    } else {
      unsetenv("UNIMAP_PLUGIN_PATH");
    }
  }
  ~ScopedPluginPath() {
    if (old_) {
      setenv("UNIMAP_PLUGIN_PATH", old_->c_str(), 1);
    } else {
      unsetenv("UNIMAP_PLUGIN_PATH");
    }
  }

 private:
  std::optional<std::string> old_;
};

// A fresh folder under the system temp folder, removed with the object.
class TempFolder {
 public:
  explicit TempFolder(const std::string& tag)
      : path_(fs::temp_directory_path() / ("unimap_loader_test_" + tag + "_" + std::to_string(getpid()))) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// True when a library with this file name is mapped into the process.
bool IsMapped(const std::string& file_name) {
  struct Query {
    std::string file_name;
    bool found = false;
  } query{file_name};
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void* data) {
        auto* q = static_cast<Query*>(data);
        if (info->dlpi_name != nullptr && fs::path(info->dlpi_name).filename() == q->file_name) {
          q->found = true;
        }
        return 0;
      },
      &query);
  return query.found;
}

// Loads name and returns the message of the error, checking that the error's
// dynamic type is exactly E (not merely derived from it).
template <typename E>
std::string LoadErrorOf(const PluginLoader& loader, const std::string& name) {
  try {
    loader.Load(name);
  } catch (const PluginError& e) {
    EXPECT_EQ(typeid(e), typeid(E)) << "Load(" << name << ") threw " << e.what();
    return e.what();
  }
  ADD_FAILURE() << "Load(" << name << ") did not throw";
  return "";
}

TEST(PluginLoaderTest, LibraryFileNameFollowsTheConvention) {
  EXPECT_EQ(PluginLoader::LibraryFileName("rotating_2d"), "libunimap_payload_rotating_2d.so");
}

TEST(PluginLoaderTest, LoadsTheValidTestPluginByName) {
  const PluginLoader loader({kTestPluginDir});
  const LoadedPlugin loaded = loader.Load("test_valid");
  ASSERT_NE(loaded.plugin, nullptr);
  EXPECT_EQ(loaded.plugin->Name(), "test_valid");
  EXPECT_EQ(loaded.abi_version, kPayloadAbiVersion);
  EXPECT_TRUE(loaded.library_path.is_absolute());
  EXPECT_TRUE(fs::equivalent(loaded.library_path, TestPlugin("test_valid")));
  EXPECT_EQ(loaded.plugin->Defaults().Find("motor.direction")->default_value, ParameterValue(std::string("ccw")));
}

TEST(PluginLoaderTest, LoadsByPathWithoutSearching) {
  const PluginLoader loader(std::vector<fs::path>{});
  EXPECT_EQ(loader.Resolve(TestPlugin("test_valid").string()), TestPlugin("test_valid"));
  EXPECT_EQ(loader.Load(TestPlugin("test_valid").string()).plugin->Name(), "test_valid");
}

TEST(PluginLoaderTest, MissingPayloadListsEveryFolderSearched) {
  const fs::path nowhere = kTestPluginDir / "no_such_folder";
  const PluginLoader loader({nowhere, kTestPluginDir});
  try {
    loader.Load("no_such_payload");
    FAIL() << "no error";
  } catch (const PluginNotFoundError& e) {
    EXPECT_EQ(e.searched(), (std::vector<fs::path>{nowhere, kTestPluginDir}));
    EXPECT_TRUE(Contains(e.what(), "no_such_payload"));
    EXPECT_TRUE(Contains(e.what(), nowhere.string()));
    EXPECT_TRUE(Contains(e.what(), kTestPluginDir.string()));
  }
}

TEST(PluginLoaderTest, MissingPathIsNotFound) {
  const PluginLoader loader({kTestPluginDir});
  const std::string path = (kTestPluginDir / "libunimap_payload_absent.so").string();
  EXPECT_TRUE(Contains(LoadErrorOf<PluginNotFoundError>(loader, path), path));
  EXPECT_TRUE(Contains(LoadErrorOf<PluginNotFoundError>(loader, ""), "not found"));
}

TEST(PluginLoaderTest, LibraryWithoutUnimapSymbolsIsNotAPlugin) {
  const std::string message = LoadErrorOf<NotAPluginError>(PluginLoader({kTestPluginDir}), "no_symbols");
  EXPECT_TRUE(Contains(message, TestPlugin("no_symbols").string()));
  EXPECT_TRUE(Contains(message, "unimap_payload_abi_version"));
}

TEST(PluginLoaderTest, LibraryWithoutFactoryIsNotAPlugin) {
  const std::string message = LoadErrorOf<NotAPluginError>(PluginLoader({kTestPluginDir}), "no_factory");
  EXPECT_TRUE(Contains(message, TestPlugin("no_factory").string()));
  EXPECT_TRUE(Contains(message, "unimap_create_payload_plugin"));
}

TEST(PluginLoaderTest, OtherAbiVersionIsRefusedBeforeTheFactoryRuns) {
  // The factory of abi_mismatch aborts the process if it is ever called.
  try {
    PluginLoader({kTestPluginDir}).Load("abi_mismatch");
    FAIL() << "no error";
  } catch (const AbiMismatchError& e) {
    EXPECT_EQ(e.found(), kPayloadAbiVersion + 1);
    EXPECT_EQ(e.expected(), kPayloadAbiVersion);
    EXPECT_TRUE(Contains(e.what(), TestPlugin("abi_mismatch").string()));
  }
}

TEST(PluginLoaderTest, ThrowingFactoryIsAFactoryError) {
  const std::string message = LoadErrorOf<PluginFactoryError>(PluginLoader({kTestPluginDir}), "factory_throws");
  EXPECT_TRUE(Contains(message, TestPlugin("factory_throws").string()));
  EXPECT_TRUE(Contains(message, "deliberate failure in ThrowingPlugin()"));
}

TEST(PluginLoaderTest, NullFactoryIsAFactoryError) {
  const std::string message = LoadErrorOf<PluginFactoryError>(PluginLoader({kTestPluginDir}), "factory_null");
  EXPECT_TRUE(Contains(message, TestPlugin("factory_null").string()));
  EXPECT_TRUE(Contains(message, "nullptr"));
}

TEST(PluginLoaderTest, FileThatIsNotASharedLibraryIsALoadError) {
  const std::string message = LoadErrorOf<PluginLoadError>(PluginLoader({kTestPluginDir}), "garbage");
  EXPECT_TRUE(Contains(message, TestPlugin("garbage").string()));
  EXPECT_TRUE(Contains(message, "invalid ELF header"));  // dlerror's words
}

TEST(PluginLoaderTest, UnresolvedSymbolIsALoadErrorAtLoadTime) {
  const std::string message = LoadErrorOf<PluginLoadError>(PluginLoader({kTestPluginDir}), "unresolved");
  EXPECT_TRUE(Contains(message, TestPlugin("unresolved").string()));
  EXPECT_TRUE(Contains(message, "undefined symbol"));
  EXPECT_TRUE(Contains(message, "unimap_test_function_defined_nowhere"));
}

TEST(PluginLoaderTest, DefaultFoldersAreEnvironmentThenBuildThenInstall) {
  const fs::path build = UNIMAP_PLUGIN_BUILD_DIR;
  // libunimap_config.so lives in <build>/lib; the install folder is relative to it.
  const fs::path install = fs::path(UNIMAP_BINARY_DIR) / "lib" / "unimap" / "plugins";
  {
    const ScopedPluginPath env(std::string(":/first::/second:"));
    EXPECT_EQ(PluginLoader::DefaultSearchFolders(), (std::vector<fs::path>{"/first", "/second", build, install}));
    EXPECT_EQ(PluginLoader().folders(), PluginLoader::DefaultSearchFolders());
  }
  {
    const ScopedPluginPath env(std::string(""));
    EXPECT_EQ(PluginLoader::DefaultSearchFolders(), (std::vector<fs::path>{build, install}));
  }
  {
    const ScopedPluginPath env(std::nullopt);
    EXPECT_EQ(PluginLoader::DefaultSearchFolders(), (std::vector<fs::path>{build, install}));
  }
}

TEST(PluginLoaderTest, FirstFolderWithTheFileWins) {
  // An impostor: the garbage file under the valid plugin's name.
  const TempFolder impostor("first_wins");
  fs::copy_file(TestPlugin("garbage"), impostor.path() / kValidFile);

  const PluginLoader impostor_first({impostor.path(), kTestPluginDir});
  EXPECT_EQ(impostor_first.Resolve("test_valid"), impostor.path() / kValidFile);
  EXPECT_TRUE(Contains(LoadErrorOf<PluginLoadError>(impostor_first, "test_valid"), impostor.path().string()));

  const PluginLoader valid_first({kTestPluginDir, impostor.path()});
  EXPECT_EQ(valid_first.Resolve("test_valid"), TestPlugin("test_valid"));
  EXPECT_EQ(valid_first.Load("test_valid").plugin->Name(), "test_valid");

  // UNIMAP_PLUGIN_PATH comes before the build and install folders.
  const ScopedPluginPath env(impostor.path().string() + ":" + kTestPluginDir.string());
  EXPECT_EQ(PluginLoader().Resolve("test_valid"), impostor.path() / kValidFile);
  EXPECT_EQ(PluginLoader().Resolve("no_symbols"), TestPlugin("no_symbols"));
}

TEST(PluginLoaderTest, DiscoverListsPluginFilesSortedByNameFirstWins) {
  const TempFolder extra("discover");
  fs::copy_file(TestPlugin("garbage"), extra.path() / kValidFile);
  fs::copy_file(TestPlugin("garbage"), extra.path() / "libunimap_payload_aaa_extra.so");
  fs::copy_file(TestPlugin("garbage"), extra.path() / "libother.so");            // not a payload name
  fs::copy_file(TestPlugin("garbage"), extra.path() / "libunimap_payload_.so");  // no payload name
  fs::create_directory(extra.path() / "libunimap_payload_folder.so");            // not a file

  const PluginLoader loader({kTestPluginDir / "no_such_folder", extra.path(), kTestPluginDir});
  const std::vector<fs::path> expected = {extra.path() / "libunimap_payload_aaa_extra.so",
                                          TestPlugin("abi_mismatch"),
                                          TestPlugin("factory_null"),
                                          TestPlugin("factory_throws"),
                                          TestPlugin("garbage"),
                                          TestPlugin("no_factory"),
                                          TestPlugin("no_symbols"),
                                          extra.path() / kValidFile,
                                          TestPlugin("unresolved")};
  EXPECT_EQ(loader.Discover(), expected);
  EXPECT_TRUE(PluginLoader(std::vector<fs::path>{}).Discover().empty());
}

TEST(PluginLoaderTest, LibraryStaysLoadedWhileAnyPluginObjectLives) {
  ASSERT_FALSE(IsMapped(kValidFile)) << "another test leaked the test plugin";
  std::shared_ptr<PayloadPlugin> survivor;
  {
    const PluginLoader loader({kTestPluginDir});
    const LoadedPlugin first = loader.Load("test_valid");
    const LoadedPlugin copy = first;  // NOLINT(performance-unnecessary-copy-initialization)
    EXPECT_TRUE(IsMapped(kValidFile));
    survivor = copy.plugin;
  }  // loader, first and copy gone: only survivor holds the library
  ASSERT_TRUE(IsMapped(kValidFile));
  // Virtual calls run the library's code.
  EXPECT_EQ(survivor->Name(), "test_valid");
  survivor->Configure(survivor->Defaults().DefaultMap());
  EXPECT_TRUE(Contains(survivor->Description(), "configured 1 times"));

  survivor.reset();  // the last copy: object destroyed, then the library released
  EXPECT_FALSE(IsMapped(kValidFile));
}

TEST(PluginLoaderTest, TwoLoadsShareTheLibraryUntilBothAreGone) {
  ASSERT_FALSE(IsMapped(kValidFile)) << "another test leaked the test plugin";
  const PluginLoader loader({kTestPluginDir});
  LoadedPlugin a = loader.Load("test_valid");
  LoadedPlugin b = loader.Load("test_valid");
  EXPECT_NE(a.plugin.get(), b.plugin.get());  // two objects from one library
  a.plugin.reset();
  ASSERT_TRUE(IsMapped(kValidFile));
  EXPECT_EQ(b.plugin->Name(), "test_valid");
  b.plugin.reset();
  EXPECT_FALSE(IsMapped(kValidFile));
}

}  // namespace
}  // namespace unimap
