#include "unimap/Platform.hpp"

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "unimap/Errors.hpp"
#include "unimap/Version.hpp"

namespace unimap {
namespace {

namespace fs = std::filesystem;

const fs::path kTestPluginDir = UNIMAP_BROKEN_PLUGIN_DIR;  // holds libunimap_payload_test_valid.so

// Passes when text contains part; the failure message shows both.
::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

// A loader that sees only the test plugins.
PluginLoader TestLoader() { return PluginLoader({kTestPluginDir}); }

// The ConfigError that loading the YAML text throws (a failure if none).
ConfigError LoadError(const std::string& text) {
  try {
    LoadPlatformFromString(text, "inline.yaml", TestLoader());
  } catch (const ConfigError& e) {
    return e;
  }
  ADD_FAILURE() << "no ConfigError for:\n" << text;
  return ConfigError("", 0, "", "");
}

// Expects the text to fail at line with key and a reason containing words.
void ExpectLoadError(const std::string& text, int line, const std::string& key, const std::string& words) {
  const ConfigError e = LoadError(text);
  EXPECT_EQ(e.file(), "inline.yaml") << e.what();
  EXPECT_EQ(e.line(), line) << e.what();
  EXPECT_EQ(e.key(), key) << e.what();
  EXPECT_TRUE(Contains(e.reason(), words));
}

// The effective entry for a key (a failure if absent).
const EffectiveParameter& EffectiveOf(const Platform& platform, const std::string& key) {
  for (const EffectiveParameter& entry : platform.effective) {
    if (entry.spec.key == key) return entry;
  }
  ADD_FAILURE() << "no effective parameter " << key;
  return platform.effective.front();
}

const std::string kOverrides =
    "# test platform\n"                       // 1
    "plugin: test_valid   # the fake one\n"   // 2
    "parameters:\n"                           // 3
    "  scans_per_3d_scan: 40\n"               // 4
    "  distance_map_resolution_m: 0.2\n"      // 5
    "  sigma_gyro_rad_s: 1\n"                 // 6: integer for a number
    "  extrinsic:\n"                          // 7
    "    body_motor:\n"                       // 8
    "      translation_m: [0.5, -1, 2e-1]\n"  // 9
    "  motor:\n"                              // 10
    "    direction: cw\n"                     // 11
    "    enabled: false\n"                    // 12
    "  label: \"40\"\n";                      // 13: quoted, so a string

TEST(PlatformTest, DefaultsOnlyWhenNothingIsOverridden) {
  const Platform platform = LoadPlatformFromString("plugin: test_valid\n", "inline.yaml", TestLoader());
  EXPECT_EQ(platform.file, "inline.yaml");
  EXPECT_EQ(platform.plugin_name, "test_valid");
  ASSERT_NE(platform.plugin.plugin, nullptr);
  EXPECT_EQ(platform.plugin.abi_version, kPayloadAbiVersion);
  const ParameterSet defaults = platform.plugin.plugin->Defaults();
  EXPECT_EQ(platform.parameters, defaults.DefaultMap());
  ASSERT_EQ(platform.effective.size(), defaults.specs().size());
  for (const EffectiveParameter& entry : platform.effective) {
    EXPECT_EQ(entry.source, ParameterSource::kPluginDefault) << entry.spec.key;
    EXPECT_EQ(entry.line, 0) << entry.spec.key;
  }
  EXPECT_TRUE(Contains(platform.plugin.plugin->Description(), "configured 1 times; N=1;"));
}

TEST(PlatformTest, OverridesAreAppliedWithProvenance) {
  const Platform platform = LoadPlatformFromString(kOverrides, "inline.yaml", TestLoader());
  const ParameterMap& p = platform.parameters;
  EXPECT_EQ(p.GetInt("scans_per_3d_scan"), 40);
  EXPECT_EQ(p.GetDouble("distance_map_resolution_m"), 0.2);
  EXPECT_EQ(p.At("sigma_gyro_rad_s"), ParameterValue(1.0));  // coerced to a number
  EXPECT_EQ(p.GetVector("extrinsic.body_motor.translation_m", 3), (std::vector<double>{0.5, -1.0, 0.2}));
  EXPECT_EQ(p.GetVector("extrinsic.body_motor.rpy_deg", 3), (std::vector<double>{0.0, 0.0, 0.0}));
  EXPECT_EQ(p.GetString("motor.direction"), "cw");
  EXPECT_FALSE(p.GetBool("motor.enabled"));
  EXPECT_EQ(p.GetString("label"), "40");
  EXPECT_EQ(p.GetDouble("distance_map_max_range_m"), 20.0);  // untouched default

  // Spec order, with the line of each override.
  const ParameterSet defaults = platform.plugin.plugin->Defaults();
  ASSERT_EQ(platform.effective.size(), defaults.specs().size());
  for (std::size_t i = 0; i < defaults.specs().size(); ++i) {
    EXPECT_EQ(platform.effective[i].spec.key, defaults.specs()[i].key);
    EXPECT_EQ(platform.effective[i].value, p.At(defaults.specs()[i].key));
  }
  const std::vector<std::pair<std::string, int>> set_lines = {{"scans_per_3d_scan", 4},
                                                              {"distance_map_resolution_m", 5},
                                                              {"sigma_gyro_rad_s", 6},
                                                              {"extrinsic.body_motor.translation_m", 9},
                                                              {"motor.direction", 11},
                                                              {"motor.enabled", 12},
                                                              {"label", 13}};
  for (const auto& [key, line] : set_lines) {
    EXPECT_EQ(EffectiveOf(platform, key).source, ParameterSource::kPlatformFile) << key;
    EXPECT_EQ(EffectiveOf(platform, key).line, line) << key;
  }
  for (const std::string key : {"scans_3d_per_submap", "extrinsic.body_motor.rpy_deg"}) {
    EXPECT_EQ(EffectiveOf(platform, key).source, ParameterSource::kPluginDefault) << key;
    EXPECT_EQ(EffectiveOf(platform, key).line, 0) << key;
  }
  // The plugin was configured with exactly these values.
  EXPECT_TRUE(Contains(platform.plugin.plugin->Description(), "configured 1 times; N=40; direction=cw"));
}

TEST(PlatformTest, PluginByLibraryPath) {
  const std::string path = (kTestPluginDir / "libunimap_payload_test_valid.so").string();
  const Platform platform =
      LoadPlatformFromString("plugin: " + path + "\n", "inline.yaml", PluginLoader(std::vector<fs::path>{}));
  EXPECT_EQ(platform.plugin_name, path);
  EXPECT_EQ(platform.plugin.plugin->Name(), "test_valid");
}

TEST(PlatformTest, FileErrorsNameTheFileAndLine) {
  const fs::path folder = fs::temp_directory_path() / ("unimap_platform_test_" + std::to_string(getpid()));
  fs::create_directories(folder / "plugins");
  // A plugin path relative to the platform file's folder.
  fs::copy_file(kTestPluginDir / "libunimap_payload_test_valid.so",
                folder / "plugins" / "libunimap_payload_test_valid.so");
  const fs::path good = folder / "good.yaml";
  const fs::path bad = folder / "bad.yaml";
  std::ofstream(good) << "plugin: plugins/libunimap_payload_test_valid.so\n"
                         "parameters:\n  scans_3d_per_submap: 7\n";
  std::ofstream(bad) << "plugin: test_valid\nparameters:\n  scans_3d_per_submap: 0\n";
  {
    const Platform platform = LoadPlatform(good, PluginLoader(std::vector<fs::path>{}));
    EXPECT_EQ(platform.file, good.string());
    EXPECT_EQ(platform.parameters.GetInt("scans_3d_per_submap"), 7);
    EXPECT_EQ(EffectiveOf(platform, "scans_3d_per_submap").line, 3);
    EXPECT_TRUE(fs::equivalent(platform.plugin.library_path, folder / "plugins" / "libunimap_payload_test_valid.so"));
  }
  try {
    LoadPlatform(bad, TestLoader());
    ADD_FAILURE() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), bad.string());
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.key(), "scans_3d_per_submap");
    EXPECT_TRUE(Contains(e.what(), bad.string() + ":3: key 'scans_3d_per_submap': "));
    EXPECT_TRUE(Contains(e.reason(), "out of range [1, 100000]"));
  }
  try {
    LoadPlatform(folder / "absent.yaml", TestLoader());
    ADD_FAILURE() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), (folder / "absent.yaml").string());
    EXPECT_TRUE(Contains(e.reason(), "not found"));
  }
  fs::remove_all(folder);
}

