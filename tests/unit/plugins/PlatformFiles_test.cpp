// configs/platforms/*.yaml: the rigs differ only where the paper says
// platforms differ (plugin, its seven parameters), in sensor extrinsics and
// in the sensor model (lidar.*); every key is one its plugin knows.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "PluginTestSupport.hpp"
#include "unimap/CoreParameters.hpp"
#include "unimap/Platform.hpp"

namespace unimap {
namespace {

// A platform file, flattened: plugin name and dotted key -> value text
// (scalars as written, lists as "[a, b, c]").
struct FlatPlatform {
  std::string file;
  std::string plugin;
  std::map<std::string, std::string> parameters;
};

void Flatten(const YAML::Node& map, const std::string& prefix, std::map<std::string, std::string>* out) {
  for (auto it = map.begin(); it != map.end(); ++it) {
    const std::string key = prefix + it->first.as<std::string>();
    const YAML::Node value = it->second;
    if (value.IsMap()) {
      Flatten(value, key + ".", out);
    } else if (value.IsSequence()) {
      std::string text = "[";
      for (std::size_t i = 0; i < value.size(); ++i) {
        text += (i == 0 ? "" : ", ") + value[i].as<std::string>();
      }
      (*out)[key] = text + "]";
    } else {
      (*out)[key] = value.as<std::string>();
    }
  }
}

std::filesystem::path PlatformDir() { return std::filesystem::path(UNIMAP_SOURCE_DIR) / "configs" / "platforms"; }

// Every shipped platform file, by name.
const std::vector<std::string>& PlatformFileNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> found;
    for (const auto& entry : std::filesystem::directory_iterator(PlatformDir())) {
      if (entry.path().extension() == ".yaml") found.push_back(entry.path().filename().string());
    }
    std::sort(found.begin(), found.end());
    return found;
  }();
  return names;
}

FlatPlatform ReadFlat(const std::string& name) {
  const YAML::Node root = YAML::LoadFile((PlatformDir() / name).string());
  FlatPlatform flat;
  flat.file = name;
  for (auto it = root.begin(); it != root.end(); ++it) {
    const std::string key = it->first.as<std::string>();
    EXPECT_TRUE(key == "plugin" || key == "parameters") << name << ": top-level key " << key;
  }
  flat.plugin = root["plugin"].as<std::string>();
  Flatten(root["parameters"], "", &flat.parameters);
  return flat;
}

// Keys allowed to differ between platforms.
bool MayDiffer(const std::string& key) {
  const auto& paper = CoreParameters::Keys();
  return std::find(paper.begin(), paper.end(), key) != paper.end() || key.rfind("extrinsic.", 0) == 0 ||
         key.rfind("lidar.", 0) == 0;
}

TEST(PlatformFilesTest, DifferOnlyInPluginPaperParametersAndExtrinsics) {
  std::vector<FlatPlatform> platforms;
  for (const auto& name : PlatformFileNames()) platforms.push_back(ReadFlat(name));
  std::set<std::string> plugins;
  for (const FlatPlatform& p : platforms) {
    plugins.insert(p.plugin);
    for (const std::string& key : CoreParameters::Keys()) {
      EXPECT_EQ(p.parameters.count(key), 1u) << p.file << " must set " << key;
    }
  }
  EXPECT_EQ(plugins, (std::set<std::string>{"fixed_3d", "rotating_3d", "rotating_2d"}));
  // Outside the allowed keys, every file has the same keys with the same values.
  const auto shared = [](const FlatPlatform& p) {
    std::map<std::string, std::string> rest;
    for (const auto& [key, value] : p.parameters) {
      if (!MayDiffer(key)) rest[key] = value;
    }
    return rest;
  };
  for (std::size_t i = 1; i < platforms.size(); ++i) {
    EXPECT_EQ(shared(platforms[i]), shared(platforms[0])) << platforms[i].file << " vs " << platforms[0].file;
  }
}

TEST(PlatformFilesTest, StartWithACommentNamingTheRig) {
  const std::map<std::string, std::string> rig = {
      {"fixed_vlp16.yaml", "VLP-16"},      {"rotating_vlp16.yaml", "VLP-16"}, {"rotating_hokuyo.yaml", "Hokuyo"},
      {"kitti_hdl64.yaml", "HDL-64E"},     {"ouster_os1_64.yaml", "OS1-64"},  {"livox_avia.yaml", "Livox"},
      {"tilting_urg04lx.yaml", "URG-04LX"}};
  for (const auto& name : PlatformFileNames()) {
    std::ifstream in(PlatformDir() / name);
    std::string first_line;
    ASSERT_TRUE(std::getline(in, first_line)) << name;
    EXPECT_EQ(first_line.rfind("# ", 0), 0u) << name;
    EXPECT_NE(first_line.find(rig.at(name)), std::string::npos) << name << ": " << first_line;
  }
}

TEST(PlatformFilesTest, EveryKeyIsKnownToThePluginAndTheFileLoads) {
  const PluginLoader loader({std::filesystem::path(UNIMAP_PLUGIN_BUILD_DIR)});
  for (const auto& name : PlatformFileNames()) {
    const FlatPlatform flat = ReadFlat(name);
    const LoadedPlugin loaded = loader.Load(flat.plugin);
    EXPECT_EQ(loaded.plugin->Name(), flat.plugin) << name;
    const ParameterSet defaults = loaded.plugin->Defaults();
    for (const auto& [key, value] : flat.parameters) {
      EXPECT_NE(defaults.Find(key), nullptr) << name << ": " << key << " unknown to " << flat.plugin;
    }
    // The real platform loader accepts the file (types, ranges, plugin).
    const Platform platform = LoadPlatform(PlatformDir() / name, loader);
    EXPECT_EQ(platform.plugin_name, flat.plugin) << name;
    EXPECT_EQ(platform.plugin.plugin->Name(), flat.plugin) << name;
    std::size_t from_file = 0;
    for (const EffectiveParameter& e : platform.effective) {
      if (e.source == ParameterSource::kPlatformFile) ++from_file;
    }
    EXPECT_EQ(from_file, flat.parameters.size()) << name;
  }
}

}  // namespace
}  // namespace unimap
