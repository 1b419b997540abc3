// RunMain, the plugin list and the instantiation of the payload conformance
// suite over it. The tests themselves live in *Conformance.cpp next to this.
#include "unimap/conformance/PayloadConformance.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "PayloadConformanceTest.hpp"

namespace unimap::conformance {
namespace {

constexpr const char* kPluginFlag = "--plugin=";
constexpr const char* kPluginsEnv = "UNIMAP_CONFORMANCE_PLUGINS";
constexpr const char* kLibraryPrefix = "libunimap_payload_";

// The list PluginPaths() returns; set by RunMain before InitGoogleTest.
std::vector<std::string>& MutablePluginPaths() {
  static std::vector<std::string> paths;
  return paths;
}

// An existing file becomes an absolute path (the loader then takes it as a
// path whatever the working directory); anything else is left for the
// loader to resolve as a payload name.
std::string Normalize(const std::string& entry) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(entry, ec)) {
    return std::filesystem::absolute(entry, ec).lexically_normal().string();
  }
  return entry;
}

// The ':'-separated non-empty entries of text.
std::vector<std::string> SplitPathList(const std::string& text) {
  std::vector<std::string> entries;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t end = std::min(text.find(':', begin), text.size());
    if (end > begin) entries.push_back(text.substr(begin, end - begin));
    begin = end + 1;
  }
  return entries;
}

// Readable gtest name of a plugin: the library file stem without
// "libunimap_payload_", sanitised to [A-Za-z0-9_]; a name that an earlier
// plugin already produced gets "_<index>" appended.
std::string BaseName(const std::string& path) {
  std::string stem = std::filesystem::path(path).stem().string();
  if (stem.rfind(kLibraryPrefix, 0) == 0 && stem.size() > std::string(kLibraryPrefix).size()) {
    stem = stem.substr(std::string(kLibraryPrefix).size());
  }
  for (char& c : stem) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return stem.empty() ? std::string("plugin") : stem;
}

std::string PluginTestName(const ::testing::TestParamInfo<std::string>& info) {
  const std::string base = BaseName(info.param);
  const std::vector<std::string>& paths = PluginPaths();
  for (std::size_t j = 0; j < info.index && j < paths.size(); ++j) {
    if (BaseName(paths[j]) == base) return base + "_" + std::to_string(info.index);
  }
  return base;
}

}  // namespace

const std::vector<std::string>& PluginPaths() { return MutablePluginPaths(); }

int RunMain(int argc, char** argv, std::vector<std::string> default_plugins) {
  std::vector<std::string> chosen;
  std::vector<char*> gtest_args;
  for (int i = 0; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i > 0 && arg.rfind(kPluginFlag, 0) == 0) {
      const std::string path = arg.substr(std::string(kPluginFlag).size());
      if (!path.empty()) chosen.push_back(path);
    } else {
      gtest_args.push_back(argv[i]);
    }
  }
  if (const char* env = std::getenv(kPluginsEnv)) {
    for (const std::string& entry : SplitPathList(env)) chosen.push_back(entry);
  }
  std::vector<std::string>& paths = MutablePluginPaths();
  paths.clear();
  for (const std::string& entry : chosen.empty() ? default_plugins : chosen) {
    paths.push_back(Normalize(entry));
  }
  if (paths.empty()) {
    std::cerr << "unimap conformance: no plugin library given (use --plugin=PATH or " << kPluginsEnv << ")\n";
    return 2;
  }
  // InitGoogleTest registers the parameterised tests now, evaluating the
  // generator below (ValuesIn(PluginPaths())) against the list just built.
  int gtest_argc = static_cast<int>(gtest_args.size());
  gtest_args.push_back(nullptr);
  ::testing::InitGoogleTest(&gtest_argc, gtest_args.data());
  return RUN_ALL_TESTS();
}

// gtest evaluates this generator when InitGoogleTest registers the
// parameterised tests (UnitTestImpl::RegisterParameterizedTests), not at
// static initialisation, so it sees the list RunMain built.
INSTANTIATE_TEST_SUITE_P(Payload, PayloadConformanceTest, ::testing::ValuesIn(PluginPaths()), PluginTestName);

}  // namespace unimap::conformance