TEST(PlatformTest, SyntaxAndStructureErrors) {
  ExpectLoadError("plugin: test_valid\nparameters:\n  label: [1, 2\n  scans_per_3d_scan: 3\n", 4, "",
                  "YAML syntax error");
  ExpectLoadError("plugin: test_valid\nparamters:\n  label: x\n", 2, "paramters", "unknown top-level key");
  ExpectLoadError("parameters:\n  label: x\n", 0, "plugin", "missing 'plugin'");
  ExpectLoadError("", 0, "plugin", "missing 'plugin'");
}

TEST(PlatformTest, MissingOrBrokenPluginIsAConfigErrorOnThePluginLine) {
  const ConfigError missing = LoadError("# platform\nplugin: no_such_payload\n");
  EXPECT_EQ(missing.line(), 2);
  EXPECT_EQ(missing.key(), "plugin");
  EXPECT_TRUE(Contains(missing.reason(), "'no_such_payload' not found"));
  EXPECT_TRUE(Contains(missing.reason(), kTestPluginDir.string()));  // the folders searched

  ExpectLoadError("plugin: garbage\n", 1, "plugin", "invalid ELF header");
  ExpectLoadError("plugin: no_symbols\n", 1, "plugin", "not a unimap payload plugin");
  ExpectLoadError("plugin: abi_mismatch\n", 1, "plugin", "ABI version");
  ExpectLoadError("plugin: factory_throws\n", 1, "plugin", "deliberate failure");
  ExpectLoadError("plugin: factory_null\n", 1, "plugin", "returned no plugin");
}

TEST(PlatformTest, ParameterErrorsNameLineKeyAndReason) {
  const std::string head = "plugin: test_valid\nparameters:\n";  // overrides start on line 3
  ExpectLoadError(head + "  scans_per_3d_scn: 4\n", 3, "scans_per_3d_scn",
                  "unknown parameter (did you mean 'scans_per_3d_scan'?)");
  ExpectLoadError(head + "  label: x\n  extrinsic:\n    body_motr:\n      rpy_deg: [0, 0, 0]\n", 6,
                  "extrinsic.body_motr.rpy_deg", "did you mean 'extrinsic.body_motor.rpy_deg'?");
  ExpectLoadError(head + "  wholly_unrelated_setting: 1\n", 3, "wholly_unrelated_setting", "unknown parameter");
  ExpectLoadError(head + "  extrinsic: 5\n", 3, "extrinsic", "is a group");
  ExpectLoadError(head + "  scans_per_3d_scan: 1.5\n", 3, "scans_per_3d_scan", "expected integer, got number 1.5");
  ExpectLoadError(head + "  motor:\n    enabled: yes\n", 4, "motor.enabled", "expected bool, got string yes");
  ExpectLoadError(head + "  scans_per_3d_scan: 0\n", 3, "scans_per_3d_scan", "out of range [1, 100000]");
  ExpectLoadError(head + "  extrinsic.body_motor.rpy_deg: [0, 0, 400]\n", 3, "extrinsic.body_motor.rpy_deg",
                  "out of range [-360, 360]");
  ExpectLoadError(head + "  extrinsic.body_motor.translation_m: [1, 2]\n", 3, "extrinsic.body_motor.translation_m",
                  "expected a list of 3 numbers, got 2");
  ExpectLoadError(head + "  extrinsic.body_motor.translation_m: [1, x, 2]\n", 3, "extrinsic.body_motor.translation_m",
                  "element 2 is 'x'");
  ExpectLoadError(head + "  motor.direction: up\n", 3, "motor.direction", "not one of: cw, ccw");
  ExpectLoadError(head + "  label:\n", 3, "label", "no value given");
  ExpectLoadError(head + "  label: a\n  label: b\n", 4, "label", "set twice (first on line 3)");
}

TEST(PlatformTest, PluginConfigureErrorGetsFileAndLine) {
  // Each value is in range; the plugin itself rejects the combination.
  const ConfigError e = LoadError(
      "plugin: test_valid\n"
      "parameters:\n"
      "  distance_map_max_range_m: 4\n"
      "  distance_map_resolution_m: 1.5\n");
  EXPECT_EQ(e.file(), "inline.yaml");
  EXPECT_EQ(e.line(), 4);
  EXPECT_EQ(e.key(), "distance_map_resolution_m");
  EXPECT_TRUE(Contains(e.reason(), "at most a quarter of distance_map_max_range_m"));
}

}  // namespace
}  // namespace unimap
